"""What a node's params-file-driven constructs mean for its schema, worded for a message.

A node option or a read of the overrides the import has not turned into an open group
(see overrides.py) gets one of these: ``allow_undeclared_parameters`` stays in the node
and changes nothing the schema states (a note); the others name what translates and
leave the rest to the author (a warning).
"""

from __future__ import annotations

from genparams.rclpy_import.found import NodeOption
from genparams.rclpy_import.overrides import BY_PREFIX

ALLOW_UNDECLARED = "allow_undeclared_parameters"
AUTOMATIC = "automatically_declare_parameters_from_overrides"
_LOOP = "a loop over the keys found under a prefix"


def kept_by_the_node(found: NodeOption, every_read: bool = False) -> bool:
    """Whether the schema is exact without the construct: the node keeps
    ``allow_undeclared_parameters``; ``automatically_declare_parameters_from_overrides``
    goes when the schema holds ``every_read`` parameter the node reads."""
    return found.option == ALLOW_UNDECLARED or (found.option == AUTOMATIC and every_read)


def what_it_needs(found: NodeOption, every_read: bool = False) -> str:
    """Why the construct is not in the schema, and what of it would be."""
    if found.option == ALLOW_UNDECLARED:
        return (
            f"{found.construct}: the node keeps it (sets of parameters no one declared "
            "still succeed); the schema holds the parameters it declares"
        )
    if found.option == AUTOMATIC and every_read:
        return (
            f"{found.construct}: the schema declares every parameter the node reads, each "
            "required, and the patch takes the option out: names of the params file the "
            "node never reads are no longer declared"
        )
    if found.option == AUTOMATIC:
        return (
            f"{found.construct}: declares whatever the params file names, which a schema "
            f"cannot state: only reads of <prefix>.<key>.<field> in {_LOOP} translate "
            "(an open group); with --params-file, the file's parameters are taken"
        )
    how = (
        "{k.split('.')[0] for k in ...}"
        if BY_PREFIX in found.construct
        else ("{n.split('.')[1] for n in ... if n.startswith('sensors.')}")
    )
    return (
        f"{found.construct}: reads what the params file brings: only {_LOOP} ({how}) "
        "that declares or reads <prefix>.<key>.<field> translates (an open group)"
    )
