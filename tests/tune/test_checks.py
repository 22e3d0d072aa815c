"""The page's checks are the node's: the check route, and the page in Chromium, against real nodes.

Every row of the edge-value table (tests/edge_values.py) is checked through
``/api/check`` and set on a real node over its parameter services: verdict and
reason must be equal. A subset goes through the real page. Then the values the
old JavaScript checks refused, rules and custom validators shown before apply,
values of the wrong JSON type, and a change made while the page's own apply is
in flight.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Any

import pytest
from playwright.sync_api import Page, Route, expect
from rcl_interfaces.msg import SetParametersResult
from rclpy.parameter import Parameter

from genparams.tune.server import TuneServer
from tests.edge_values import EDGES, SCALAR_EDGES, TOLERANCE, Edge
from tests.patience import WAIT_S
from tests.support import RosHarness, ServiceClient
from tests.tune.support import (
    api_call,
    demo_nodes,
    error,
    eventually,
    service_client,
    unique,
)
from tests.tune.support import open_node as open_in_page

EDGES_NODE, CHECKS_NODE, ARM_NODE = (
    f"/{unique(s)}" for s in ("check_edges", "check_rules", "check_arm")
)
TRUSTED = ("tests.custom_checks", "node_only_checks")


@pytest.fixture(scope="module")
def nodes() -> Iterator[None]:
    with demo_nodes(f"{EDGES_NODE[1:]}:edges", f"{CHECKS_NODE[1:]}:checks", f"{ARM_NODE[1:]}:arm"):
        yield


@pytest.fixture(scope="module")
def server(nodes: None) -> Iterator[TuneServer]:
    tune = TuneServer(nodes=(EDGES_NODE, CHECKS_NODE, ARM_NODE), trusted_packages=TRUSTED)
    tune.start()
    tune.graph.wait_for_schemas([EDGES_NODE, CHECKS_NODE, ARM_NODE], timeout=WAIT_S)
    try:
        yield tune
    finally:
        tune.stop()


def post(server: TuneServer, path: str, body: Any) -> tuple[int, dict[str, Any]]:
    answer = api_call(server, "/" + path, body)
    return answer.status, answer.json()


def check(server: TuneServer, node: str, *edits: tuple[str, Any]) -> dict[str, Any]:
    """The check route's answer; each value goes with the type the node holds."""
    held = {p["name"]: p["type"] for p in server.graph.read_node(node)}
    params = [{"name": n, "type": held[n], "value": v} for n, v in edits]
    status, answer = post(server, "api/check", {"node": node, "params": params})
    assert status == 200, answer
    return answer


def plain(value: Any) -> Any:
    return value if isinstance(value, (bool, int, float, str)) else list(value)


def node_verdict(remote: ServiceClient, *edits: tuple[str, Any]) -> SetParametersResult:
    """What the node answers to an atomic set of ``edits``; what it held is put back."""
    names = [name for name, _ in edits]
    before = remote.get(*names)
    result = remote.set_atomically(*(Parameter(n, value=v) for n, v in edits))
    if result.successful:
        restored = remote.set_atomically(
            *(Parameter(n, value=plain(v)) for n, v in zip(names, before, strict=True))
        )
        assert restored.successful, restored.reason
    return result


def same_verdict(answer: dict[str, Any], node: SetParametersResult) -> None:
    assert (answer["successful"], answer["reason"]) == (node.successful, node.reason or None)


# Parity over the whole edge-value table -------------------------------------------------


@pytest.mark.parametrize("edge", EDGES, ids=lambda e: e.id)
def test_the_check_route_gives_the_node_verdict(
    edge: Edge, server: TuneServer, ros_harness: RosHarness
) -> None:
    answer = check(server, EDGES_NODE, (edge.name, edge.value))
    node = node_verdict(service_client(ros_harness, EDGES_NODE), (edge.name, edge.value))
    assert node.successful == edge.accepted, node.reason
    same_verdict(answer, node)
    (result,) = answer["results"]
    assert (result["successful"], result["reason"]) == (node.successful, node.reason or None)


