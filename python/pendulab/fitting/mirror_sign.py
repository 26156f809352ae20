"""Whether the mirror y → −y is a symmetry of the fitted model, and the sign of the sideways motion
where it is not (docs/fit.md, "A swing near its plane, seen from the side").

Data seen as (x, z) — and a phone's frame-free scalars — are the same for a motion x(t) and its
mirror image S x(t), S = diag(1, −1, 1) (φ ↦ −φ). Whether that image is again a motion of the model
is a property of its equations:

- the ideal pendulum and the swinging spring: gravity g⃗ ∥ e_z and the constraint |x| = l (the spring's
  central force) commute with S: the image is a motion, (φ₀, φ̇₀) ↦ (−φ₀, −φ̇₀), all else unchanged;
- damping −c v, drag −c_q |v| v and dry friction against the relative motion are equivariant
  (S v ↦ S v): symmetric; a gravity direction d or a forcing direction e with a y component is
  mapped to (d_x, −d_y, d_z), a different model, unless that component is 0;
- the rotating frame (Foucault): ẍ = g⃗ − 2 Ω × ẋ − Ω × (Ω × x). Since S(a × b) = −(S a) × (S b)
  (S is a reflection, det S = −1), S x solves the equations with Ω' = −S Ω = (−Ω_x, Ω_y, −Ω_z):
  Ω = |Ω|(0, cos λ, sin λ) goes to |Ω|(0, cos λ, −sin λ), latitude −λ. The mirror reverses the
  sense of the rotation about the vertical, so the image is a motion only where Ω_z = |Ω| sin λ = 0
  (the equator, or no rotation);
- a moving pivot P(t): S x solves the equations with the pivot S P(t); the slewing crane's
  (R cos ωt, R sin ωt, h) goes to (R cos ωt, −R sin ωt, h), the boom turning at −ω: symmetric only
  for R ω = 0. The vibrating pivot (0, 0, A cos νt) moves along z: symmetric. A fixed pivot's y does
  not enter x, z;
- a pinhole camera (``perspective`` κ, looking along +y) sees x/(1 + κ y): its image is that of −κ.

A parameter the mirror negates (latitude, the slewing rate, d_y, e_y, κ) that is fitted keeps the
symmetry, the mirror mapping it too: the misfit stays even about the plane φ₀ = φ̇₀ = 0 in its profile
over the others, and mirror.py checks the sideways motion's bars. One held at a value that breaks the
symmetry (:func:`broken_by` names it) makes the model not mirror-symmetric: such data are not
mirror-blind (``FitResult.mirror_blind`` False), mirror.py's check (which assumes an even misfit) is
not made, and the data tell the motion from its image only through that term. How well they do is
checked (:func:`check_sign`): the fit's mirror image refitted (one of φ₀, φ̇₀ held at its image,
the others free, from the image of the fit) rises by r in units of the noise; where r is below the
95 % level of one parameter (3.84) and below half the rise D² its linearised bars predict (D: the
Wald distance of the image from the fit; a misfit near-even about the plane, as for the Earth's
slow rotation, is quartic there and far flatter than the curvature says), the image fits as well and
the sign of the sideways motion is not determined: φ₀, φ̇₀ are marked not determined, with the
reason, and the finding says why and what helps. The refit holds one of φ₀, φ̇₀ (the one farther
from the plane in bars): an upper bound of the image's valley floor, so it is then released (all
free, from there) and, where it stays on the image's side, its lower rise decides; where it slides
back to the fit the valley is the fit's own and the held rise stands (an intermediate rotation,
Ω_z = 0.023 and 0.078 rad/s, SciPy's integration: 34 of 34 seeds slid back, no decision changed).
Otherwise (a fast enough rotation: the term shows at first order) the curvature's bars stand: at
those rates, released at rest in the plane, 15 s of x, z, sigma not given, φ₀ was within 1 and 2
bars of the truth in 21 and 33 of 34 fits that told the sign, φ̇₀ in 18 and 34; their 95 % profile
likelihood intervals were no wider than the curvature's in all 34 (python/tests/test_fit_mirror_sign.py).
What was found is ``FitResult.mirror_sign`` (:class:`SignCheck`), a line of the report. A check the
time limit, Ctrl-C, a robust loss or an unconverged fit leaves undone marks them not determined with
its reason.
Units: φ₀ [rad], φ̇₀ [rad/s]; times [s].
"""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from .mirror import (
    SIDEWAYS,
    _distance,
    _exact,
    plane_of,
)
from .search import Search
from .short_record import Late, TimedRise, hanging_length, mark_not_determined, why_unchecked

