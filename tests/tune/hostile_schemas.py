"""Nodes that publish schema messages a tool must not trust, in a process of their own.

``python -m tests.tune.hostile_schemas FILE`` reads a JSON list of
``{"node": NAME, "topic": TOPIC, "text": TEXT}``, starts one node per entry that
publishes TEXT, latched, on TOPIC (its own schema topic or another node's), and
prints "ready".
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import rclpy
from rclpy.node import Node
from std_msgs.msg import String

from genparams.live.schema_topics import SCHEMA_QOS
from tests.node_process import serve


def main(argv: list[str]) -> int:
    entries = json.loads(Path(argv[0]).read_text(encoding="utf-8"))
    rclpy.init()
    nodes = []
    for entry in entries:
        node = Node(entry["node"])
        publisher = node.create_publisher(String, entry["topic"], SCHEMA_QOS)
        publisher.publish(String(data=entry["text"]))
        nodes.append(node)
    return serve(nodes)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
