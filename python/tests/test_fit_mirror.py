"""A swing near its plane filmed from the side (positions x, z; bench/fit_validate.py case 27: case 1's
video released in the x–z plane, fitted as a spherical pendulum, data from the independent SciPy
integrator): x and z are blind to the mirror y → −y, the misfit is even about the plane and quartic
near it, so the curvature's bars of φ₀ and φ̇₀ were too narrow (φ₀ = 0.136 ± 0.031 rad for 0 in a
40-seed run). Their bars now come from the profile likelihood (fitting/mirror.py), the plane inside
where the data cannot exclude it, said in words the page keys; an ellipse (case 28, φ̇₀ clearly
nonzero) keeps its curvature bars. Units SI."""

from __future__ import annotations

import math
import re
import sys
import time
import warnings
from pathlib import Path
from typing import Any

sys.path.append(str(Path(__file__).resolve().parents[2] / "bench"))  # last: bench/ has animate.py, compare.py
import fit_validate as fv
import numpy as np
import pytest
from fit_validate_cases import DAMPED, VIDEO, VIDEO_FIT, cases
from fit_validate_data import video

import pendulab as pl
from pendulab.fitting import inference, mirror, profile, short_record
from pendulab.fitting.problem import Problem
from pendulab.server.fit_words import REASONS, keyed

PLANAR = 26  # the index of "video x,z, a planar swing fitted as a spherical one" in fit_validate_cases
ELLIPSE = 27  # "video x,z, ellipse, the start's truth"

#: The fit's time limit falls this long after the mirror check's first refit began [s].
LEFT = 0.02


def test_a_planar_swing_seen_from_the_side_has_honest_sideways_bars() -> None:
    """Seed 15: φ₀ = −0.111 ± 0.037 rad and φ̇₀ = 0.495 ± 0.134 rad/s by the curvature (truth 0 and 0:
    3.0 and 3.7 bars off); their profiles are −0.216 … 0.216 rad and −0.706 … 0.706 rad/s, the plane
    inside, the bars the larger side over 1.96 (± 0.167, ± 0.613), and the finding says the data are
    consistent with a planar swing."""
    r = fv.trial(PLANAR, 15, 60.0)
    assert r["status"] == "ok", r
    for name in ("phi0", "phi_dot0"):
        assert r["determined"][name] and r["off_in_stderr"][name] <= 2.0, (name, r["params"], r["stderr"])
    said = next(w for w in r["warnings"] if w.startswith("the data are consistent with a planar"))
    note = keyed(said)
    assert note["key"] == "mirrorPlanar", said
    assert float(note["values"]["rise"]) < mirror.PLANAR_RISE and note["values"]["level"] == "5.99"
    assert "phi0 -0.2162 … 0.2162 rad" in said and "Fit planar=True" in said


def test_an_ellipse_seen_from_the_side_keeps_its_curvature_bars() -> None:
    """φ̇₀ ≈ 0.8 rad/s is many bars from the plane: no profile, no finding, the truth within 2 bars."""
    r = fv.trial(ELLIPSE, 0, 60.0)
    assert r["status"] == "ok", r
    assert not any("planar" in w or "sideways" in w for w in r["model_warnings"]), r["model_warnings"]
    for name in ("phi0", "phi_dot0"):
        assert r["off_in_stderr"][name] <= 2.0, (name, r["params"][name], r["stderr"][name])


def test_the_reasons_of_the_sideways_motion_are_keyed() -> None:
    assert keyed(mirror.OPEN, REASONS)["key"] == "mirrorOpen"
    assert keyed(mirror.UNCHECKED, REASONS)["key"] == "mirrorUnchecked"
    text = (
        "seen from the side near its plane, the sideways motion shows only at second order: the error "
        "bars of phi0 were taken from their 95 % profile-likelihood intervals (phi0 0.01 … 0.2; ...)"
    )
    assert (keyed(text)["key"], keyed(text)["values"]) == ("mirrorWidened", {"others": "phi0"})


