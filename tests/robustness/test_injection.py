"""Schema text never becomes code: hostile strings come back exactly, or fail as schema errors.

Every payload sits in every text field at once; the module is generated,
imported and declared on a real node, and must hand back each string exactly
through cfg, the node, the parameter service and the descriptor.
"""

from __future__ import annotations

import builtins
import keyword
import subprocess
import sys
import tokenize
from pathlib import Path

import pytest

import genparams
from genparams.runtime.core.tree import get_path
from genparams.schema.errors import SchemaError
from tests.readback import mismatches, params_class, read_back
from tests.support import RosHarness, import_file
from tests.yaml_text import quoted


def payloads(marker: Path) -> list[str]:
    touch = f'import os; os.system("touch {marker}")'
    return [
        f'"); {touch} #',
        f"'); {touch} #",
        f'"""); {touch} #',
        f"'''); {touch} #",
        f'\\"); {touch} #',
        f"\\\n{touch}",
        f"\n{touch}\n",
        "{{ self.__init__.__globals__ }}",
        "{% for x in range(3) %}{{ x }}{% endfor %}",
        "{# comment #}{%- raw -%}",
        "# just a comment",
        "\u2028" + touch + "\u2029",
        "\x85\r\n\t\x0b\x0c",
        "\\x00 \\u2028 \\N{BULLET}",
        "back\\slash\\",
        "ü€😀 \u202e RTL \ufeff",
        "x" * 10_000,
        "",
    ]


FIELDS = ("description", "unit", "additional_constraints", "deprecated")


def hostile_schema(texts: list[str]) -> str:
    lines = ["genparams: 1", "name: hostile", f"description: {quoted(texts[0])}", "parameters:"]
    for index, text in enumerate(texts):
        lines.append(f"  p{index}:")
        lines.append("    type: string")
        lines.append(f"    default: {quoted(text)}")
        lines.append(f"    choices: [{quoted(text)}, {quoted(text + 'x')}]")
        for field in FIELDS:
            lines.append(f"    {field}: {quoted(text or 'x')}")
        lines.append(
            f"  a{index}: {{type: string_array, default: [{quoted(text)}, {quoted('#')}]}}"
        )
    return "\n".join(lines) + "\n"


def test_hostile_text_round_trips_exactly(ros: RosHarness, tmp_path: Path) -> None:
    marker = tmp_path / "PWNED"
    texts = payloads(marker)
    text = genparams.generate("hostile.yaml", hostile_schema(texts))
    module_path = tmp_path / "hostile_params.py"
    module_path.write_text(text, encoding="utf-8")
    cls = params_class(import_file(module_path))
    node = ros.node()
    cfg = cls.declare(node)
    expected: dict[str, object] = {}
    for index, payload in enumerate(texts):
        expected[f"p{index}"] = payload
        expected[f"a{index}"] = (payload, "#")
    assert mismatches(read_back(ros, node, cfg), expected) == {}
    descriptors = ros.client(node).describe(*(f"p{i}" for i in range(len(texts))))
    for payload, descriptor in zip(texts, descriptors, strict=True):
        unit = payload or "x"
        assert descriptor.description == f"{unit} [{unit}]"
        assert descriptor.additional_constraints.endswith(unit)
    assert cls.__doc__ == (texts[0].strip() or "Parameters of hostile.")
    assert not marker.exists()


@pytest.mark.parametrize("field", ["default", "description", "choices", "unit"])
def test_nul_is_a_schema_error_wherever_it_is(field: str) -> None:
    leaf = {
        "default": '{type: string, default: "a\\0b"}',
        "description": '{type: string, default: a, description: "a\\0b"}',
        "choices": '{type: string, default: a, choices: [a, "a\\0b"]}',
        "unit": '{type: string, default: a, unit: "\\0"}',
    }[field]
    with pytest.raises(SchemaError, match=r"cannot contain NUL"):
        genparams.generate("nul.yaml", f"genparams: 1\nname: n\nparameters:\n  x: {leaf}\n")