SIGN = "seen from the side, only {told} tells the motion from its mirror image y → −y"
"""The start of the reason (and of the finding) where the image fits as well (server/fit_words.py)."""

SIGN_UNCHECKED = "the refit of the motion's mirror image y → −y was not finished"
"""Why φ₀, φ̇₀ are not determined when the image's refit was not done (server/fit_words.py)."""


@dataclass(frozen=True)
class SignCheck:
    """What :func:`check_sign` found (``FitResult.mirror_sign``): ``told`` True where the data tell the
    motion from its mirror image y → −y (the image's refit rose by ``rise`` ≥ ``threshold``), False where
    the image fits as well, None where the refit was not finished (``why``); ``by``: the term that tells
    them apart (:data:`CAUSES`' words); ``rise``: the misfit's rise of the image's refit in units of the
    noise (NaN when not finished); ``level``: the χ²(1) 95 % quantile (3.84); ``threshold``: the rise
    below which the image fits as well (the smaller of ``level`` and half its Wald distance squared)."""

    told: bool | None
    by: str
    rise: float
    level: float
    threshold: float
    why: str = ""

    def short(self) -> str:
        """The notebook table's cell: told / not told by the data, with the image's rise."""
        if self.told is None:
            return "not checked (the mirror image's refit was not finished)"
        rise = f"the mirror image's misfit +{max(self.rise, 0.0):.3g}, threshold {self.threshold:.3g}"
        return f"{'told' if self.told else 'not told'} by the data ({rise})"

    def line(self) -> str:
        """The report's sentence (fitting/report.py; server/fit_words.py keys it)."""
        if self.told is None:
            return (
                f"the sign of the sideways motion (phi0, phi_dot0) was not checked: {SIGN_UNCHECKED} "
                f"({self.why}); only {self.by} tells the motion from its mirror image"
            )
        if self.told:
            return (
                f"the data tell the sign of the sideways motion (phi0, phi_dot0) through {self.by}: the "
                f"motion's mirror image y -> -y refitted has a misfit higher by {self.rise:.3g} "
                f"(threshold {self.threshold:.3g}, 95 % level {self.level:.3g})"
            )
        return (
            f"the data do not tell the sign of the sideways motion (phi0, phi_dot0): only {self.by} "
            f"could, and the motion's mirror image y -> -y fits as well (misfit higher by only "
            f"{max(self.rise, 0.0):.2g}; 95 % level {self.level:.3g})"
        )


#: What each held term that breaks the symmetry is called in the reason.
CAUSES = {
    "rotation": "the frame's rotation about the vertical (frame_rate·sin(latitude))",
    "slewing": "the pivot's motion along y (the slewing boom)",
    "gravity": "gravity's y component (gravity_y)",
    "forcing": "the forcing's y component (forcing_y)",
    "perspective": "the camera's perspective",
}


def broken_by(model: str, values: Mapping[str, Any], free: Collection[str]) -> str:
    """The terms (:data:`CAUSES`' words, joined by "and") that, held at their ``values``, break the
    mirror y → −y of ``model`` (module doc; ``free``: the fitted names, which keep it); "" where it is
    a symmetry."""

    def held(name: str) -> float:
        return 0.0 if name in free else float(values.get(name, 0.0))

    def moves(name: str) -> bool:
        return name in free or float(values.get(name, 0.0)) != 0.0

    causes = []
    latitude = float(values.get("latitude", 0.0))
    if model == "rotating" and "latitude" not in free and math.sin(latitude) != 0.0 and moves("frame_rate"):
        causes.append("rotation")
    if model == "slewing" and held("rate") != 0.0 and moves("radius"):
        causes.append("slewing")
    if model == "damped":
        if held("gravity_y") != 0.0:
            causes.append("gravity")
        if held("forcing_y") != 0.0 and moves("forcing_amplitude"):
            causes.append("forcing")
    if held("perspective") != 0.0:
        causes.append("perspective")
    return " and ".join(CAUSES[c] for c in causes)


