"""A crane's rope lengths bounded as a pendulum's length is (``pl.limits()`` ``length``, 1e-6 to 1e4 m;
docs/limits.md, docs/cranes.md): ``Crane(rope=…)``, ``rigging``, ``Crane.modes(rope=…)``,
``crane.lqr(rope)``, ``residual_grid(ropes)``, a ``Hoist``'s samples and the true range of its spline
(which overshoots far above samples of ≤ 40 m between samples much closer in time than their
neighbours: 182 m), refused naming the value, the place and what is allowed; in a crane file the key.
A scenario file's error shows five problems and says how many more (``problems`` keeps them all)."""

from __future__ import annotations

import re

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

import pendulab as pl
from pendulab import InvalidInputError, crane
from pendulab.crane.scenario import parse

LONGEST = {row["name"]: row for row in pl.limits()}["length"]["max"]
ALLOWED = "in [1e-6, 1e4] m (a pendulum's length, pl.limits() length)"
SHORTEST = {row["name"]: row for row in pl.limits()}["length"]["min"]


def test_the_bounds_are_the_pendulums() -> None:
    assert (SHORTEST, LONGEST) == (1e-6, 1e4)
    pl.Pendulum(length=LONGEST)
    pl.Pendulum(length=SHORTEST)
    crane.Crane(rope=LONGEST)  # the longest and the shortest themselves are allowed, as for a pendulum
    crane.Crane(rope=SHORTEST)
    crane.Hoist([0.0, 10.0], [LONGEST, 10.0])
    crane.Hoist([0.0, 10.0], [SHORTEST, 10.0])
    with pytest.raises(InvalidInputError, match="length"):
        pl.Pendulum(length=1e-9)  # and what a pendulum refuses, a crane refuses too (below)


@pytest.mark.parametrize(
    ("make", "named"),
    [
        (lambda: crane.Crane(rope=2e4), "rope = 20000.0"),
        (lambda: crane.Crane(rope=5.0, hook_mass=50.0, rigging=1e5), "rigging = 100000.0"),
        (lambda: crane.Crane(rope=5.0).modes(rope=1.5e4), "rope = 15000.0"),
        (lambda: crane.lqr(2e4), "rope = 20000.0"),
        (lambda: crane.residual_grid([5.0, 3e4], [0.1], [None], progress=False), r"ropes\[1\] = 30000.0"),
        (lambda: crane.Hoist([0.0, 1.0, 2.0], [5.0, 1e4, 2e4]), r"length\[2\] = 20000.0"),
        (lambda: crane.rope_range(1.0, 2e4), "rope_max = 20000.0"),
        # below the shortest pendulum (a 1e-9 m rope had built and simulated)
        (lambda: crane.Crane(rope=1e-9), "rope = 1e-09"),
        (lambda: crane.Crane(rope=5.0, hook_mass=50.0, rigging=5e-7), "rigging = 5e-07"),
        (lambda: crane.Crane(rope=5.0).modes(rope=1e-7), "rope = 1e-07"),
        (lambda: crane.lqr(1e-8), "rope = 1e-08"),
        (lambda: crane.residual_grid([5.0, 1e-9], [0.1], [None], progress=False), r"ropes\[1\] = 1e-09"),
        (lambda: crane.Hoist([0.0, 1.0, 2.0], [5.0, 1e-9, 5.0]), r"length\[1\] = 1e-09"),
        (lambda: crane.rope_range(1e-9, 2.0), "rope_min = 1e-09"),
    ],
)
def test_a_rope_outside_a_pendulums_lengths_is_refused_naming_it(make, named: str) -> None:
    with pytest.raises(
        InvalidInputError, match=f"^invalid {named}: (a )?finite numbers? {re.escape(ALLOWED)}$"
    ):
        make()


def _overshoot(t: list[float], length: list[float]) -> tuple[float, float]:
    """(t [s], l [m]) of the spline's highest point, independently: SciPy's spline on a fine grid."""
    dense_t = np.linspace(t[0], t[-1], 2_000_001)
    dense = CubicSpline(t, length, bc_type="clamped")(dense_t)
    return float(dense_t[dense.argmax()]), float(dense.max())


def test_a_spline_overshooting_far_above_its_samples_is_refused() -> None:
    """Samples of ≤ 40 m, the rise from 10 to 40 m in 1 s between pieces of 1 and 26 s: the spline
    rose to 182 m at 10.7 s and was taken (a crane run then hoisted to 182 m)."""
    t, length = [0.0, 1.0, 2.0, 28.0], [10.0, 10.0, 40.0, 40.0]
    at, high = _overshoot(t, length)
    assert high == pytest.approx(182.316, abs=1e-3)
    with pytest.raises(InvalidInputError) as err:
        crane.Hoist(t, length)
    m = re.fullmatch(
        r"the Hoist spline through the lengths rises to (\S+) m at t = (\S+) s, between the samples "
        r"\(2 s, 40 m\) and \(28 s, 40 m\): (\S+) m above the largest sample \(40 m\), more than the "
        r"samples' spread \(30 m\): a spline overshoots so far between samples much closer in time than "
        r"their neighbours; give more samples there or a gentler change",
        str(err.value),
    )
    assert m is not None, str(err.value)
    assert float(m[1]) == pytest.approx(high, abs=1e-3) and float(m[2]) == pytest.approx(at, abs=1e-4)
    assert float(m[3]) == pytest.approx(high - 40.0, abs=1e-3)
    crane.Hoist([0.0, 10.0, 20.0, 30.0], [10.0, 10.0, 40.0, 40.0])  # even times: 2.7 m above, taken


