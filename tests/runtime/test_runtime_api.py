"""A generated module refuses to run on a runtime of another API, and says what to do."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import genparams.runtime
from tests.golden import CASES
from tests.support import import_file, load_generated


def test_a_module_imports_on_the_runtime_it_was_generated_for(tmp_path: Path) -> None:
    module = load_generated(CASES / "all_types" / "schema.yaml", tmp_path)
    assert (
        f"runtime API {genparams.runtime.RUNTIME_API}," in Path(module.__file__ or "").read_text()
    )


def test_a_module_generated_for_another_runtime_fails_at_import(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    generated = (CASES / "all_types" / "expected_params.py").read_text(encoding="utf-8")
    path = tmp_path / "old_params.py"
    path.write_text(generated, encoding="utf-8")
    current = genparams.runtime.RUNTIME_API
    monkeypatch.setattr(genparams.runtime, "RUNTIME_API", current + 1)
    with pytest.raises(ImportError) as raised:
        import_file(path)
    message = str(raised.value)
    assert f"generated for genparams runtime API {current}," in message
    assert f"has API {current + 1}" in message
    assert "regenerate with genparams generate" in message


def test_no_zero_step_is_written() -> None:
    for module in CASES.glob("*/expected_params.py"):
        text = module.read_text(encoding="utf-8")
        assert re.search(r"range=\([^)]*, 0(\.0)?\)", text) is None, module
        assert "range=(" in text or module.parent.name != "validators"
