"""Self-describing nodes: every class declared on a node publishes its schema on a latched topic.

One message per node on ``~/genparams/schema`` (std_msgs/String holding JSON),
transient-local so a late subscriber (a tuning page, ``genparams audit``,
``ros2 bag record``) gets it without asking. A node that declares a second
class, or the same class under another prefix, republishes the merged message.

The description is built from the runtime's compiled specs, never from the
compiler: what is published is exactly what the node enforces. Validators and
rules appear twice, in words (for people) and as their schema spelling (so a
client can rebuild the same checks). The text is written by the JSON codec
(:mod:`~genparams.runtime.core.json_codec`): a NaN or infinite default or bound
travels as ``{"$float": "nan"}``, never as a token a strict reader refuses.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import sys
import threading
import weakref
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from genparams._version import __version__
from genparams.runtime.core.conditions import condition_json
from genparams.runtime.core.naming import ENTRY_KEY, join_prefix
from genparams.runtime.core.records import Record, store
from genparams.runtime.core.spec import CompiledParam, CompiledSchema

if TYPE_CHECKING:
    from rclpy.node import Node
    from rclpy.publisher import Publisher
    from rclpy.qos import QoSProfile

SCHEMA_TOPIC = "~/genparams/schema"
"""Relative to the node: ``/ns/camera`` publishes on ``/ns/camera/genparams/schema``."""

SCHEMA_TOPIC_SUFFIX = "/genparams/schema"


def schema_qos() -> QoSProfile:
    """The schema topic's QoS, for its publisher and every reader: the last message, kept
    for late subscribers (transient local)."""
    from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy

    return QoSProfile(
        depth=1,
        history=HistoryPolicy.KEEP_LAST,
        reliability=ReliabilityPolicy.RELIABLE,
        durability=DurabilityPolicy.TRANSIENT_LOCAL,
    )


def json_value(value: Any) -> Any:
    """A typed-view value as JSON: tuples become lists, bytes a list of ints."""
    if isinstance(value, bytes):
        return list(value)
    if isinstance(value, tuple | list):
        return [json_value(item) for item in value]
    return value


def describe_parameter(param: CompiledParam, name: str) -> dict[str, Any]:
    spec = param.spec
    ros_range = param.ros_range
    described: dict[str, Any] = {
        "name": name,
        "type": spec.type,
        "required": spec.required,
        "default": None if spec.required else json_value(spec.default),
        "description": spec.description,
        "unit": spec.unit,
        "read_only": spec.read_only,
        "range": None,
        "choices": None if spec.choices is None else json_value(spec.choices),
        "validators": [[rule, json_value(argument)] for rule, argument in spec.validators],
        "constraints": [check.describe() for check in param.checks],
        "additional_constraints": spec.additional_constraints,
        "deprecated": spec.deprecated,
        "aliases": list(spec.aliases),
    }
    if spec.range is not None:
        low, high, *step = spec.range
        described["range"] = {"min": low, "max": high, "step": step[0] if step else 0}
    if ros_range is not None:
        described["ros_range"] = True
    if spec.optional:  # only when true: messages of other schemas stay as they were
        described["optional"] = True
    if spec.when:
        described["when"] = condition_json(spec.when)
    return described


def describe_class(compiled: CompiledSchema, prefix: str) -> dict[str, Any]:
    """One declared class under one prefix, with full ROS names; mapped fields as templates."""

    def full(name: str) -> str:
        return join_prefix(prefix, name)

    maps = []
    for path, key_name in compiled.maps.items():
        # An entry's field names, relative to the entry: "" when the entry is one parameter
        # named by its item (a per-item parameter).
        entry = join_prefix(path, ENTRY_KEY)
        fields = [
            describe_parameter(param, name[len(entry) + 1 :])
            for name, param in compiled.templates.items()
            if name == entry or name.startswith(f"{entry}.")
        ]
        maps.append({"path": full(path), "for_each": full(key_name), "fields": fields})
    body: dict[str, Any] = {
        "class": compiled.spec.name,
        "prefix": prefix,
        "parameters": [
            describe_parameter(param, full(name)) for name, param in compiled.parameters.items()
        ],
        "maps": maps,
        "rules": [
            {
                "name": rule.name,
                "check": rule.check,
                "description": rule.description,
                "parameters": [full(name) for name in rule.parameters],
            }
            for rule in compiled.rules
        ],
    }
    body["hash"] = schema_hash(body)
    return body


def schema_hash(body: Mapping[str, Any]) -> str:
    """A stable digest of a description: equal schemas under equal prefixes hash equal."""
    from genparams.runtime.core.json_codec import dumps  # with the first message

    return text_hash(dumps(body, sort_keys=True, separators=(",", ":")))


def text_hash(text: str) -> str:
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


class ClassText(Record):
    """A class's description as JSON text, and its hash."""

    _fields = ("text", "hash")
    __slots__ = _fields
    text: str
    hash: str

    def __init__(self, text: str, hash: str) -> None:
        store(self, "text", text)
        store(self, "hash", hash)


# Every node that declares a class under a prefix publishes the same description:
# it is built once (about 25 us a parameter) and reused. Keyed by identity, as
# compile_schema is; the entry keeps its CompiledSchema alive so the id stays its own.
_CLASS_TEXTS: dict[tuple[int, str], tuple[CompiledSchema, ClassText]] = {}


