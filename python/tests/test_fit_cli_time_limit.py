"""``pendulab fit --time-limit`` (docs/cli.md, docs/fit.md "The time limit"): the command had no way to
set pl.fit's ``time_limit``, which the advice of a fit stopped by it names. Seconds, or ``none``; a bad
value is refused before the fit, naming the value and what is allowed."""

from __future__ import annotations

from typing import Any

import pytest
from test_cli import assert_user_error, invoke

from pendulab.cli import fit as fit_cli


class _Stop(Exception):
    """Raised by the fit stand-in once it has seen its arguments."""


@pytest.fixture
def seen(monkeypatch: pytest.MonkeyPatch) -> dict[str, Any]:
    """The keyword arguments the command gives pl.fit (the fit itself is not run)."""
    got: dict[str, Any] = {}

    def record(**kwargs: Any) -> None:
        got.update(kwargs)
        raise _Stop

    monkeypatch.setattr(fit_cli, "fit", record)
    return got


@pytest.mark.parametrize(
    ("given", "expected"),
    [(None, None), ("none", None), ("None", None), ("300", 300.0), ("0.5", 0.5), ("1e3", 1000.0)],
)
def test_the_time_limit_reaches_pl_fit(seen: dict[str, Any], given: str | None, expected: Any) -> None:
    args = ["fit", "example:crane_sway"] + ([] if given is None else ["--time-limit", given])
    with pytest.raises(_Stop):
        invoke(*args)
    assert seen["time_limit"] == expected


@pytest.mark.parametrize("bad", ["0", "-5", "nan", "inf", "1e9", "soon", ""])
def test_a_bad_time_limit_is_refused_before_the_fit(seen: dict[str, Any], bad: str) -> None:
    assert_user_error(
        *invoke("fit", "example:crane_sway", "--time-limit", bad),
        f"--time-limit {bad!r}",
        "a number of seconds > 0 and < 1e9, or none",
    )
    assert not seen