# Mapped entries, the keys that make them, and an old name (alias) of a parameter.
ARM_EDITS = [
    [("gains.shoulder.p", 2.0)],
    [("gains.shoulder.p", -1.0)],
    [("gains.elbow.i", -0.5), ("gains.shoulder.p", 0.5)],
    [("joints", ["shoulder", "shoulder"])],
    [("joints", ["shoulder", "bad key!"])],
    [("joints", ["shoulder", "elbow", "wrist"])],
    [("max_speed", 3.5)],
    [("speed_limit", 2.0)],
    [("speed_limit", 3.5)],
]


@pytest.mark.parametrize("edits", ARM_EDITS, ids=repr)
def test_mapped_entries_and_old_names_answer_as_the_node(
    edits: list[tuple[str, Any]], server: TuneServer, ros_harness: RosHarness
) -> None:
    answer = check(server, ARM_NODE, *edits)
    same_verdict(answer, node_verdict(service_client(ros_harness, ARM_NODE), *edits))


# A representative subset through the real page: edges and sides of each kind of check.
PAGE_EDGES = [
    e
    for e in SCALAR_EDGES
    if (e.name, e.value)
    in {
        ("count", 5),
        ("count", 7),
        ("count", 105),
        ("ratio", 0.25 + TOLERANCE / 10),
        ("ratio", 0.3),
        ("level", 2.001),
        ("gain", 0.0),
        ("gain", 10.0),
        ("offset", 5),
        ("steps", 4),
        ("tag", "a"),
        ("tag", "abcde"),
    }
]


def open_node(page: Page, server: TuneServer, node: str, live: bool = True) -> None:
    """The node's form; with ``live`` off, edits wait for Apply."""
    open_in_page(page, server, node)
    if not live:
        page.locator("#live").uncheck()


def enter(page: Page, name: str, text: str) -> None:
    """Type into the parameter's text or number box, as a user does, and leave it."""
    box = page.locator(f'[data-param-box="{name}"]')
    if box.count() == 0:
        box = page.locator(f'[data-param="{name}"]')
    box.fill(text)
    box.dispatch_event("change")


def row(page: Page, name: str):  # type: ignore[no-untyped-def]
    return page.locator(f'[data-row="{name}"]')


SETTLED = re.compile("^(ok|refused)$")


def shown_verdict(page: Page, name: str) -> tuple[bool, str | None]:
    """The verdict a row shows once the server answered: ok, or refused and why."""
    expect(row(page, name)).to_have_attribute("data-verdict", SETTLED)
    verdict = row(page, name).get_attribute("data-verdict")
    return verdict == "ok", error(page, name).text_content() or None


def test_the_page_subset_covers_every_kind(server: TuneServer) -> None:
    assert len(PAGE_EDGES) == 12
    assert {e.accepted for e in PAGE_EDGES} == {True, False}


