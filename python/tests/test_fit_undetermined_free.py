"""No error bar is computed with a parameter the data do not determine held at its fitted value
(docs/fit.md, "Honest at cut directions"): identify.py gives the determined ones the covariance with
the undetermined ones free, and a profile's end is never closed by a refit that did not converge
(fitting/profile.py). The data of the fit come from the independent SciPy integrator
(testdata/generate/independent_pendulum.py, via bench/fit_validate_data.py). Units SI."""

from __future__ import annotations

import math
import sys
import warnings
from pathlib import Path

sys.path.append(str(Path(__file__).resolve().parents[2] / "bench"))  # last: bench/ has animate.py, compare.py
import fit_validate_data as fvd
import independent_pendulum as ip
import numpy as np
import pytest

import pendulab as pl
from pendulab.fitting import profile
from pendulab.fitting.identify import analyse
from pendulab.server.fit_words import REASONS, keyed


def test_a_determined_bar_is_computed_with_the_undetermined_free() -> None:
    """Angles see g and l only through g/l: their columns (per unit of ln l, ln g) are opposite, and
    both are not determined. θ̇₀'s column shares a part with theirs: its variance is 1/(cᵀ(I − P)c),
    P the projection on their span, not 1/(cᵀc) with them held (which it was: narrower)."""
    rng = np.random.default_rng(0)
    a, b = rng.standard_normal(400), rng.standard_normal(400)
    c = 0.7 * a + b
    names = ["length", "g", "theta_dot0"]
    ident = analyse(names, {"length": 1.0, "g": 1.0, "theta_dot0": 0.1}, np.column_stack([a, -a, c]), 1.0,
                    {"length", "g"})  # fmt: skip
    assert ident.determined == {"length": False, "g": False, "theta_dot0": True}
    free = 1.0 / (c @ c - (c @ a) ** 2 / (a @ a))
    assert ident.covariance[2, 2] == pytest.approx(free, rel=1e-9)
    assert ident.covariance[2, 2] > 1.3 * (1.0 / (c @ c))


def test_a_column_that_only_the_undetermined_explain_is_not_determined_either() -> None:
    """length and g trade off exactly along a + (−a + εb) − εb = 0, where pivot_z (column b) has a
    share of only ε/√2 < 1 %: the cut does not name it, and with length and g held it kept the bar
    1/|b|. Their columns span b, though: with them free nothing of it is left, so it is not
    determined either, with the keyed reason naming them."""
    rng = np.random.default_rng(1)
    a, b, d = rng.standard_normal(300), rng.standard_normal(300), rng.standard_normal(300)
    jac = np.column_stack([a, -a + 1e-3 * b, b, d])
    names = ["length", "g", "pivot_z", "theta0"]
    ident = analyse(names, dict.fromkeys(names, 1.0), jac, 1.0, {"length", "g"})
    assert ident.determined == {"length": False, "g": False, "pivot_z": False, "theta0": True}
    assert keyed(ident.reasons["pivot_z"], REASONS) == {
        "key": "combination",
        "values": {"others": "length, g"},
        "text": "the data determine only a combination of it with length, g",
    }


def _angles(seed: int, fit: list[str]) -> pl.FitResult:
    """bench/fit_validate.py case 5's data (θ, φ at 20 Hz for 20 s, σ 2 mrad, l = 1 m), fitted."""
    data = fvd.angles(ip.Truth(length=1.0))(np.random.default_rng([4, seed + 1]), 1.0)
    length = 1.3 if "length" in fit else 1.0
    return pl.fit(pendulum=pl.Pendulum(length=length, g=9.81), fit=fit, time_limit=60.0, **data.kw)


def test_length_and_g_from_angles_leave_the_starts_bars_as_wide_as_with_the_length_known() -> None:
    """With length and g both fitted to angles, g/length is determined and they are not; the start's
    bars were computed with both held, so with g/length held: θ̇₀ ± 0.00062 rad/s for seed 12, 2.3
    bars off (34 of 40 seeds within 2 bars); with them free they equal those of a fit with the length
    known (± 0.00089, 1.6 bars off; 39 of 40)."""
    both, known = _angles(12, ["length", "g"]), _angles(12, ["g"])
    assert not both.determined["length"] and not both.determined["g"] and "g/length" in both.combinations
    for name in ("theta0", "phi0", "theta_dot0", "phi_dot0"):
        assert both.stderr[name] == pytest.approx(known.stderr[name], rel=0.02), name
    assert abs(both.params["theta_dot0"] - 0.1) < 2.0 * both.stderr["theta_dot0"]


