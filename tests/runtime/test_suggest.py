"""The one "did you mean": schema checks, rules, remote sets and check-params all use it."""

from __future__ import annotations

from genparams.runtime.core.suggest import closest, closest_name, did_you_mean, did_you_mean_name


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


def test_the_whole_name_comes_before_its_last_segment() -> None:
    # The last segment alone ("rat") is closer to "rates", the whole name to the frame rate.
    assert closest_name("camera.rat", ["lidar.rates", "camera.frame_rate"]) == "camera.frame_rate"
    deep = ["control.gain", "wrist.gain"]
    assert closest_name("robot.arm.left.wrist.gian", deep) == "wrist.gain"
    assert closest_name("robot.arm.left.wrist.gian", deep, by_leaf=False) is None


def test_node_names_are_split_at_their_slashes() -> None:
    sections = ["/robot/cam", "/lidar"]
    assert closest_name("/ns/cam", sections, separator="/", by_leaf=False) == "/robot/cam"
