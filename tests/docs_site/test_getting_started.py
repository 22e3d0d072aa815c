"""docs/getting-started.md runs as written, from an empty temporary folder.

The page is the script: its blocks are read in order. A block whose first line names a
file (`# ws/src/rover/setup.py`, `<!-- ws/src/rover/package.xml -->`) is written there;
every line of a `sh` block runs in one bash session, so `cd` and `.` carry over as in a
terminal. An output block right after a `sh` block is what that block prints; a
trailing `# exit N` is the exit code a line is shown to give.

Left to the machine, not run: the `ros2` lines (ros2cli comes with a ROS 2 install,
which the test machine has not), the install lines (the test runs in the development
venv, which holds what they install; tests/integration/test_packaging.py installs the
wheel into a fresh venv) and the line exporting the DDS domain (the suite gives each run
its own). `genparams tune` runs until the page is served, then is stopped. What the page
says of the `ros2` lines is checked on the built node over the same parameter services.
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
from dataclasses import dataclass
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

from tests.build_support import node_process, space_free_tools, tool_env, wait_for_node
from tests.docs_site.pages import DOCS, Block, blocks, shell_lines
from tests.support import RosHarness, unique_name

pytestmark = [pytest.mark.docs, pytest.mark.slow]

PAGE = DOCS / "getting-started.md"
_FILE_NAME = re.compile(r"^(?:#|<!--)\s*(?P<path>ws/[\w./-]+)\s*(?:-->)?\s*$")
_SHOWN_EXIT = re.compile(r"#.*\bexit (\d)\s*$")
_NOT_RUN = re.compile(
    r"^(?:ros2 |python3 -m venv |\.venv/bin/pip install |\. \.venv/bin/activate$|"
    r"export ROS_AUTOMATIC_DISCOVERY_RANGE=)"
)
_TUNE = re.compile(r"^genparams tune\b")


@dataclass(frozen=True)
class Step:
    kind: str  # "file", "sh"
    text: str
    path: str = ""
    output: str | None = None  # what a sh block prints, when the page shows it


def steps(text: str) -> list[Step]:
    found: list[Step] = []
    for block in blocks(text):
        first = block.body.partition("\n")[0]
        named = _FILE_NAME.match(first)
        if named and block.lang != "sh":
            found.append(Step("file", block.body, path=named["path"]))
        elif block.lang == "sh":
            found.append(Step("sh", block.body, output=shown_output(block)))
    return found


def shown_output(block: Block) -> str | None:
    after = block.followed_by
    return after.body if after is not None and not after.lang else None


def script_line(line: str, log: Path) -> str:
    """One page line as the session runs it; a failure stops the session naming the line."""
    command = line.split("   #")[0].rstrip()
    shown = _SHOWN_EXIT.search(line)
    expected = int(shown[1]) if shown else 0
    quoted = shlex.quote(line)
    if _TUNE.match(command):
        # Any free port; served once its address is printed; then Ctrl-C (a job of its
        # own, as in a terminal: a plain background job would ignore SIGINT).
        tune_log = shlex.quote(str(log.with_suffix(".tune")))
        return (
            f"set -m; {command} --port 0 > {tune_log} 2>&1 & tune=$!; set +m\n"
            f"for _ in $(seq 600); do grep -q 'serving http' {tune_log} && break;"
            " kill -0 $tune 2>/dev/null || break; sleep 0.1; done\n"
            f"grep -q 'serving http://127.0.0.1:' {tune_log} || {{ kill $tune; cat {tune_log} >&2;"
            " echo 'FAILED: genparams tune served nothing' >&2; exit 99; }\n"
            "kill -INT $tune; wait $tune ||"
            " { echo 'FAILED: genparams tune did not stop' >&2; exit 99; }\n"
        )
    return (
        f"{command} >> {shlex.quote(str(log))} 2>&1; code=$?\n"
        f"[ $code -eq {expected} ] || {{ cat {shlex.quote(str(log))} >&2;"
        f' echo "FAILED (exit $code): "{quoted} >&2; exit 99; }}\n'
    )


def session(page_steps: list[Step], top: Path, logs: Path) -> str:
    lines = [f"cd {shlex.quote(str(top))}"]
    for number, step in enumerate(page_steps):
        if step.kind == "file":
            target = shlex.quote(str(top / step.path))
            lines.append(f"mkdir -p $(dirname {target})")
            end = "GETTING_STARTED_FILE"
            lines.append(f"cat > {target} <<'{end}'\n{step.text}{end}")
            continue
        log = logs / f"{number}.out"
        for line in shell_lines(step.text):
            if line.strip() and not _NOT_RUN.match(line):
                lines.append(script_line(line, log))
    return "\n".join(lines) + "\n"


def test_the_page_is_read_as_expected() -> None:
    page_steps = steps(PAGE.read_text(encoding="utf-8"))
    files = [step.path for step in page_steps if step.kind == "file"]
    assert "ws/src/rover/setup.py" in files and "ws/src/rover/package.xml" in files
    commands = [line for s in page_steps if s.kind == "sh" for line in shell_lines(s.text)]
    assert any(line.startswith("colcon build") for line in commands)
    assert any(line.startswith("ros2 param set") for line in commands)
    assert any(_TUNE.match(line) for line in commands)


def test_the_page_runs_from_an_empty_folder(tmp_path: Path, ros: RosHarness) -> None:
    # No space in this path: colcon's install/setup.sh breaks on one (docs/getting-started.md).
    top = tmp_path / "empty"
    top.mkdir()
    logs = tmp_path / "logs"
    logs.mkdir()
    page_steps = steps(PAGE.read_text(encoding="utf-8"))
    env = tool_env()
    env["PATH"] = f"{space_free_tools(tmp_path)}{os.pathsep}{env['PATH']}"
    assert env["ROS_DOMAIN_ID"] != "42" and env["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "LOCALHOST"
    env.pop("VIRTUAL_ENV", None)
    ran = subprocess.run(
        ["bash", "-c", session(page_steps, top, logs)],
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
        check=False,
    )
    assert ran.returncode == 0, ran.stderr[-4000:]
    for number, step in enumerate(page_steps):
        if step.output is not None:
            assert (logs / f"{number}.out").read_text() == step.output, step.text
    generated = list((top / "ws" / "install").rglob("rover_driver_params.py"))
    assert generated, "colcon installed no generated module"
    assert (top / "ws" / "src" / "rover" / "rover_driver.md").read_text().count("speed.max") >= 1
    assert not (top / "ws" / "src" / "rover" / "rover" / "rover_driver_params.py").exists()
    assert os.listdir(top) == ["ws"]

    # `ros2 run rover rover_driver`, then what the page says `ros2 param` shows.
    workspace = top / "ws"
    name = unique_name("rover_driver")
    remap = ["-r", f"__node:={name}", "--params-file", "src/rover/config/rover.params.yaml"]
    with node_process(workspace, "install/rover/lib/rover/rover_driver", *remap) as process:
        client = wait_for_node(ros, process, f"/{name}")
        (described,) = client.describe("speed.max")
        assert described.description.startswith("Fastest speed the driver commands.")
        assert (
            described.floating_point_range[0].from_value,
            described.floating_point_range[0].to_value,
        ) == (0.0, 3.0)
        assert client.set(Parameter("speed.max", value=2.5))[0].successful
        (refused,) = client.set(Parameter("speed.max", value=7.0))
        assert not refused.successful
        # rclpy's own range check refuses it; genparams words the reason (the same rule).
        assert refused.reason == "speed.max: must be within [0.0, 3.0] (range), got 7.0"
        assert client.get("speed.max") == [2.5]
