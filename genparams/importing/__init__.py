"""What the importers share: the record of one import, the schema's name, the schema writer.

``import-gpl``, ``import-rclpy`` and ``import-node`` each read their own source into one
frozen ``Imported`` record; ``schema_name`` names the schema the same way for all three,
and ``attribute_clash`` keeps two names of one Python attribute out of it;
``schema_text`` writes it as YAML under comment lines, and ``write_outputs`` puts it (with
any file beside it) on disk all at once or not at all.
"""

from __future__ import annotations

from genparams.importing.naming import attribute_clash, schema_name
from genparams.importing.record import (
    APPROXIMATE,
    EXACT,
    LEFT_OUT,
    Fate,
    Imported,
    Outcome,
    in_order,
)
from genparams.importing.writer import schema_text, unwritten_label, validated, write_outputs

__all__ = [
    "APPROXIMATE",
    "EXACT",
    "LEFT_OUT",
    "Fate",
    "Imported",
    "Outcome",
    "attribute_clash",
    "in_order",
    "schema_name",
    "schema_text",
    "unwritten_label",
    "validated",
    "write_outputs",
]