def _planar_fit(monkeypatch: pytest.MonkeyPatch, pressed: bool) -> tuple[Any, list[str], float | None]:
    """Case 27, seed 15 (the mirror check profiles φ₀ and φ̇₀) fitted with the fit's time limit set to
    fall LEFT s after the check's first refit began, or (``pressed``) Ctrl-C in that refit's first model
    run; the result and the warnings."""
    polished, rise, safe = inference._polished, profile.Rise.__call__, Problem.safe_residuals
    searches: list[Any] = []
    began: list[float] = []

    def keep(search: Any, *args: Any) -> Any:
        searches.append(search)
        return polished(search, *args)

    def first(rise_self: Any, c: float, start: dict[str, float]) -> Any:
        if not began:
            began.append(time.perf_counter())
            if not pressed:
                searches[-1].clock.time_limit = began[0] + LEFT - searches[-1].began
        return rise(rise_self, c, start)

    def run(problem: Any, *args: Any, **kwargs: Any) -> Any:
        if pressed and began:
            raise KeyboardInterrupt
        return safe(problem, *args, **kwargs)

    monkeypatch.setattr(inference, "_polished", keep)
    monkeypatch.setattr(profile.Rise, "__call__", first)
    monkeypatch.setattr(Problem, "safe_residuals", run)
    case = cases()[PLANAR]
    data = case.make(np.random.default_rng([PLANAR, 16]), 1.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            res = pl.fit(pendulum=pl.Pendulum(**case.pendulum), fit=case.fit, loss=case.loss, **data.kw)
        except KeyboardInterrupt:
            pytest.fail("Ctrl-C in the mirror check's profile left pl.fit as KeyboardInterrupt")
    assert began, "the mirror check did not profile"
    return res, [str(w.message) for w in caught], searches[-1].time_limit


@pytest.mark.parametrize(("pressed", "stop"), [(False, "timeLimit"), (True, "ctrlC")])
def test_the_time_limit_or_ctrl_c_in_the_mirror_check_leaves_the_sideways_motion_not_determined(
    monkeypatch: pytest.MonkeyPatch, pressed: bool, stop: str
) -> None:
    """The mirror check's refits stopped by the time limit left φ₀ and φ̇₀ not determined with a reason
    that said neither why nor what to do, and no warning; Ctrl-C in them raised KeyboardInterrupt out
    of pl.fit and lost the fit. Now both end as a short record's profiles do (short_record.TimedRise,
    why_unchecked): the fit is returned, φ₀ and φ̇₀ not determined, the reason and a warning naming the
    time limit and how to raise it (or Ctrl-C), keyed for the page with the short record's clauses."""
    res, said, limit = _planar_fit(monkeypatch, pressed)
    values = {} if pressed else {"seconds": f"{limit:g}"}
    why = short_record.STOPS[stop].format(**values)
    clause = {"key": "stop" + stop[0].upper() + stop[1:], "values": values}
    assert all(math.isfinite(v) for v in res.params.values()), res.params  # the search's optimum kept
    assert res.interrupted  # stopped short in the error analysis (FitResult.interrupted)
    for name in mirror.SIDEWAYS:
        assert not res.determined[name] and res.stderr[name] == math.inf, (name, res.stderr)
        reason = keyed(res.reasons[name], REASONS)
        assert why in res.reasons[name] and reason["key"] == "mirrorUnchecked", res.reasons
        assert reason["clauses"] == [clause], reason
    note = next(w for w in said if w.startswith("seen from the side, phi0, phi_dot0 are not determined"))
    assert why in note and keyed(note)["key"] == "mirrorUndetermined" and keyed(note)["clauses"] == [clause]
    if not pressed:
        assert "give a larger limit (pl.fit's time_limit=, pendulab fit's --time-limit)" in note


def test_ctrl_c_before_the_mirror_check_names_ctrl_c(monkeypatch: pytest.MonkeyPatch) -> None:
    """Ctrl-C in the polish skips the mirror check (inference.py): φ₀ and φ̇₀ are not determined and
    their reason and the finding name Ctrl-C (check_mirror's ``ctrl_c``), not a vague "the fit
    stopped" as before."""

    def pressed(*args: Any, **kwargs: Any) -> Any:
        raise KeyboardInterrupt

    monkeypatch.setattr(inference, "polish", pressed)
    case = cases()[PLANAR]
    data = case.make(np.random.default_rng([PLANAR, 16]), 1.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(pendulum=pl.Pendulum(**case.pendulum), fit=case.fit, loss=case.loss, **data.kw)
    why = short_record.STOPS["ctrlC"]
    for name in mirror.SIDEWAYS:
        assert not res.determined[name] and why in res.reasons[name], res.reasons
    assert any(
        str(w.message).startswith("seen from the side, phi0") and why in str(w.message) for w in caught
    )


def test_a_swing_released_at_phi0_pi_is_checked_about_its_own_half_plane() -> None:
    """Case 27's swing released on the x < 0 side (θ = 0.5, φ = π; at the first sample θ₀ = 0.222,
    φ₀ = π): the plane is φ₀ ∈ {0, π} (mod 2π) and the fit lands near π (3.18 ± 0.30 rad, seed 0), so
    the profile is taken about π, not 0 (φ₀ 2.902 … 3.382 rad, symmetric about π), and the finding
    names the plane held, φ₀ = π (it said "phi0 = 0 or π"). The bench compares angles modulo 2π
    (fit_validate._difference): the start's truth is within 2 bars."""
    make = video(VIDEO, start=(0.5, math.pi, 0.0, 0.0), start_truth=True)
    data = make(np.random.default_rng([99, 0]), 1.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(pendulum=pl.Pendulum(**DAMPED), fit=VIDEO_FIT, **data.kw)
    said = next(str(w.message) for w in caught if "consistent with a planar" in str(w.message))
    note = keyed(said)
    assert note["key"] == "mirrorPlanar" and note["values"]["plane"] == "π", note
    lo, hi = (float(v) for v in re.search(r"phi0 (\S+) … (\S+) rad", said).groups())  # type: ignore[union-attr]
    assert lo < math.pi < hi and abs((lo + hi) / 2.0 - math.pi) < 1e-3, said
    truth = dict(data.truth)
    fv._same_start(truth, dict(res.params), res.mirror_blind)
    for name in ("theta0", "phi0", "theta_dot0", "phi_dot0"):
        off = abs(fv._difference(name, res.params[name], truth[name]))
        assert res.determined[name] and off <= 2.0 * res.stderr[name], (name, res.params, truth)


def test_the_bench_compares_angles_modulo_two_pi() -> None:
    """φ₀ = −3.1 and 3.1 rad are 0.083 rad apart (the bench took 6.2); a length is not wrapped; the
    start (θ, φ, θ̇, φ̇) = (−0.2, 0.1, −1, 0.3) is (0.2, 0.1 + π, 1, 0.3) written with θ₀ > 0."""
    assert fv._difference("phi0", -3.1, 3.1) == pytest.approx(2.0 * math.pi - 6.2)
    assert fv._difference("phi0", 3.1, -3.1) == pytest.approx(6.2 - 2.0 * math.pi)
    assert fv._difference("phi0", 7.0, 0.0) == pytest.approx(7.0 - 2.0 * math.pi)
    assert fv._difference("phi0", math.pi, -math.pi) == 0.0 and fv._difference("length", 7.0, 0.0) == 7.0
    truth = {"theta0": 0.2, "phi0": 0.1 + math.pi, "theta_dot0": 1.0, "phi_dot0": 0.3}
    fv._same_start(truth, {"theta0": -0.2, "phi0": 0.1, "phi_dot0": 0.3}, mirror_blind=True)
    assert truth["theta0"] == -0.2 and truth["theta_dot0"] == -1.0 and truth["phi_dot0"] == 0.3
    assert fv._difference("phi0", 0.1, truth["phi0"]) == pytest.approx(0.0, abs=1e-12)


def test_a_spring_swinging_in_its_plane_seen_from_the_side_is_mirror_checked() -> None:
    """The swinging spring (spring_model.py) is a central force plus gravity along −z: a motion and its
    mirror image y → −y ((φ₀, φ̇₀) → (−φ₀, −φ̇₀), r₀, ṙ₀, θ₀, θ̇₀ unchanged) are both solutions, so its
    x, z are mirror-blind as a rod's are. It was not mirror-checked (mirror.py returned for the
    spring): 3.5 s of a spring released in the x–z plane (seed 2) gave φ₀ = −0.108 ± 0.029 rad and
    φ̇₀ = 0.503 ± 0.156 rad/s for 0 and 0, 3.7 and 3.2 bars off, with no word. Now it is checked as a
    rod's (the period from the hanging length l₀ + m g/k): ± 0.133 and ± 0.654 from the profile, the
    truth within a bar, and the planar finding is said."""
    spring = pl.SwingingSpring(60.0, 0.75, 9.81, 1.0)  # k/m 60 1/s², hanging 0.91 m: ω_r/ω_swing 2.4
    rate, every = 25.0, 50
    tr = pl.simulate_spring(
        spring, [0.3, 0.0, -0.85], [0.0, 0.0, 0.0], 3.5, dt=1 / rate / every, save_every=every, order=4
    )
    xz = tr.x[:, [0, 2]] + 1.5e-3 * np.random.default_rng(2).standard_normal((len(tr.t), 2))
    guess = pl.SwingingSpring(50.0, 0.8, 9.81, 1.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(tr.t, positions=xz, pendulum=guess, fit="stiffness,length,g")
    said = [str(w.message) for w in caught]
    assert res.model == "spring" and res.mirror_blind and res.converged, (res.message, said)
    planar = next(w for w in said if w.startswith("the data are consistent with a planar swing"))
    assert keyed(planar)["key"] == "mirrorPlanar" and keyed(planar)["values"]["plane"] == "0", planar
    for name in mirror.SIDEWAYS:  # the truth (the plane) within 2 of the profile's bars
        assert res.determined[name], res.reasons
        off = abs(res.params[name] - mirror.plane_of(name, res.params[name]))
        assert off <= 2.0 * res.stderr[name], (name, res.params[name], res.stderr[name])
