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
BAD_ANSWER = "bad-answer"  # its parameter services answered what cannot be used: exit 1
DUPLICATE_NAME = "duplicate-name"  # more than one node has the name: exit 1
KINDS = (
    VIOLATION,
    DRIFT_DEFAULT,
    DRIFT_FILE,
    NO_SCHEMA,
    UNREACHABLE,
    BAD_SCHEMA,
    BAD_ANSWER,
    DUPLICATE_NAME,
    NOT_CHECKED,
    RULE_ACROSS_NODES,
)
FAILING = frozenset(
    {VIOLATION, UNREACHABLE, BAD_SCHEMA, BAD_ANSWER, DUPLICATE_NAME, RULE_ACROSS_NODES}
)


def plain(value: Any) -> Any:
    """A value as one spelling shows it: every sequence a list (a schema default is a tuple,
    a value read from a node a list), bytes as a list of ints."""
    if isinstance(value, bytes):
        return list(value)
    if isinstance(value, list | tuple):
        return [plain(item) for item in value]
    return value


@dataclass(frozen=True)
class Finding:
    node: str
    kind: str
    parameter: str = ""
    detail: str = ""
    expected: Any = None
    actual: Any = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "expected", plain(self.expected))
        object.__setattr__(self, "actual", plain(self.actual))

    @property
    def failing(self) -> bool:
        return self.kind in FAILING

    def set_by_file(self, names: set[str]) -> bool:
        """A drift from the default of a value a deployment file sets: the file is the
        reference for it, so this is no finding (a drift from the file is one)."""
        return self.kind == DRIFT_DEFAULT and self.parameter in names

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
