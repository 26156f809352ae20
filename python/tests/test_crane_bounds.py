"""The crane's work and memory bounded before it starts: a grid of ``Path.knots`` or
``Path.pivot_samples`` that would not fit in the memory this process can get, an ``LQR.simulate`` over
more steps than allowed, refused up front naming the value, the samples or steps asked and the most
allowed; a ``Tower`` given ``luff`` without ``boom`` (or ``boom`` without ``luff``), which the radius
silently overrode, refused naming what is missing, and one given a ``radius`` with them, which they
silently overrode, refused naming all three; its ``radius_at(t)``, the radius as a number [m] when the
``radius`` field is None (luffing) or a profile."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from pendulab import InvalidInputError, crane, memory
from pendulab.crane._checks import SAMPLE_BYTES
from pendulab.validate import show

MOVE = crane.move(2.0, 0.5, 0.5)
MIB = 2**20


@pytest.fixture
def one_mib(monkeypatch: pytest.MonkeyPatch) -> int:
    """This process can get 1 MiB more: 0.8 MiB / SAMPLE_BYTES samples fit."""
    monkeypatch.setattr(memory, "available_bytes", lambda: MIB)
    return int(memory.USABLE_FRACTION * MIB / SAMPLE_BYTES)


def test_knots_beyond_memory_are_refused_up_front(one_mib: int) -> None:
    with pytest.raises(InvalidInputError) as err:
        MOVE.knots(0.0, 10.0, spacing=1e-3)
    text = str(err.value)
    assert text.startswith("invalid spacing = 0.001:"), text
    assert f"at most {one_mib} samples fit" in text and "10001 asked over 10.0 s" in text, text
    assert "a larger spacing or a shorter span" in text
    t, p, _, _ = MOVE.knots(0.0, 10.0, spacing=10.0 / (one_mib - 20))  # fits (breaks add a few)
    assert p.shape[0] == t.size > one_mib - 20


def test_pivot_samples_beyond_memory_are_refused_up_front(one_mib: int) -> None:
    with pytest.raises(InvalidInputError, match=re.escape("invalid spacing = 0.0001:")) as err:
        MOVE.pivot_samples(10.0, spacing=1e-4)
    assert f"at most {one_mib} samples fit" in str(err.value) and "100001 asked" in str(err.value)
    t, _ = MOVE.pivot_samples(10.0, spacing=10.0 / (one_mib - 1))
    assert t.size == one_mib


def test_memory_unknown_leaves_the_sample_limit_only(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(memory, "available_bytes", lambda: None)
    assert MOVE.pivot_samples(1.0, spacing=1e-3)[0].size == 1001
    with pytest.raises(InvalidInputError, match="at most 1000000000 samples"):
        MOVE.pivot_samples(1e3, spacing=1e-9)


@pytest.mark.parametrize(
    ("kwargs", "given", "missing"),
    [({"luff": 0.5}, "luff = 0.5", "boom"), ({"boom": 30.0}, "boom = 30.0", "luff")],
)
def test_tower_luff_and_boom_come_together(kwargs: dict[str, float], given: str, missing: str) -> None:
    with pytest.raises(InvalidInputError) as err:
        crane.Tower(radius=12.0, **kwargs)  # type: ignore[arg-type]
    text = str(err.value)
    assert text.startswith(f"Tower: {given} given without {missing}:"), text
    assert "give both, or neither" in text


def test_tower_luff_profile_without_boom_is_refused() -> None:
    with pytest.raises(InvalidInputError, match=r"Tower: luff = .* given without boom"):
        crane.Tower(luff=crane.profile(0.3, 0.1, 0.1))


def test_tower_with_both_or_neither_is_taken() -> None:
    luffing = crane.Tower(luff=0.5, boom=30.0, height=2.0)
    assert luffing.position(0.0)[0, 2] == pytest.approx(2.0 + 30.0 * 0.479425538604203)
    assert luffing.radius is None  # L cos β is the radius
    assert crane.Tower(radius=12.0).position(0.0)[0, 0] == pytest.approx(12.0)
    assert crane.Tower().radius == 10.0 and crane.Tower().position(0.0)[0, 0] == 10.0  # the default


def test_tower_radius_at_is_a_number_luffing_or_not() -> None:
    """A luffing tower's ``radius`` is None (and a radius profile no number): callers reading it as a
    number broke. ``radius_at(t)`` [m] is the radius at any time: L cos β(t) on a luffing boom (here
    checked against the tip's horizontal distance from the axis, from the position), the profile, or
    the constant."""
    luff = crane.profile(-0.3, 0.05, 0.03, start=1.0)
    t = np.array([0.0, 3.0, 8.0, 40.0])
    for tower in (
        crane.Tower(slew=0.7, luff=luff, boom=35.0, height=5.0),
        crane.Tower(slew=crane.profile(1.0, 0.1, 0.05), radius=crane.profile(5.0, 0.5, 0.2, start=12.0)),
    ):
        p = tower.position(t)
        np.testing.assert_allclose(tower.radius_at(t), np.hypot(p[:, 0], p[:, 1]), rtol=1e-14)
    assert crane.Tower(luff=0.5, boom=30.0).radius_at(0.0)[0] == pytest.approx(
        30.0 * math.cos(0.5), rel=1e-15
    )
    assert crane.Tower(luff=luff, boom=35.0).radius_at(0.0)[0] == pytest.approx(35.0 * math.cos(1.0))
    assert crane.Tower(radius=12.0).radius_at([0.0, 5.0]).tolist() == [12.0, 12.0]
    assert crane.Tower().radius_at(0.0).tolist() == [10.0]  # the default
    with pytest.raises(InvalidInputError, match="invalid t = nan"):
        crane.Tower(luff=0.5, boom=30.0).radius_at(math.nan)


@pytest.mark.parametrize("radius", [12.0, 10.0, crane.profile(2.0, 0.5, 0.5, start=10.0)])
def test_tower_radius_with_luff_and_boom_is_refused(radius: float | crane.Profile) -> None:
    """The boom's tip is at radius L cos β: a radius given beside luff and boom was silently ignored
    (10 m, the default, too: given is given)."""
    with pytest.raises(InvalidInputError) as err:
        crane.Tower(radius=radius, luff=0.5, boom=30.0)
    text = str(err.value)
    assert text.startswith(f"Tower: radius = {show(radius)} given with"), text
    assert "given with luff = 0.5 and boom = 30.0: a luffing boom's tip is at radius boom·cos(luff)" in text
    assert "give radius for a trolley on a horizontal jib, or luff and boom for a luffing boom" in text


CTRL = crane.lqr(rope=5.0)


@pytest.mark.parametrize("t_end", [1e6, 1e9, 1e12])
def test_lqr_over_more_steps_than_minutes_is_refused_up_front(
    monkeypatch: pytest.MonkeyPatch, t_end: float
) -> None:
    """SciPy's DOP853 steps in Python (~0.5 ms a step): 2e5 steps at most, a few minutes (1e6 s here is
    ~2.3e5 steps, taken before under a crane run's 2e7 steps, which would be hours)."""
    monkeypatch.setattr(memory, "available_bytes", lambda: None)  # the step limit alone
    with pytest.raises(InvalidInputError) as err:
        CTRL.simulate(1.0, t_end=t_end)
    text = str(err.value)
    assert text.startswith(f"invalid t_end = {t_end!r}: at most 200000 steps of the closed loop (SciPy"), text
    rate = max(abs(CTRL.poles))
    assert f"it takes about {t_end * rate / 6.0:.3g}" in text and "a shorter t_end" in text, text
    assert f"(t_end - t_start <= {2e5 * 6.0 / rate:.3g} s)" in text, text


def test_lqr_beyond_memory_is_refused_and_within_runs(one_mib: int) -> None:
    from pendulab.crane.lqr import STEP_BYTES

    most = int(memory.USABLE_FRACTION * MIB / STEP_BYTES)
    with pytest.raises(InvalidInputError, match=f"at most {most} steps of the closed loop .what fits in"):
        CTRL.simulate(1.0, t_end=1e4)
    run = CTRL.simulate(1.0, t_end=1e3)
    taken = sum(len(s.ts) - 1 for s in run._dense.sols)
    assert 1e3 * max(abs(CTRL.poles)) / 6.0 <= taken <= most  # the estimate is below the steps taken