def class_text(compiled: CompiledSchema, prefix: str) -> ClassText:
    key = (id(compiled), prefix)
    cached = _CLASS_TEXTS.get(key)
    if cached is None or cached[0] is not compiled:
        from genparams.runtime.core.json_codec import dumps

        body = describe_class(compiled, prefix)
        cached = (compiled, ClassText(dumps(body, sort_keys=True), body["hash"]))
        _CLASS_TEXTS[key] = cached
    return cached[1]


def node_message_text(node_name: str, classes: list[ClassText]) -> str:
    """The node's message: the JSON of node_message, assembled from cached class texts."""
    from genparams.runtime.core.json_codec import dumps
    from genparams.runtime.core.schema_message import FORMAT_VERSION

    node_hash = schema_hash({"classes": [c.hash for c in classes]})
    head = {"format": FORMAT_VERSION, "genparams": __version__, "hash": node_hash}
    # Keys in sorted order, as json.dumps(sort_keys=True) would write them.
    return (
        '{"classes": ['
        + ", ".join(c.text for c in classes)
        + "], "
        + dumps(head, sort_keys=True)[1:-1]
        + f', "node": {dumps(node_name)}}}'
    )


def string_message_type() -> Any:
    """std_msgs/msg/String, loading nothing else of std_msgs when it can.

    ``std_msgs.msg`` imports all of its thirty message modules (5-10 ms of a
    process); the schema topic needs one. rosidl_generator_py writes each message
    to ``<package>/msg/_<name>.py``, so that file is loaded alone, under the name
    ``std_msgs.msg`` itself imports it by: a later ``import std_msgs.msg`` finds
    it there and hands out the very same class. Anything unexpected (the package
    imported already, another layout) takes the ordinary import.
    """
    name = "std_msgs.msg._string"
    loaded = sys.modules.get("std_msgs.msg")
    if loaded is None and name not in sys.modules:
        try:
            package = importlib.util.find_spec("std_msgs")
            folders = package.submodule_search_locations if package is not None else None
            path = os.path.join(next(iter(folders or ())), "msg", "_string.py")
            spec = importlib.util.spec_from_file_location(name, path)
            if spec is not None and spec.loader is not None and os.path.isfile(path):
                module = importlib.util.module_from_spec(spec)
                sys.modules[name] = module
                try:
                    spec.loader.exec_module(module)
                except BaseException:
                    del sys.modules[name]
                    raise
        except (ImportError, OSError, StopIteration):
            pass
    found = sys.modules.get(name)
    if found is not None and hasattr(found, "String"):
        return found.String
    from std_msgs.msg import String

    return String


class SchemaPublisher:
    """The one latched publisher of a node, holding every class declared there.

    The publisher exists from the first declare, so the topic is discoverable at
    once; the message is built and published when a subscriber first matches it
    (a tuning page, ``genparams audit``, ``ros2 topic echo``, a bag recorder), and
    again at every later declare. A node nobody asks never builds its description
    nor keeps a copy of it in the DDS writer's history. The matched event is
    delivered by the node's executor, as its parameter services are; on a
    middleware without matched events the message is published at once.
    """

    def __init__(self, node: Node) -> None:
        from rclpy.event_handler import PublisherEventCallbacks, UnsupportedEventTypeError

        String = string_message_type()  # noqa: N806 (a class)

        # The node's name, not the node: the registry below is keyed weakly by the node,
        # and a value holding its key would keep every node ever declared alive.
        self.node_name = node.get_fully_qualified_name()
        self.classes: dict[tuple[str, str], tuple[CompiledSchema, str]] = {}
        self.message_type = String
        self.lock = threading.Lock()
        self.requested = False  # a subscriber matched once: publish every change at once
        qos = schema_qos()
        try:
            self.publisher: Publisher = node.create_publisher(
                String,
                SCHEMA_TOPIC,
                qos,
                event_callbacks=PublisherEventCallbacks(matched=self.matched),
            )
        except UnsupportedEventTypeError:
            self.requested = True
            self.publisher = node.create_publisher(String, SCHEMA_TOPIC, qos)

    @classmethod
    def of(cls, node: Node) -> SchemaPublisher:
        with _GUARD:
            found = _PUBLISHERS.get(node)
            if found is None:
                found = _PUBLISHERS[node] = cls(node)
            return found

    def add(self, compiled: CompiledSchema, prefix: str) -> None:
        with self.lock:
            self.classes[(prefix, compiled.spec.name)] = (compiled, prefix)
            if self.requested or self.publisher.get_subscription_count() > 0:
                self.requested = True
                self.publish()

    def matched(self, status: Any) -> None:
        """The publisher's matched event: the first subscriber asks for the message."""
        with self.lock:
            if not self.requested and status.current_count > 0:
                self.requested = True
                self.publish()

    def message_text(self) -> str:
        ordered = [class_text(*self.classes[key]) for key in sorted(self.classes)]
        return node_message_text(self.node_name, ordered)

    def publish(self) -> None:
        message = self.message_type()
        message.data = self.message_text()
        self.publisher.publish(message)


_PUBLISHERS: weakref.WeakKeyDictionary[Node, SchemaPublisher] = weakref.WeakKeyDictionary()
_GUARD = threading.Lock()


def publish_schema(node: Node, compiled: CompiledSchema, prefix: str) -> None:
    """Add a declared class to its node's schema message; republish it once asked for."""
    SchemaPublisher.of(node).add(compiled, prefix)
