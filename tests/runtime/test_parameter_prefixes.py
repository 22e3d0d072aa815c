"""Parameter prefixes: dotted names are accepted, anything else is refused with one message."""

from __future__ import annotations

import pytest

from genparams.runtime.core.naming import check_prefix


@pytest.mark.parametrize("prefix", ["", "camera", "robot.front_camera", "robot.front-camera"])
def test_dotted_prefixes_are_accepted(prefix: str) -> None:
    assert check_prefix(prefix) == prefix


def test_a_bad_prefix_is_refused() -> None:
    with pytest.raises(ValueError) as caught:
        check_prefix("robot..camera")
    assert str(caught.value) == (
        "invalid parameter prefix 'robot..camera': dot-separated names of letters, digits, "
        "'_' and '-', starting with a letter, in parts joined by single '/'"
    )
