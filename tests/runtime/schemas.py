"""Schemas the runtime tests share, generated into a tmp folder and imported."""

from __future__ import annotations

import types
from pathlib import Path

from tests.support import load_generated

MOTION = """\
genparams: 1
name: motion
parameters:
  min_speed: {type: double, default: 0.5, range: {min: 0.0, max: 10.0}}
  max_speed: {type: double, default: 2.0, range: {min: 0.0, max: 10.0}, aliases: [top_speed]}
  gain: {type: double, default: .nan}
  weights: {type: double_array, default: [1.0, .nan]}
  lambda_: {type: double, default: 0.1}
  frame:
    from_: {type: string, default: odom}
  joints: {type: string_array, default: [a], configure_only: true}
  port: {type: string, default: /dev/ttyUSB0, configure_only: true}
rules:
  - {name: speed_order, check: min_speed <= max_speed}
"""

SAFETY = """\
genparams: 1
name: safety
parameters:
  mode: {type: string, default: normal, choices: [normal, slow, stop]}
  limit: {type: double, default: 5.0}
"""


def generate(tmp_path: Path, text: str, stem: str) -> types.ModuleType:
    schema = tmp_path / f"{stem}.yaml"
    schema.write_text(text)
    return load_generated(schema, tmp_path)
