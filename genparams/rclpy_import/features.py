"""What rclpy nodes do that the schema format cannot state yet.

``awaiting_feature`` is the one place that decides it: it names the construct
and the schema feature it needs; the import warns and leaves it out. When a
feature lands, its branch becomes a translation in convert.py and the warning
goes.
"""

from __future__ import annotations

from genparams.rclpy_import.scan import NodeOption


def awaiting_feature(found: NodeOption) -> str:
    """The schema feature this node option needs, worded for a warning."""
    return (
        f"{found.construct}: parameters named by the params file: "
        "needs open groups keyed by the overrides"
    )
