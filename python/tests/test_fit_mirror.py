"""A swing near its plane filmed from the side (positions x, z; bench/fit_validate.py case 27: case 1's
video released in the x–z plane, fitted as a spherical pendulum, data from the independent SciPy
integrator): x and z are blind to the mirror y → −y, the misfit is even about the plane and quartic
near it, so the curvature's bars of φ₀ and φ̇₀ were too narrow (φ₀ = 0.136 ± 0.031 rad for 0 in a
40-seed run). Their bars now come from the profile likelihood (fitting/mirror.py), the plane inside
where the data cannot exclude it, said in words the page keys; an ellipse (case 28, φ̇₀ clearly
nonzero) keeps its curvature bars. Units SI."""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.append(str(Path(__file__).resolve().parents[2] / "bench"))  # last: bench/ has animate.py, compare.py
import fit_validate as fv

from pendulab.fitting import mirror
from pendulab.server.fit_words import REASONS, keyed

PLANAR = 26  # the index of "video x,z, a planar swing fitted as a spherical one" in fit_validate_cases
ELLIPSE = 27  # "video x,z, ellipse, the start's truth"


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
