"""Where the mapped groups of a node's schema stand on the node, for the page.

The page lists a group's entries from these: the keys of its key list, or of an
open group the names the node declared under it, and a group inside an entry of
another once per outer key. The rule is the audit's
(:func:`genparams.runtime.core.entries.map_places`); the page does not repeat it.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from genparams.runtime.core.entries import map_places


def entry_places(
    schema: Mapping[str, Any] | None, parameters: Sequence[Mapping[str, Any]]
) -> list[dict[str, Any]]:
    """Each place of each mapped group: the group (``map``, its path in the schema
    message), where it stands (``path``), its entries' ``keys``, the ``fields`` each
    entry holds, and whether it is ``open`` (keyed by the overrides: no key to add)."""
    if schema is None:
        return []
    values = {str(p["name"]): p.get("value") for p in parameters}
    return [
        {
            "map": place.group["path"],
            "path": place.path,
            "keys": list(place.keys),
            "fields": [field["name"] for field in place.fields],
            "open": place.is_open,
        }
        for described in schema.get("classes", [])
        for place in map_places(described["maps"], values)
    ]
