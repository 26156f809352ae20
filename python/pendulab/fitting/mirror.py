"""Error bars of the sideways motion φ₀, φ̇₀ for data blind to the mirror y → −y (docs/fit.md, "A
swing near its plane, seen from the side").

Positions seen as (x, z) — and a phone's frame-free scalars — are the same for a motion and its mirror
image y → −y, which maps (φ₀, φ̇₀) to (−φ₀, −φ̇₀) and leaves every other unknown as it is. The misfit is
therefore even about the plane φ₀ = φ̇₀ = 0 (φ₀ = ±π is the same plane), and near it the data see the
sideways motion only at second order: the misfit is quartic there, not quadratic, and the curvature's
error bars are too narrow (bench/fit_validate.py case 27, a swing released in the x–z plane fitted with
``planar=False``: seed 15, φ₀ = −0.111 ± 0.037 rad and φ̇₀ = 0.495 ± 0.134 rad/s for 0 and 0, 3.0 and 3.7
bars off; φ₀ within 2 bars in 30 of 40 seeds, with the profile 37). For a swing far from its plane (an
ellipse: φ̇₀ many bars from 0) the curvature is right and nothing is done. A fit on the plane itself (the
columns of φ₀, φ̇₀ vanish: identify.py leaves them not determined) has them profiled too, uncorrelated
with the others to first order. Where the plane lies within :data:`MIRROR_BARS` linearised bars of the
fit (the joint Wald distance of (φ₀, φ̇₀) from the plane; for a misfit quartic about the plane the
linearised bar toward it is then ≥ 12 % too narrow), the fit and its mirror image share one valley, and
each of φ₀, φ̇₀ gets its 95 % profile-likelihood interval (profile.py's :class:`Rise` and
:func:`profile_end`): the end away from the plane by steps and bisection, the end toward it likewise but
on past the plane; an interval that reaches the plane is, as the profile is even, symmetric about it (the
wider of its two half-widths). The bar becomes the larger side over 1.96 (never narrower), as
short_record.py shows its profile intervals. With both held at the plane (the other unknowns refitted)
the misfit rising less than the χ²(2) 95 % quantile (5.99), the data are consistent with a planar swing,
which is said (a finding naming the profile intervals); otherwise a bar widened by
:data:`short_record.WIDENED` or more is said. An open profile makes the parameter not determined, with
its reason; so does a check the time limit or Ctrl-C in a refit stops, or an interrupted, unconverged or
robust fit leaves undone, with a finding, both saying why and what to do as a short record's do (the
same code: short_record.TimedRise, why_unchecked; Ctrl-C returns the fit). Records shorter
than a swing are short_record.py's (every parameter profiled there); noise-free data fitted to round-off
have no statistics to profile. The swinging spring (spring_model.py: a central force plus gravity, so
the mirror image of a motion is one too, r₀ and ṙ₀ unchanged) is checked alike, its period that of the
hanging length l₀ + m g/k (short_record.hanging_length); a spring record shorter than a swing, as a
rod's, by short_record.py. Only models the mirror is a symmetry of are checked: estimator.py leaves
``mirror_blind`` False where a held term breaks it (a rotating frame with Ω_z ≠ 0, a pivot moving along
y, a gravity or forcing direction or a perspective with a y part: mirror_sign.py derives which), and
mirror_sign.check_sign decides there whether the data tell the sign of the sideways motion.
Units: φ₀ [rad], φ̇₀ [rad/s]; times [s].
"""

from __future__ import annotations

import math
from statistics import NormalDist
from typing import Any

import numpy as np

from .identify import FLAT
from .problem import bounds_of, scale_of
from .profile import profile_end
from .search import Search
from .short_record import (
    ASYMMETRIC,
    LEVEL,
    SHORT_PERIODS,
    STOPPED,
    WIDENED,
    Late,
    TimedRise,
    hanging_length,
    mark_not_determined,
    shown_interval,
    why_unchecked,
)

#: The sideways motion: the unknowns the mirror y → −y changes (to their negatives).
SIDEWAYS = ("phi0", "phi_dot0")

#: The joint linearised distance (in bars) of the plane from the fit below which the profile decides.
MIRROR_BARS = 10.0

#: Steps of doubling size per end (out to 63 curvature bars), bisections of the crossing, refits per end.
DOUBLINGS = 6
BISECTIONS = 4
REFITS = 2 * (DOUBLINGS + BISECTIONS + 1)

#: The misfit's rise with φ₀ = φ̇₀ = 0 held below which the data are consistent with a planar swing
#: (the χ²(2) 95 % quantile, in units of the noise).
PLANAR_RISE = 5.991

UNCHECKED = "the fit stopped before the profile likelihood of the sideways motion was checked"
"""Why φ₀, φ̇₀ are not determined when the profile was not computed (server/fit_words.py keys it)."""

NARROW = (
    "near its plane the sideways motion shows only at second order and the curvature's error bars are too "
    "narrow"
)
"""Why the curvature's bars of φ₀, φ̇₀ are not kept when their profile was not checked."""