@pytest.mark.parametrize("edge", PAGE_EDGES, ids=lambda e: e.id)
def test_the_page_shows_the_node_verdict(
    edge: Edge, page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    open_node(page, server, EDGES_NODE, live=False)
    enter(page, edge.name, repr(edge.value) if not isinstance(edge.value, str) else edge.value)
    shown = shown_verdict(page, edge.name)
    node = node_verdict(service_client(ros_harness, EDGES_NODE), (edge.name, edge.value))
    assert shown == (node.successful, node.reason or None)
    assert node.successful == edge.accepted


# What the JavaScript copy of the checks refused, and the node accepts ----------------------

ACCEPTED_BY_THE_NODE = [("label", "café"), ("share", 1.0000005), ("fine", 0.30000001)]


@pytest.mark.parametrize(("name", "value"), ACCEPTED_BY_THE_NODE)
def test_values_the_node_accepts_pass_the_check(
    name: str, value: Any, server: TuneServer, ros_harness: RosHarness
) -> None:
    answer = check(server, CHECKS_NODE, (name, value))
    node = node_verdict(service_client(ros_harness, CHECKS_NODE), (name, value))
    assert node.successful, node.reason
    same_verdict(answer, node)


def test_the_page_applies_values_the_node_accepts(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    remote = service_client(ros_harness, CHECKS_NODE)
    before = remote.get(*(n for n, _ in ACCEPTED_BY_THE_NODE))
    open_node(page, server, CHECKS_NODE)
    try:
        for name, value in ACCEPTED_BY_THE_NODE:
            enter(page, name, value if isinstance(value, str) else repr(value))
            eventually(lambda n=name, v=value: remote.get(n) == [v])  # type: ignore[misc]
            assert error(page, name).text_content() == ""
    finally:
        remote.set_atomically(
            *(Parameter(n, value=v) for (n, _), v in zip(ACCEPTED_BY_THE_NODE, before, strict=True))
        )


# Rules and custom validators, before apply ----------------------------------------------


def test_rules_and_custom_validators_answer_as_the_node(
    server: TuneServer, ros_harness: RosHarness
) -> None:
    remote = service_client(ros_harness, CHECKS_NODE)
    for edits in (
        [("low", 9)],
        [("low", 4), ("high", 3)],
        [("low", 9), ("high", 10)],
        [("even", 3)],
        [("even", 4)],
        [("even", 3), ("label", "a b")],
        [("low", 9), ("even", 3)],
        [("share", 2.0), ("low", 9)],
    ):
        answer = check(server, CHECKS_NODE, *edits)
        same_verdict(answer, node_verdict(remote, *edits))
    rule = check(server, CHECKS_NODE, ("low", 4), ("high", 3))
    assert [r["successful"] for r in rule["results"]] == [False, False]
    assert all("rule 'low_below_high' broken" in r["reason"] for r in rule["results"])
    # The node names only the value that fails its own check; the page shows the rule too.
    both = check(server, CHECKS_NODE, ("low", 9), ("even", 3))
    same_verdict(both, node_verdict(remote, ("low", 9), ("even", 3)))
    assert both["reason"] == "even: 3 is odd (tests.custom_checks:is_even)"
    low, even = both["results"]
    assert low["reason"].startswith("rule 'low_below_high' broken: low < high is false")
    assert even["reason"] == both["reason"]


def test_a_custom_validator_the_server_cannot_run_is_left_to_the_node(
    server: TuneServer, ros_harness: RosHarness
) -> None:
    answer = check(server, CHECKS_NODE, ("short", "abcd"))
    assert answer["successful"]
    (note,) = answer["results"][0]["not_checked"]
    assert "node_only_checks:is_short" in note
    assert "checked by the node on apply" in note
    assert "does not import here" in note
    refused = node_verdict(service_client(ros_harness, CHECKS_NODE), ("short", "abcd"))
    assert not refused.successful
    assert refused.reason == "short: 'abcd' is longer than 3 (node_only_checks:is_short)"
    untrusting = TuneServer(graph=server.graph)  # the default: no module is trusted
    untrusting.start()
    try:
        answer = check(untrusting, CHECKS_NODE, ("even", 3))
    finally:
        untrusting.stop()
    assert answer["successful"]
    (note,) = answer["results"][0]["not_checked"]
    assert "tests.custom_checks:is_even" in note
    assert "not trusted" in note


def test_rules_and_custom_validators_show_in_the_page_before_apply(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    remote = service_client(ros_harness, CHECKS_NODE)
    open_node(page, server, CHECKS_NODE, live=False)
    enter(page, "low", "9")
    (high,) = remote.get("high")
    assert shown_verdict(page, "low") == (
        False,
        f"rule 'low_below_high' broken: low < high is false for low=9, high={high}",
    )
    enter(page, "low", "1")
    enter(page, "even", "3")
    assert shown_verdict(page, "even") == (False, "even: 3 is odd (tests.custom_checks:is_even)")
    enter(page, "short", "abcd")
    assert shown_verdict(page, "short") == (True, None)
    expect(page.locator('[data-param-note="short"]')).to_contain_text(
        "checked by the node on apply"
    )
    assert remote.get("low", "even", "short") == [1, 2, "ab"]  # nothing was sent
    apply = page.locator("[data-apply]")
    apply.click()  # refused by the page's check: not sent
    expect(page.locator("#status")).to_contain_text("the node would refuse")
    assert remote.get("low", "even", "short") == [1, 2, "ab"]


def test_the_node_reason_shows_for_what_only_the_node_checks(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    open_node(page, server, CHECKS_NODE)
    enter(page, "short", "abcd")
    expect(error(page, "short")).to_have_text(
        "short: 'abcd' is longer than 3 (node_only_checks:is_short)"
    )
    assert service_client(ros_harness, CHECKS_NODE).get("short") == ["ab"]


# Values of the wrong JSON type ----------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "type_name", "value", "words"),
    [
        ("low", "int", True, "low: expected integer, got bool True"),
        ("low", "int", 2.5, "low: expected integer, got double 2.5"),
        ("share", "double", "0.5", "share: expected double, got string '0.5'"),
        ("share", "double", True, "share: expected double, got bool True"),
        ("label", "string", 5, "label: expected string, got integer 5"),
        ("low", "int", 2**63, "low: integer 9223372036854775808 does not fit in int64"),
    ],
)
def test_values_of_the_wrong_json_type_are_refused(
    name: str,
    type_name: str,
    value: Any,
    words: str,
    server: TuneServer,
    ros_harness: RosHarness,
) -> None:
    remote = service_client(ros_harness, CHECKS_NODE)
    before = remote.get(name)
    body = {"node": CHECKS_NODE, "params": [{"name": name, "type": type_name, "value": value}]}
    status, answer = post(server, "api/set", body)
    assert status == 400
    assert words in answer["error"]
    assert remote.get(name) == before
    status, answer = post(server, "api/check", body)
    assert status == 200
    assert (answer["successful"], answer["reason"]) == (False, words)


def test_a_double_may_be_written_without_a_fraction(
    server: TuneServer, ros_harness: RosHarness
) -> None:
    remote = service_client(ros_harness, CHECKS_NODE)
    body = {"node": CHECKS_NODE, "params": [{"name": "share", "type": "double", "value": 1}]}
    try:
        status, answer = post(server, "api/set", body)
        assert status == 200, answer
        assert answer["results"][0]["successful"]
        assert remote.get("share") == [1.0]
    finally:
        remote.set(Parameter("share", value=0.5))


def test_an_integer_typed_with_a_fraction_is_refused_in_the_page(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    open_node(page, server, CHECKS_NODE)
    enter(page, "low", "2.5")
    expect(error(page, "low")).to_have_text("low: expected integer, got double 2.5")
    enter(page, "high", "")
    expect(error(page, "high")).to_have_text("high: enter a number")
    enter(page, "even", "9223372036854775808")  # past 2^53: sent with every digit
    expect(error(page, "even")).to_have_text(
        "even: integer 9223372036854775808 does not fit in int64"
    )
    assert service_client(ros_harness, CHECKS_NODE).get("low", "high", "even") == [1, 5, 2]


# A change made while the page's own apply is in flight -----------------------------------


def test_a_change_during_the_apply_ends_in_the_form(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    remote = service_client(ros_harness, CHECKS_NODE)
    held: list[Route] = []
    open_node(page, server, CHECKS_NODE, live=False)
    page.route("**/api/set", lambda route: held.append(route))  # held until let go
    try:
        enter(page, "low", "2")
        assert shown_verdict(page, "low") == (True, None)
        page.locator("[data-apply]").click()
        while not held:  # the route fires while Playwright waits
            page.wait_for_timeout(20)
        applied = held[0].fetch()  # the node now holds low=2; the page has no answer yet
        assert remote.get("low") == [2]
        assert remote.set(Parameter("low", value=3))[0].successful  # another tab's change
        # The page has seen the other change while its apply is in flight.
        expect(page.locator('[data-param-node="low"]')).to_have_text("the node now holds 3")
        held[0].fulfill(response=applied)
        expect(page.locator('[data-param="low"]')).to_have_value("3")
        expect(page.locator("[data-apply]")).to_be_disabled()
        assert remote.get("low") == [3]
    finally:
        page.unroute("**/api/set")
        remote.set(Parameter("low", value=1))


def test_a_parameter_the_node_does_not_declare_answers_as_the_node(
    server: TuneServer, ros_harness: RosHarness
) -> None:
    remote = service_client(ros_harness, CHECKS_NODE)
    for edits in ([("no_such", 1)], [("low", 2), ("no_such", 1), ("nor_this", 2)]):
        params = [{"name": n, "type": "int", "value": v} for n, v in edits]
        status, answer = post(server, "api/check", {"node": CHECKS_NODE, "params": params})
        assert status == 200, answer
        same_verdict(answer, node_verdict(remote, *edits))
