"""Without the tune extra, `genparams tune` names the install command and exits 2.

Here the web stack is made unimportable in a fresh interpreter; a lean install from the
wheel, where it is absent for real, is tested in tests/integration/test_packaging.py.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

from genparams.commands.tune import INSTALL_HINT

# A None in sys.modules makes `import NAME` fail as for a package that is not installed.
WITHOUT = """
import sys
for name in sys.argv[1].split(","):
    sys.modules[name] = None
from genparams.cli import main
sys.exit(main(["tune", *sys.argv[2:]]))
"""


def tune_without(missing: str, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-c", WITHOUT, missing, *args],
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )


@pytest.mark.parametrize("missing", ["starlette", "uvicorn", "starlette,uvicorn"])
def test_tune_without_the_extra_prints_the_install_command(missing: str) -> None:
    done = tune_without(missing, "--port", "0", "/some/node")
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr.startswith("genparams tune: ")
    assert done.stderr.endswith(f": {INSTALL_HINT}\n") and done.stderr.count("\n") == 1
    assert INSTALL_HINT == "pip install 'genparams[tune]'"


def test_another_missing_module_is_not_taken_for_the_extra() -> None:
    done = tune_without("genparams.live.graph")
    assert done.returncode == 1 and INSTALL_HINT not in done.stderr
    assert "ModuleNotFoundError" in done.stderr
