"""Numbers as C strtod reads them: hex fractions, zeros with exponents, the smallest doubles."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import yaml

from genparams.paramsfile.ros_yaml import ScalarValue, ros_scalar
from tests.support import RosHarness

SPELLINGS: list[tuple[str, ScalarValue]] = [
    ("0x1.8p1", 3.0),
    ("-0x1.8p1", -3.0),
    ("-0X1.8P1", -3.0),
    ("-0x1.8", -1.5),  # no exponent: p0
    ("+0x1.8", 1.5),
    ("1.0", 1.0),
    ("0x1p0", 1.0),
    ("0x0P5", 0.0),
    ("-0x0.0P+5", -0.0),
    ("0e5", 0.0),
    ("0E5", 0.0),
    ("-0.0e9", -0.0),
    ("0.000E12", 0.0),
    ("2.2250738585072014e-308", 2.2250738585072014e-308),  # the smallest normal double
    ("-2.2250738585072014e-308", -2.2250738585072014e-308),
    ("2.2250738585072009e-308", "2.2250738585072009e-308"),  # subnormal: ERANGE, kept as text
    ("1e-320", "1e-320"),
    ("0x1.8p-1074", "0x1.8p-1074"),  # rounds: ERANGE
    ("0x1p-1074", 5e-324),  # the smallest subnormal, exact: no ERANGE
    ("-0x0.0000000000001p-1022", -5e-324),
    ("0x1p-1030", 2.0**-1030),
    ("0x3p-1074", 3 * 5e-324),
    ("0xcp-1076", 3 * 5e-324),
    ("0x10p-1078", 5e-324),
    ("0x0." + "0" * 267 + "1", 2.0**-1072),  # exact and subnormal, written without p
    ("0x1.0000000000001p-1030", "0x1.0000000000001p-1030"),
    ("0x1p-1080", "0x1p-1080"),  # rounds to zero: ERANGE
    ("0x0.0ep-2000", "0x0.0ep-2000"),
    ("0x0.0Ap-2000", "0x0.0Ap-2000"),
    ("0x0.0p-2000", 0.0),
    ("1e-99999", "1e-99999"),
    ("0x1p-1022", 2.2250738585072014e-308),
    ("0x1p1024", "0x1p1024"),  # overflow
    # integers as strtol reads them with base 0: hex in either case, octal after a 0
    ("0X1A", 26),
    ("0x1a", 26),
    ("017", 15),
    ("-017", -15),
    ("08", 8.0),  # not octal: strtol stops at 8, strtod reads the whole
]


def _same(a: object, b: object) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return (math.isnan(a) and math.isnan(b)) or (
            a == b and math.copysign(1, a) == math.copysign(1, b)
        )
    return type(a) is type(b) and a == b


@pytest.mark.parametrize(("text", "value"), SPELLINGS)
def test_number_spellings_read_as_strtod_reads_them(text: str, value: ScalarValue) -> None:
    node = yaml.compose(f"p: {text}\n")
    assert node is not None
    scalar = node.value[0][1]
    assert _same(ros_scalar(scalar.value, scalar.style), value)


def test_rcl_reads_the_same_values(ros: RosHarness, tmp_path: Path) -> None:
    lines = [f"    p{index}: {text}" for index, (text, _value) in enumerate(SPELLINGS)]
    path = tmp_path / "numbers.yaml"
    path.write_text("/**:\n  ros__parameters:\n" + "\n".join(lines) + "\n", encoding="utf-8")
    node = ros.node("numbers", args=["--params-file", str(path)])
    seen = {key: p.value for key, p in node._parameter_overrides.items()}
    for index, (text, value) in enumerate(SPELLINGS):
        assert _same(seen[f"p{index}"], value), (text, seen[f"p{index}"])