OPEN = "seen from the side near its plane, the sideways motion's profile likelihood does not close"
"""Why φ₀ or φ̇₀ is not determined when its profile is open (server/fit_words.py keys it)."""


def plane_of(name: str, value: float) -> float:
    """The value of ``name`` on the plane nearest ``value``: φ₀ the nearest multiple of π, φ̇₀ 0."""
    return math.pi * round(value / math.pi) if name == "phi0" else 0.0


def check_mirror(res: Any, clock: Search, checkable: bool = True, ctrl_c: bool = False) -> list[str]:
    """For a mirror-blind :class:`pendulab.FitResult` ``res`` whose fitted sideways motion lies within
    :data:`MIRROR_BARS` bars of its plane: the bars of φ₀ and φ̇₀ from their profile likelihood (or
    not determined), ``res`` changed in place; the findings to warn (module doc). ``clock``: the fit's
    search, whose ``time_limit`` bounds every refit; once it has passed, at Ctrl-C in a refit, when not
    ``checkable`` (an interrupted fit, a robust loss; ``ctrl_c``: Ctrl-C stopped the error analysis
    before) or not converged: not determined, the reason and the finding saying why and what to do
    (short_record.why_unchecked, as a short record's)."""
    names = [n for n in SIDEWAYS if n in res.params and res.determined[n]]
    flat = [n for n in SIDEWAYS if n in res.params and res.reasons.get(n, "").startswith(FLAT)]
    values = {**res.fixed, **res.params}
    if not (res.mirror_blind and (names or flat)) or res.planar or _exact(res):
        return []
    if not names:  # a fit at the plane itself: no first-order sensitivity, the profile gives the bars
        names = flat
    if any(n not in res.params and values.get(n, 0.0) != plane_of(n, values.get(n, 0.0)) for n in SIDEWAYS):
        return []  # a sideways value held off the plane: its mirror image is not a fit of these data
    length, g = hanging_length(values), float(values["g"])
    if not (length > 0.0 and math.isfinite(length) and math.isfinite(g) and g != 0.0):
        return []
    period = 2.0 * math.pi * math.sqrt(length / abs(g))
    if float(res.t[-1] - res.t[0]) < SHORT_PERIODS * period or _distance(res, names) > MIRROR_BARS:
        return []  # short records: short_record.py profiles every parameter
    if not (checkable and res.converged):  # no optimum to profile from
        return _stopped(res, names, flat, why_unchecked(res, clock, "ctrl_c" if ctrl_c else ""))
    from scipy import stats

    target = float(stats.chi2.ppf(LEVEL, 1))
    try:
        held = tuple(n for n in SIDEWAYS if n in res.params)
        plane = {n: plane_of(n, values[n]) for n in SIDEWAYS}
        rise = TimedRise(res, held[0], period, clock, held)
        plane_rise = rise(plane[held[0]], {**values, **plane})[0]
        ends = {n: _interval(res, n, values, period, clock, target) for n in names}
    except Late as e:  # the time limit or Ctrl-C in a refit: the fit is returned
        return _stopped(res, names, flat, why_unchecked(res, clock, "ctrl_c" if e.ctrl_c else "late"))
    closed = {n: e for n, e in ends.items() if all(map(math.isfinite, e))}
    mark_not_determined(res, [n for n in ends if n not in closed and n not in flat], OPEN)
    return _widened(res, closed, plane_rise)


def _exact(res: Any) -> bool:
    """Noise-free data fitted to round-off (goodness.py's "exact"): no statistics to profile."""
    kinds = res.goodness.kinds.values() if res.goodness is not None else []
    return bool(kinds) and all(c.verdict() == "exact" for c in kinds)


def _distance(res: Any, names: list[str]) -> float:
    """The joint Wald distance [bars] of the plane from the fitted (φ₀, φ̇₀) of ``names`` (0 where the
    residuals do not change with them: a fit at the plane)."""
    if not all(res.determined[n] for n in names):
        return 0.0
    i = [res.names.index(n) for n in names]
    d = np.array([res.params[n] - plane_of(n, res.params[n]) for n in names])
    cov = res.covariance[np.ix_(i, i)]
    if not np.all(np.isfinite(cov)):
        return math.inf
    return float(math.sqrt(max(float(d @ np.linalg.pinv(cov) @ d), 0.0)))


