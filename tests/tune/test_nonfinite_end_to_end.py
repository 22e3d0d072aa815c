"""NaN and infinities end to end: the schema topic, the tuning API and page, the downloaded
params file, the audit and `genparams json-schema`; every JSON on the way is strict."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from playwright.sync_api import expect, sync_playwright

from genparams.runtime.core.json_codec import loads
from genparams.tune.server import TuneServer
from tests.support import ROOT
from tests.tune.support import (
    CHROMIUM,
    CHROMIUM_ARGS,
    api_call,
    demo_nodes,
    eventually,
    run_audit,
    unique,
)

NODE = f"/{unique('nonfinite')}"
SCHEMA = ROOT / "tests/tune/nonfinite.yaml"


def strict(text: str) -> Any:
    """Parse as a strict reader does: the tokens NaN and Infinity are not JSON."""
    return json.loads(text, parse_constant=lambda token: pytest.fail(f"{token} in {text[:80]}"))


@pytest.fixture(scope="module")
def server() -> Iterator[TuneServer]:
    with demo_nodes(f"{NODE[1:]}:nonfinite"):
        tune = TuneServer(nodes=(NODE,))
        tune.start()
        try:
            eventually(lambda: tune.graph.schema(NODE))
            yield tune
        finally:
            tune.stop()


def get(server: TuneServer, path: str, body: Any = None) -> str:
    answer = api_call(server, path, body)
    assert answer.ok, answer.body
    return answer.body.decode("utf-8")


def values(server: TuneServer) -> dict[str, Any]:
    answer = loads(get(server, f"/api/node?name={NODE}"))
    return {p["name"]: p["value"] for p in answer["parameters"]}


def test_the_api_carries_non_finite_defaults_bounds_and_values(server: TuneServer) -> None:
    text = get(server, f"/api/node?name={NODE}")
    strict(text)
    assert '{"$float":"nan"}' in text and '{"$float":"-inf"}' in text
    answer = loads(text)
    described = {p["name"]: p for p in answer["schema"]["classes"][0]["parameters"]}
    assert math.isnan(described["threshold"]["default"])
    assert described["ceiling"]["default"] == math.inf
    assert described["gain"]["range"]["max"] == math.inf
    held = {p["name"]: p["value"] for p in answer["parameters"]}
    assert math.isnan(held["threshold"]) and held["floor"] == -math.inf
    nan, one, minus_inf = held["samples"]
    assert math.isnan(nan) and one == 1.0 and minus_inf == -math.inf


def test_sets_send_non_finite_values_as_tags(server: TuneServer) -> None:
    def set_ceiling(value: Any) -> None:
        body = {"node": NODE, "params": [{"name": "ceiling", "type": "double", "value": value}]}
        answer = loads(get(server, "/api/set", body))
        assert answer["results"][0]["successful"], answer

    set_ceiling(5.0)
    assert values(server)["ceiling"] == 5.0
    set_ceiling({"$float": "inf"})
    assert values(server)["ceiling"] == math.inf


def test_the_page_decodes_the_tags(server: TuneServer) -> None:
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        try:
            page = browser.new_page()
            page.goto(server.url + f"#{NODE}")
            expect(page.locator(f'form[data-node="{NODE}"]')).to_be_visible()
            expect(page.locator('[data-param="threshold"]')).to_have_count(1)
            # NaN holding NaN and inf holding inf are at their defaults.
            expect(page.locator("[data-diff-empty]")).to_be_visible()
            decoded = page.evaluate(
                """async () => {
                  const { parseJson, stringifyJson } = await import("/static/json.js");
                  const back = parseJson(stringifyJson([NaN, Infinity, -Infinity, 1.5]));
                  return [Number.isNaN(back[0]), back[1] === Infinity, back[2] === -Infinity,
                          back[3], stringifyJson({ v: -Infinity })];
                }"""
            )
            assert decoded == [True, True, True, 1.5, '{"v":{"$float":"-inf"}}']
        finally:
            browser.close()


def test_the_page_shows_and_takes_nan_and_infinities_by_name(server: TuneServer) -> None:
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        try:
            page = browser.new_page()
            page.goto(server.url + f"#{NODE}")
            threshold = page.locator('[data-param="threshold"]')
            expect(threshold).to_have_value("nan")
            expect(page.locator('[data-param="floor"]')).to_have_value("-inf")
            expect(page.locator('[data-param="mode"]')).to_have_value("1.0")  # a double: 1.0
            threshold.fill("inf")
            threshold.dispatch_event("change")  # live: applied at once
            eventually(lambda: values(server)["threshold"] == math.inf)
            diff = page.locator('[data-diff="threshold"] td')
            expect(diff).to_have_text(["threshold", "nan", "inf"])  # never null
            threshold.fill("1e400")  # no double: refused in the page, nothing sent
            threshold.dispatch_event("change")
            expect(page.locator('[data-param-error="threshold"]')).to_contain_text("not a number")
            threshold.fill("NaN")
            threshold.dispatch_event("change")
            eventually(lambda: math.isnan(values(server)["threshold"]))
            expect(page.locator("[data-diff-empty]")).to_be_visible()
        finally:
            browser.close()


def test_download_then_audit_finds_no_drift(server: TuneServer, tmp_path: Path) -> None:
    params = tmp_path / "nonfinite.yaml"
    params.write_text(get(server, f"/api/params-file?node={NODE}"), encoding="utf-8")
    assert ".nan" in params.read_text(encoding="utf-8")
    done = run_audit("--format", "json", "--params-file", str(params), NODE, cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    report = strict(done.stdout)
    assert report["audited"] == [NODE]
    assert report["findings"] == []


def test_json_schema_writes_no_infinity(tmp_path: Path) -> None:
    out = tmp_path / "nonfinite.schema.json"
    done = subprocess.run(
        [sys.executable, "-m", "genparams", "json-schema", str(SCHEMA), "-o", str(out)],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    definitions = strict(out.read_text(encoding="utf-8"))["$defs"]
    # An infinite bound is no bound; a default JSON cannot hold is left out.
    assert definitions["param.ceiling"]["minimum"] == 0.0
    assert "maximum" not in definitions["param.ceiling"]
    assert "maximum" not in definitions["param.gain"]
    assert "exclusiveMaximum" not in definitions["param.floor"]
    assert "enum" not in definitions["param.mode"]
    assert "default" not in definitions["param.threshold"]
    assert definitions["param.gain"]["default"] == 1.0