KEYWORDS = [k for k in [*keyword.kwlist, *keyword.softkwlist] if k.isidentifier() and k != "_"]
BUILTINS = ["print", "list", "dict", "type", "id", "len", "object", "property", "range", "super"]
BUILTINS += ["open", "exec", "eval", "compile", "globals", "self", "cls", "os", "sys"]
API = ["snapshot", "declare", "defaults", "on_change", "to_dict", "remote", "changes"]


def test_keywords_builtins_and_api_names_are_usable(ros: RosHarness, tmp_path: Path) -> None:
    names = list(dict.fromkeys(KEYWORDS + BUILTINS))  # 'type' is a soft keyword from 3.12
    body = [f"  {name}: {{type: int, default: {i}}}" for i, name in enumerate(names)]
    body.append("  to-dict: {type: int, default: -1}")  # '-' spelt '_': a method's name
    body.append("  api:")
    body += [f"    {name}: {{type: string, default: {name}}}" for name in API]
    schema = "genparams: 1\nname: names\nparameters:\n" + "\n".join(body) + "\n"
    module_path = tmp_path / "names_params.py"
    module_path.write_text(genparams.generate("names.yaml", schema), encoding="utf-8")
    cls = params_class(import_file(module_path))
    node = ros.node()
    cfg = cls.declare(node)
    expected: dict[str, object] = {name: i for i, name in enumerate(names)}
    expected.update({f"api.{name}": name for name in API})
    expected["to-dict"] = -1
    assert mismatches(read_back(ros, node, cfg), expected) == {}
    assert get_path(cfg, ("class_",)) == names.index("class")
    assert getattr(cfg, "print") == names.index("print")  # noqa: B009
    assert cfg.snapshot().to_dict()["api"]["snapshot"] == "snapshot"  # API still works
    assert (get_path(cfg, ("to_dict_",)), cfg.to_dict()["to-dict"]) == (-1, -1)
    assert builtins.print is print  # nothing was rebound


@pytest.mark.parametrize(
    "name, message",
    [
        ("__init__", "invalid name"),
        ("__class__", "invalid name"),
        ("_private", "invalid name"),
        ("x y", "invalid name"),
        ("x//y", "invalid name"),
        ("-x", "invalid name"),
        ("a.b", "invalid name"),
    ],
)
def test_names_that_cannot_work_are_schema_errors(name: str, message: str) -> None:
    schema = f"genparams: 1\nname: n\nparameters:\n  {quoted(name)}: {{type: int, default: 1}}\n"
    with pytest.raises(SchemaError, match=message):
        genparams.generate("names.yaml", schema)


def test_no_file_name_declares_the_coding_of_the_generated_module(tmp_path: Path) -> None:
    """Line 1 names the schema file: a name like 'coding=utf_7 x.yaml' must not make Python
    read the module as UTF-7, where '+ACIACg-' in a description is a quote and a newline."""
    marker = tmp_path / "PWNED"
    description = f"+ACIACg-__import__('pathlib').Path({str(marker)!r}).touch()+AAoAIg-"
    schema = tmp_path / "coding=utf_7 evil.yaml"
    schema.write_text(
        "genparams: 1\nname: evil\n"
        f"description: {quoted(description)}\n"
        "parameters:\n  x: {type: int, default: 1}\n",
        encoding="utf-8",
    )
    module_path = tmp_path / "evil_params.py"
    done = subprocess.run(
        [sys.executable, "-m", "genparams", "generate", str(schema), "-o", str(module_path)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    with module_path.open("rb") as module_file:
        assert tokenize.detect_encoding(module_file.readline)[0] == "utf-8"
    first_line = module_path.read_text(encoding="utf-8").splitlines()[0]
    assert first_line.endswith(' from "coding\\x3dutf_7 evil.yaml".')
    module = import_file(module_path)
    assert module.__doc__ == description
    assert not marker.exists()
