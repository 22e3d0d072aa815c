"""What an audit found: one record per problem or drift, with the message built from fields."""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Any

from genparams.errors import render_problem

VIOLATION = "violation"  # a value the schema forbids: exit 1
DRIFT_DEFAULT = "drift-from-default"
DRIFT_FILE = "drift-from-file"
NO_SCHEMA = "no-schema"
UNREACHABLE = "unreachable"  # published a schema but its services did not answer: exit 1
BAD_SCHEMA = "bad-schema"  # a schema message that cannot be read, or not the node's own: exit 1
NOT_CHECKED = "not-checked"  # a custom validator that cannot be imported here
RULE_ACROSS_NODES = "rule-across-nodes"  # a deployment rule the nodes' values break: exit 1


@dataclass(frozen=True)
class Finding:
    node: str
    kind: str
    parameter: str = ""
    detail: str = ""
    expected: Any = None
    actual: Any = None

    @property
    def failing(self) -> bool:
        return self.kind in (VIOLATION, UNREACHABLE, BAD_SCHEMA, RULE_ACROSS_NODES)

    # A finding is a problem (genparams.errors.Problem): the node, the parameter, its kind.
    @property
    def place(self) -> str:
        return self.node

    @property
    def key(self) -> str:
        return self.parameter

    @property
    def rule(self) -> str:
        return self.kind

    @property
    def message(self) -> str:
        if self.kind in (DRIFT_DEFAULT, DRIFT_FILE):
            return f"{self.detail} (expected {self.expected!r}, found {self.actual!r})"
        return self.detail

    def text(self) -> str:
        return render_problem(self)

    def as_json(self) -> dict[str, Any]:
        return asdict(self)