def test_a_spline_rising_above_the_cap_between_samples_below_it_is_refused() -> None:
    """Every sample ≤ 1e4 m, the overshoot (a ninth of the spread at even times) above 1e4 m."""
    t, length = [0.0, 10.0, 20.0, 30.0], [1000.0, 1000.0, 9990.0, 9990.0]
    at, high = _overshoot(t, length)
    assert high > 1e4
    with pytest.raises(InvalidInputError) as err:
        crane.Hoist(t, length)
    text = str(err.value)
    assert text.startswith(f"the Hoist spline through the lengths rises to {high:.6g} m at t = "), text
    assert f"t = {at:.6g}" in text and "between the samples (20 s, 9990 m) and (30 s, 9990 m)" in text
    assert "the rope length must stay <= 1e4 m (the longest pendulum, pl.limits() length)" in text


def test_a_spline_dipping_below_the_shortest_rope_is_refused() -> None:
    """Samples ≥ 1e-6 m whose spline's undershoot (a ninth of the spread at even times) ends below
    1e-6 m, though above 0."""
    t, length = [0.0, 1.0, 2.0, 3.0], [1e-5, 1e-5, 1.1e-6, 1.1e-6]
    dense = CubicSpline(t, length, bc_type="clamped")(np.linspace(0.0, 3.0, 300_001))
    assert 0 < dense.min() < SHORTEST
    with pytest.raises(
        InvalidInputError, match=r"the rope length must stay >= 1e-6 m \(the shortest pendulum"
    ):
        crane.Hoist(t, length)


def test_a_crane_file_names_the_key_or_the_file() -> None:
    with pytest.raises(InvalidInputError, match=r"^r\.toml: crane\.rope = 20000\.0: must be <= 10000"):
        parse({"crane": {"rope": 2e4}, "simulation": {"t_end": 5.0}}, "r.toml")
    hoist = {"t": [0.0, 1.0], "length": [5.0, 2e4]}
    with pytest.raises(InvalidInputError, match=r"^h\.toml: hoist\.length\[1\] = 20000\.0: must be <= 10000"):
        parse({"crane": {"rope": 5.0}, "hoist": hoist, "simulation": {"t_end": 5.0}}, "h.toml")
    for key in ("rope", "rigging"):
        extra = {"hook_mass": 50.0} if key == "rigging" else {}
        data = {"crane": {"rope": 5.0, key: 1e-9, **extra}, "simulation": {"t_end": 5.0}}
        with pytest.raises(InvalidInputError, match=rf"^r\.toml: crane\.{key} = 1e-09: must be >= 1e-6; "):
            parse(data, "r.toml")
    tiny = {"t": [0.0, 1.0], "length": [5.0, 1e-9]}
    with pytest.raises(InvalidInputError, match=r"^h\.toml: hoist\.length\[1\] = 1e-09: must be >= 1e-6"):
        parse({"crane": {"rope": 5.0}, "hoist": tiny, "simulation": {"t_end": 5.0}}, "h.toml")
    hoist = {"t": [0.0, 1.0, 2.0, 28.0], "length": [10.0, 10.0, 40.0, 40.0]}
    with pytest.raises(pl.ScenarioError, match=r"^s: the Hoist spline .* rises to 182\.316 m"):
        pl.Scenario.from_dict({"crane": {"rope": 10.0}, "hoist": hoist, "simulation": {"t_end": 5.0}}, "s")


def test_a_scenario_files_error_shows_five_problems_and_keeps_all() -> None:
    """A file with [crane] read by pl.load_scenario listed all its problems (a crane file's own loader
    showed five); now both show five and how many more, a pendulum's file too."""
    bad = {
        "crane": {"rope": 2e4, "payload_mass": -1.0, "damping": -1.0, "g": "x", "ropes": 1.0},
        "simulation": {"t_end": -5.0, "rtol": "z"},
    }
    with pytest.raises(pl.ScenarioError) as err:
        pl.Scenario.from_dict(bad, "c.toml")
    e = err.value
    assert len(e.problems) == 7 and e.problems[0].startswith("unknown key crane.ropes = 1.0")
    assert any(p.startswith("crane.rope = 20000.0: must be <= 10000") for p in e.problems), e.problems
    shown = " ".join(f"({k}) {p}" for k, p in enumerate(e.problems[:5], 1))
    assert str(e) == f"c.toml: 7 problems: {shown} (and 2 more)", str(e)
    pendulum = {"pendulum": {"length": -1.0, "mass": -1.0, "g": "x", "colour": 1, "size": 2, "shape": 3}}
    five = r"^p\.toml: (\d+) problems: \(1\) .*\(5\) .* \(and \d+ more\)$"
    with pytest.raises(pl.ScenarioError, match=five) as err:
        pl.Scenario.from_dict(pendulum, "p.toml")
    assert len(err.value.problems) > 5 and "(6)" not in str(err.value)