def _interval(
    res: Any, name: str, values: dict[str, float], period: float, clock: Search, target: float
) -> tuple[float, float]:
    """The 95 % profile interval of ``name`` [its unit] (module doc): ±inf for an end that does not
    close within DOUBLINGS doublings of the curvature's bar, reaches a bound, or is not settled."""
    rise = TimedRise(res, name, period, clock)
    value, err = values[name], res.stderr[name]
    centre = plane_of(name, value)
    lo_b, hi_b = bounds_of(res._problem.model, name, value)
    step0 = err if math.isfinite(err) and err > 0 else scale_of(name, value, values["length"], period) / 8
    side = 1.0 if value >= centre else -1.0
    outer, settled = profile_end(
        rise, values, step0, (lo_b, hi_b), side, REFITS, target, DOUBLINGS, BISECTIONS
    )
    if not settled or outer in (lo_b, hi_b):
        outer = side * math.inf
    # toward the plane and past it: the refits there start from the other side of the plane, and
    # the profile being even, the wider of the two half-widths is the better one (a refit caught in a
    # poorer valley rises too soon; a rise below the level is an achieved misfit, never too low)
    inner, settled = profile_end(
        rise, values, step0, (lo_b, hi_b), -side, REFITS, target, DOUBLINGS, BISECTIONS
    )
    if not settled or inner in (lo_b, hi_b):
        inner = -side * math.inf
    if value == centre or (inner - centre) * side <= 0.0:  # the plane inside: even about it
        half = max(abs(outer - centre), abs(inner - centre))
        return centre - half, centre + half
    lo, hi = sorted((inner, outer))
    return lo, hi


def _stopped(res: Any, names: list[str], flat: list[str], why: str) -> list[str]:
    """The check of ``names`` not done (``why``: short_record.why_unchecked): those determined by the
    curvature marked not determined (its bars are too narrow near the plane; ``flat`` ones keep their
    reason), the reason and the finding naming why and what to do, as a short record's (no finding
    for a fit that did not converge: its own warning says so)."""
    said = "" if why == STOPPED else f"; {why}"
    mark_not_determined(res, [n for n in names if n not in flat], f"{UNCHECKED} ({NARROW}{said})")
    if not said:  # not converged: the fit's own warning says so
        return []
    return [
        f"seen from the side, {', '.join(names)} {'is' if len(names) == 1 else 'are'} not determined "
        f"({NARROW}{said}). Fit planar=True for a swing in a plane"
    ]


def _widened(res: Any, closed: dict[str, tuple[float, float]], plane_rise: float) -> list[str]:
    """The bars in ``res`` of the parameters with a ``closed`` profile interval widened to it (the
    larger side over 1.96, never narrower); the finding: consistent with a planar swing when
    ``plane_rise`` (the misfit's rise with the sideways motion held at the plane, in units of the
    noise) is below PLANAR_RISE, else when a bar grew by WIDENED or more or is lopsided."""
    z = NormalDist().inv_cdf(0.5 + LEVEL / 2.0)
    i = {n: k for k, n in enumerate(res.names)}
    grown = []
    for n, (lo, hi) in closed.items():
        v = res.params[n]
        if not res.determined[n]:  # at the plane: no first-order coupling to the others
            grown.append(n)
            _from_profile(res, n, max(hi - v, v - lo) / z)
            continue
        f = max(max(hi - v, v - lo) / z / res.stderr[n], 1.0)
        res.stderr[n] *= f
        res.covariance[i[n], :] *= f
        res.covariance[:, i[n]] *= f
        if f >= WIDENED or max(hi - v, v - lo) > ASYMMETRIC * max(min(hi - v, v - lo), 0.0):
            grown.append(n)
    intervals = "; ".join(shown_interval(res, n, lo, hi) for n, (lo, hi) in closed.items())
    if plane_rise < PLANAR_RISE:
        return [
            f"the data are consistent with a planar swing: held in its plane (phi0 = {_plane_shown(res)}, "
            f"phi_dot0 = 0: the x–z plane) the misfit rises by only {max(plane_rise, 0.0):.2g} (95 % level "
            f"for the two: {PLANAR_RISE:.3g}). Seen from the side, the sideways motion shows only at second "
            "order near the plane"
            + (
                f"; the error bars of {', '.join(closed)} were taken from their 95 % profile-likelihood "
                f"intervals ({intervals}; the error bar is the larger side over 1.96)"
                if closed
                else ""
            )
            + ". Fit planar=True for a swing in a plane"
        ]
    if not grown:
        return []
    return [
        f"seen from the side near its plane, the sideways motion shows only at second order: the error "
        f"bars of {', '.join(grown)} were taken from their 95 % profile-likelihood intervals "
        f"({intervals}; the error bar is the larger side over 1.96), which the curvature at the fit "
        "understates"
    ]


def _plane_shown(res: Any) -> str:
    """φ₀ of the plane nearest the fit (:func:`plane_of`), as the data see it: 0 or π (mod 2π; −π and
    3π are the same half-plane, x < 0)."""
    phi = {**res.fixed, **res.params}.get("phi0", 0.0)
    return "π" if round(plane_of("phi0", phi) / math.pi) % 2 else "0"


def _from_profile(res: Any, name: str, err: float) -> None:
    """``name``, not determined by the curvature (its column vanishes at the plane), determined with the
    bar ``err`` from its profile: uncorrelated with the others to first order."""
    i = res.names.index(name)
    res.determined[name] = True
    res.reasons.pop(name, None)
    res.stderr[name] = err
    res.covariance[i, :] = 0.0
    res.covariance[:, i] = 0.0
    res.covariance[i, i] = err * err
    res.correlation[i, :] = 0.0
    res.correlation[:, i] = 0.0
    res.correlation[i, i] = 1.0
