"""The one "did you mean": schema checks, rules, remote sets and check-params all use it."""

from __future__ import annotations

from genparams.runtime.core.suggest import closest, did_you_mean, did_you_mean_name


def test_a_close_word_is_offered() -> None:
    assert did_you_mean("defualt", ["default", "description"]) == " (did you mean 'default'?)"
    assert did_you_mean("zzz", ["default"]) == ""
    assert closest("fsp", ["fps", "gain"]) == "fps"


def test_a_moved_name_is_found_by_its_last_segment() -> None:
    names = ["camera.fps", "camera.width", "control.gain"]
    assert did_you_mean_name("fps", names) == " (did you mean 'camera.fps'?)"
    assert did_you_mean_name("camera.widht", names) == " (did you mean 'camera.width'?)"
    assert did_you_mean_name("a.b.c.control.gian", names) == " (did you mean 'control.gain'?)"
    assert did_you_mean_name("nothing", names) == ""
