"""How hard the property tests and fuzzers try, chosen by GENPARAMS_TEST_PROFILE.

``ci`` (default) keeps the robustness suite to a few minutes on two cores;
``dev`` runs ten times as many examples and fuzzes ten minutes per target;
``mutate`` (set by ``make mutate``, which runs tests once per mutant) a tenth:

    GENPARAMS_TEST_PROFILE=dev .venv/bin/python -m pytest tests/robustness/test_properties.py

GENPARAMS_FUZZ_SECONDS overrides the fuzzing time of either profile.
"""

from __future__ import annotations

import os

from hypothesis import HealthCheck, Phase, settings

PROFILE = os.environ.get("GENPARAMS_TEST_PROFILE", "ci")
if PROFILE not in ("ci", "dev", "mutate"):
    raise RuntimeError(f"GENPARAMS_TEST_PROFILE must be ci, dev or mutate, not {PROFILE!r}")

_SCALE = {"ci": 1.0, "dev": 10.0, "mutate": 0.1}[PROFILE]

settings.register_profile(
    "ci",
    deadline=None,
    print_blob=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
settings.register_profile("dev", parent=settings.get_profile("ci"))
settings.register_profile("mutate", parent=settings.get_profile("ci"))
# While debugging, GENPARAMS_NO_SHRINK=1 reports the first failing example as found.
settings.register_profile(
    "no_shrink",
    parent=settings.get_profile(PROFILE),
    phases=[Phase.explicit, Phase.reuse, Phase.generate],
)
settings.load_profile("no_shrink" if os.environ.get("GENPARAMS_NO_SHRINK") else PROFILE)


def examples(ci_count: int) -> int:
    """The number of examples a test runs under the current profile."""
    return max(5, round(ci_count * _SCALE))


def fuzz_seconds(ci_seconds: float) -> float:
    override = os.environ.get("GENPARAMS_FUZZ_SECONDS")
    if override:
        return float(override)
    return 600.0 if PROFILE == "dev" else ci_seconds
