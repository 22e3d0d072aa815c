"""Where each key of a params file lies in a schema: dotted paths and the regexes that match them.

Below a mapped group, ``*`` holds the place of an entry's key; the JSON
Schema of a params file matches such keys with patterns.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Iterator

from genparams.runtime.core.naming import ENTRY_KEY, ENTRY_KEY_TEXT
from genparams.schema.model import Group, OpenNamespace, Parameter

ENTRY_KEY_PATTERN = f"^{ENTRY_KEY_TEXT.pattern}$"  # the key of a mapped entry, as naming words it
# Characters with a meaning in a regex: escaped alike for Python's re and ECMAScript's
# unicode mode (editors), which refuses re.escape's `\-`.
_REGEX_SYNTAX = re.compile(r"([\\^$.*+?()\[\]{}|/])")


def regex_literal(text: str) -> str:
    """A regex matching exactly ``text``, read alike by Python and by ECMAScript."""
    return _REGEX_SYNTAX.sub(r"\\\1", text)


def descendants(group: Group) -> Iterator[tuple[tuple[str, ...], Group | Parameter]]:
    """Every parameter and group below ``group``, with its path relative to ``group``.

    Below a mapped group, ``*`` holds the place of an entry's key. The entries of a
    per-item parameter are the parameter itself.
    """
    for parameter in group.parameters:
        yield (parameter.path[-1],), parameter
    for child in group.groups:
        if child.per_item:
            if not child.in_place:
                yield (child.path[-1],), child  # the map of its entries
            yield child.parameters[0].path[len(group.path) :], child.parameters[0]
            continue
        if child.in_place:  # its entries sit right here, by key
            entry: tuple[str, ...] = (ENTRY_KEY,)
            yield entry, child
        else:
            yield (child.path[-1],), child
            entry = (child.path[-1], ENTRY_KEY) if child.mapped_over else (child.path[-1],)
            if child.mapped_over:
                yield entry, child
        for path, item in descendants(child):
            yield (*entry, *path), item


def open_descendants(group: Group) -> Iterator[tuple[tuple[str, ...], OpenNamespace]]:
    """Every open namespace below ``group``, with its path relative to ``group``."""
    depth = len(group.path) + (1 if group.mapped_over else 0)
    for namespace in group.walk_open_namespaces():
        yield namespace.path[depth:], namespace


def dotted_pattern(path: tuple[str, ...], beside: Collection[str] = ()) -> str:
    """A regex for the dotted key of ``path``, with any entry key where ``*`` stands.

    ``beside``: the fixed names of the namespace where the first ``*`` (in-place
    entries) stands; no entry key may be one of them, so no key matches both.
    """
    token = ENTRY_KEY_PATTERN[1:-1]
    parts = [token if p == ENTRY_KEY else regex_literal(p) for p in path]
    if beside and ENTRY_KEY in path:
        names = "|".join(regex_literal(name) for name in sorted(beside))
        first = path.index(ENTRY_KEY)
        parts[first] = f"(?!(?:{names})(?:\\.|$)){token}"
    return "^" + "\\.".join(parts) + "$"


def names_beside_entries(group: Group, path: tuple[str, ...]) -> set[str]:
    """The fixed names of the namespace where the first ``*`` of ``path`` stands (relative to
    ``group``): in-place entries sit beside them. Empty when that namespace is a map."""
    at = path.index(ENTRY_KEY)
    namespace = group
    for name in path[:at]:
        found = next((g for g in namespace.groups if not g.in_place and g.path[-1] == name), None)
        if found is None or found.mapped_over:
            return set()
        namespace = found
    return fixed_names(namespace)


def fixed_names(group: Group) -> set[str]:
    """The names written directly in ``group`` (not its in-place entries' keys)."""
    names = {p.path[-1] for p in group.parameters}
    names.update(g.path[-1] for g in group.groups if not g.in_place)
    names.update(n.path[-1] for n in group.open_namespaces)
    return names