class _Fake:
    """A profile whose rise is c² (its 95 % end at 1.96) where its refit converges; between 0.5 and 1.5
    the refit stops early, 10 above the profile (as a refit at its model runs is)."""

    name = "x"

    def __init__(self, stuck: tuple[float, float]) -> None:
        self.stuck = stuck

    def __call__(self, c: float, start: dict[str, float]) -> tuple[float, dict[str, float], bool]:
        if self.stuck[0] <= abs(c) <= self.stuck[1]:
            return c * c + 10.0, {"x": c}, False
        return c * c, {"x": c}, True


def test_a_refit_that_did_not_converge_does_not_close_a_profiles_end() -> None:
    """Before, the end closed at the first stuck refit (0.5 … 1: 0.75); now the steps go on to a
    converged one, and an end no converged refit closes is open and not settled; a stuck refit inside
    the bracket ends the bisection at the bracket's outer end, checked."""
    values = {"x": 0.0}
    end, settled = profile.profile_end(_Fake((0.5, 1.5)), values, 0.5, (-9.0, 9.0), 1.0, 20, 3.84)
    assert settled and 1.96 <= end <= 2.0 + 1e-9
    end, settled = profile.profile_end(_Fake((0.5, 99.0)), values, 0.5, (-9.0, 9.0), -1.0, 20, 3.84)
    assert (end, settled) == (-math.inf, False)
    # stuck inside the bracket: the bisection ends at its converged outer end (wider, never narrower)
    end, settled = profile.profile_end(_Fake((1.9, 1.95)), values, 0.5, (-9.0, 9.0), 1.0, 20, 3.84)
    assert settled and 1.96 <= end <= 3.5


class _FarOff:
    """A profile whose rise is c² (its 95 % end at 1.96); a refit at 1 ≤ c ≤ 1.9 from values more
    than 0.6 away fails, 1e5 above the profile, though SciPy says it converged (case 20, seed 0: the
    length at 3.55 m refitted from 1.66 m stopped at its xtol after 3 model runs, g = −1.5 m/s²)."""

    name = "x"

    def __call__(self, c: float, start: dict[str, float]) -> tuple[float, dict[str, float], bool]:
        if 1.0 <= c <= 1.9 and abs(c - start["x"]) > 0.6:
            return 1e5, {"x": c}, True
        return c * c, {"x": c}, True


def test_a_refit_that_failed_far_off_is_checked_from_nearby() -> None:
    """The first step past the level (1.5, refitted from 0.5) is a failed refit: before, the end closed
    at 1.5 (the bisection only moved towards it); the check refits it from the nearest inside values,
    finds 2.25 < 3.84, and the steps go on to the true end 1.96."""
    end, settled = profile.profile_end(_FarOff(), {"x": 0.0}, 0.5, (-9.0, 9.0), 1.0, 30, 3.84, None, 10)
    assert settled and end == pytest.approx(1.96, abs=0.01)


def test_the_profile_says_when_a_refit_did_not_converge(monkeypatch: pytest.MonkeyPatch) -> None:
    """res.profile with refits cut to 3 model runs: an end they cannot close is ±inf, with a warning;
    no end is narrower than with refits that converge."""
    p = pl.Pendulum(length=1.0, g=9.81)
    t = np.linspace(0.0, 3.0 * 2.0 * np.pi / np.sqrt(9.81), 200)
    x, _ = pl.exact(p, p.state_from_angles(0.3)).state(t)
    angle = np.arctan2(x[:, 0], -x[:, 2]) + 0.01 * np.random.default_rng(0).standard_normal(len(t))
    res = pl.fit(t, planar_angle=angle, fit=["g"])
    lo, hi = res.profile("theta0")
    assert lo < res.params["theta0"] < hi and math.isfinite(lo) and math.isfinite(hi)
    monkeypatch.setattr(profile, "REFIT_EVALUATIONS", 3)
    monkeypatch.setattr(profile, "REFIT_ROUNDS", 1)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ends = res.profile("theta0")
    said = [str(w.message) for w in caught if "did not converge" in str(w.message)]
    assert said and not all(map(math.isfinite, ends)), (ends, said)
    assert ends[0] <= lo and ends[1] >= hi
