"""The hoist's rope length l(t) (pendulab.crane.Hoist, docs/cranes.md "The crane model"): the true least
and largest length of its spline, which may lie between its samples (the shown range came from the
samples), and a spline dipping to ≤ 0 m between samples refused up front naming the time and the length
(a uniform grid of 64 points a sample missed a dip between close samples)."""

from __future__ import annotations

import re

import numpy as np
import pytest

from pendulab import InvalidInputError, crane

OVERSHOOT = crane.Hoist([0.0, 10.0, 20.0, 30.0], [10.0, 10.0, 5.0, 5.0])
"""By hand: equal pieces h = 10 s, clamped ends, so the interior slopes solve m₀ + 4m₁ + m₂ =
3(l₂ − l₀)/h, m₁ + 4m₂ + m₃ = 3(l₃ − l₁)/h with m₀ = m₃ = 0: m₁ = m₂ = −0.3 m/s. On [0, 10] s the
Hermite cubic is l = 10 + 3(u² − u³), u = t/10, largest at u = 2/3: 10 + 4/9 m at t = 20/3 s; by the
symmetry, least on [20, 30] s: 5 − 4/9 m at t = 70/3 s."""


def test_the_range_is_the_splines_true_extremes_not_the_samples() -> None:
    (t_lo, lo), (t_hi, hi) = OVERSHOOT.extremes()
    assert lo == pytest.approx(5.0 - 4.0 / 9.0, rel=1e-14) and t_lo == pytest.approx(70.0 / 3.0, rel=1e-12)
    assert hi == pytest.approx(10.0 + 4.0 / 9.0, rel=1e-14) and t_hi == pytest.approx(20.0 / 3.0, rel=1e-12)
    assert OVERSHOOT.length_range() == (lo, hi)
    dense = OVERSHOOT.length(np.linspace(0.0, 30.0, 300_001))  # the extremes bound every value
    assert lo <= dense.min() <= lo + 1e-9 and hi - 1e-9 <= dense.max() <= hi


def test_a_range_over_part_of_the_span_and_beyond_it() -> None:
    """Within [12, 18] s the spline falls monotonically (its ends); before and after the samples the
    length is held at the first and last sample."""
    lo, hi = OVERSHOOT.length_range(12.0, 18.0)
    assert (lo, hi) == (float(OVERSHOOT.length(18.0)[0]), float(OVERSHOOT.length(12.0)[0]))
    assert OVERSHOOT.length_range(-50.0, 2.0) == (10.0, float(OVERSHOOT.length(2.0)[0]))
    assert OVERSHOOT.length_range(40.0, 50.0) == (5.0, 5.0)
    assert OVERSHOOT.length_range(-5.0, 100.0) == OVERSHOOT.length_range()
    with pytest.raises(InvalidInputError, match=r"t_end = 1\.0 s is before t_start = 2\.0 s"):
        OVERSHOOT.length_range(2.0, 1.0)
    with pytest.raises(InvalidInputError, match="invalid t_start = nan"):
        OVERSHOOT.length_range(float("nan"))


def test_a_constant_rope_has_one_length() -> None:
    """A piece where l̇ ≡ 0 has no isolated roots (SciPy reports NaN for it): the samples' value."""
    assert crane.Hoist([0.0, 1.0], [8.0, 8.0]).length_range() == (8.0, 8.0)
    assert repr(crane.Crane(rope=8.0)).startswith("Crane(rope=8 m,")


@pytest.mark.parametrize(
    ("t", "length", "low", "at", "between"),
    [
        # l = 0.2 m at 2 s and 3 s, still falling at 2 s: least at t = 7/3 s
        ([0.0, 1.0, 2.0, 3.0], [5.0, 5.0, 0.2, 0.2], -0.226667, 7.0 / 3.0, "(2 s, 0.2 m) and (3 s, 0.2 m)"),
        # close samples: the old check (64 points a sample over the span, one every 3 s) saw 0.059 m
        ([0.0, 100.0, 100.5, 101.0, 200.0], [5.0, 5.0, 0.2, 0.2, 0.2], -0.262782, 100.7111,
         "(100.5 s, 0.2 m) and (101 s, 0.2 m)"),
    ],
)  # fmt: skip
def test_a_spline_dipping_to_zero_between_samples_is_refused_naming_time_and_length(
    t: list[float], length: list[float], low: float, at: float, between: str
) -> None:
    with pytest.raises(InvalidInputError) as err:
        crane.Hoist(t, length)
    text = str(err.value)
    m = re.fullmatch(
        r"the Hoist spline through the lengths dips to (\S+) m at t = (\S+) s, between the samples "
        + re.escape(between)
        + r": the rope length must stay >= 1e-6 m \(the shortest pendulum, pl\.limits\(\) length\); "
        r"give more samples there or a gentler change",
        text,
    )
    assert m is not None, text
    assert float(m[1]) == pytest.approx(low, abs=1e-6) and float(m[2]) == pytest.approx(at, abs=1e-4)
    dense_t = np.linspace(t[0], t[-1], 2_000_001)  # an independent look: SciPy's spline on a fine grid
    from scipy.interpolate import CubicSpline

    dense = CubicSpline(t, length, bc_type="clamped")(dense_t)
    assert dense.min() == pytest.approx(low, abs=1e-6) and dense_t[dense.argmin()] == pytest.approx(
        at, abs=1e-4
    )


def test_a_hoisted_crane_file_with_a_dipping_hoist_names_the_file() -> None:
    from pendulab.crane.scenario import parse

    data = {
        "crane": {"rope": 5.0},
        "hoist": {"t": [0.0, 1.0, 2.0, 3.0], "length": [5.0, 5.0, 0.2, 0.2]},
        "simulation": {"t_end": 5.0},
    }
    with pytest.raises(
        InvalidInputError, match=r"^h\.toml: the Hoist spline .* dips to -0\.226667 m at t = 2\.333333333 s"
    ):
        parse(data, "h.toml")