def check_sign(res: Any, clock: Search, told: str, checkable: bool = True, ctrl_c: bool = False) -> list[str]:
    """For data blind to y (x, z; frame-free) fitted with a model the mirror is no symmetry of
    (``told``: :func:`broken_by`'s words): the refit of the fit's mirror image decides whether the
    data determine the sign of the sideways motion (module doc); ``res`` changed in place, the
    findings returned. ``clock``, ``checkable``, ``ctrl_c``: as mirror.check_mirror's."""
    from scipy import stats

    names = [n for n in SIDEWAYS if n in res.params and res.determined[n]]
    if not (told and names) or res.planar or _exact(res):
        return []
    values = {**res.fixed, **res.params}
    image = {**values, **{n: 2.0 * plane_of(n, values[n]) - values[n] for n in SIDEWAYS if n in values}}
    wald = 2.0 * _distance(res, names)  # the image from the fit [linearised bars]
    if wald == 0.0:
        return []  # the fit is its own image
    length, g = hanging_length(values), abs(float(values["g"]))
    period = 2.0 * math.pi * math.sqrt(length / g) if length > 0.0 and g > 0.0 else 1.0
    held = max(names, key=lambda n: abs(values[n] - plane_of(n, values[n])) / res.stderr[n])
    level = float(stats.chi2.ppf(0.95, 1))
    threshold = min(level, wald * wald / 2.0)
    why = ""
    if not (checkable and res.converged):
        why = why_unchecked(res, clock, "ctrl_c" if ctrl_c else "")
    else:
        try:
            rise, settled = _image_rise(res, held, period, clock, image)
        except Late as e:
            why = why_unchecked(res, clock, "ctrl_c" if e.ctrl_c else "late")
        else:
            if rise < threshold:  # an unconverged refit's rise is too high: conclusive
                res.mirror_sign = SignCheck(False, told, rise, level, threshold)
                reason = (
                    f"{SIGN.format(told=told)}, and the image fits as well: its misfit is higher by only "
                    f"{max(rise, 0.0):.2g} (95 % level {level:.3g})"
                )
                mark_not_determined(res, names, reason)
                return [
                    f"{reason}: the sign of the sideways motion ({', '.join(names)}) is not determined. "
                    "Record y too (3-D positions), or fit planar=True for a swing in a plane"
                ]
            if settled:
                res.mirror_sign = SignCheck(True, told, rise, level, threshold)
                return []  # the curvature's bars stand (module doc: they cover the truth)
            why = f"it did not converge: its misfit is higher by {rise:.2g}"
    res.mirror_sign = SignCheck(None, told, math.nan, level, threshold, why)
    mark_not_determined(res, names, f"{SIGN_UNCHECKED} ({why}); only {told} tells the two apart")
    return []


def _image_rise(
    res: Any, held: str, period: float, clock: Search, image: dict[str, float]
) -> tuple[float, bool]:
    """The misfit's rise [units of the noise] of the fit's mirror ``image`` refitted with ``held`` at its
    image value, the others free, and whether that refit converged; then released (every unknown free,
    from there): where it stays on the image's side (nearer the image than the fit in the bars of φ₀,
    φ̇₀) and lower, a valley of its own whose floor is the rise; where it slides back to the fit (a
    quadratic valley: SciPy's integration, Ω_z = 0.023 and 0.078 rad/s, 34 of 34 seeds) the held rise
    stands."""
    rise, vals, settled = TimedRise(res, held, period, clock)(image[held], image)
    if not (settled and math.isfinite(rise)):
        return rise, settled
    free = TimedRise(res, held, period, clock)
    free.others = list(res.names)  # the held one too, starting from its image value
    low, got, ok = free(vals[held], vals)
    names = [n for n in SIDEWAYS if n in res.params and res.determined[n]]
    i = [res.names.index(n) for n in names]
    w = np.linalg.pinv(res.covariance[np.ix_(i, i)])
    to_fit, to_image = (np.array([got[n] - ref[n] for n in names]) for ref in (res.params, image))
    if ok and low < rise and float(to_image @ w @ to_image) < float(to_fit @ w @ to_fit):
        return low, True
    return rise, settled
