"""Starting values from the data themselves, so that the least-squares search begins near the answer:

- the pivot (when unknown) by the algebraic sphere (circle) fit |p|² = 2 c·p + k to the positions;
- the swing's period T from the crossings of its horizontal coordinate (the principal axis of the
  horizontal motion), its amplitude A, and ω₀ = (2π/T)/(1 − A²/16) (the first amplitude correction
  of the period, T-4.x's small-swing limit); then g = ω₀² l or l = g/ω₀², whichever is free;
- g (or l) also from energy conservation, which holds for whirls over the top where the period's
  formula does not (:func:`energy_gravity`); when the two disagree by more than 10 %, both are
  tried (:func:`gravity_starts`);
- linear damping c from the decay of the swing's peaks, A(t) ∝ e^{−ct/2} (T-7.1);
- the start (θ₀, φ₀, θ̇₀, φ̇₀) from a quadratic through the first samples;
- from frame-free data only (a phone): for a planar swing of amplitude A the rod pulls T/m = g cos A at
  the turning points and g(3 − 2 cos A) at the bottom (energy conservation with T-2.3), so
  g = (f_max + 2 f_min)/3 and cos A = f_min/g; |ω|max = √(2(g/l)(1 − cos A)) gives l; the phase of
  the swing at t₀ is unknown, so several starts (:func:`phase_starts`) are tried;
- data blind to the sign of the sideways motion (x, z seen along y; a phone's frame-free scalars) are
  unchanged by the mirror y → −y, which maps (φ₀, φ̇₀) to (−φ₀, −φ̇₀): a planar start φ̇₀ = 0 is then a
  stationary point of the misfit that a search never leaves, so starts with a sideways rate are added
  (:func:`sideways_starts`).
The features of the signals these are read from (period, decay, energy, sphere, despiking) are in
:mod:`pendulab.fitting.swing_features`, whose names are also importable from here.
Units: SI (m, s, rad, m/s²).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from .._core import InvalidInputError
from .._warn import warn_user
from ..model import FloatArray
from .data import Observations
from .problem import PIVOT_NAMES
from .spring_model import spring_start
from .swing_features import _robust_line as _robust_line
from .swing_features import crossings_period, decay_rate, despiked, energy_gravity, sphere_fit, value_and_rate
from .swing_features import running_median as running_median


def _relative_positions(obs: Observations, values: Mapping[str, float], free: set[str]) -> FloatArray | None:
    """The bob relative to the pivot [m] (N, 3) from whatever the data allow, or None (frame-free)."""
    ell = values["length"]
    if "positions" in obs.values:
        p = obs.values["positions"]
        cols = p.shape[1]
        pivot = np.array([values[k] for k in PIVOT_NAMES])
        pivot = pivot if cols == 3 else pivot[[0, 2]]
        if free & set(PIVOT_NAMES):
            fitted = sphere_fit(p)
            if fitted is not None and 0.05 < fitted[1] / max(np.ptp(p, axis=0).max(), 1e-300) < 100.0:
                pivot = fitted[0]
            else:  # too flat an arc: the pivot straight above the mean at the given length
                pivot = p.mean(axis=0)
                pivot[-1] = p[:, -1].min() + ell
        rel = p - pivot
        return rel if cols == 3 else np.column_stack([rel[:, 0], np.zeros(len(rel)), rel[:, 1]])
    if "horizontal" in obs.values:  # seen from above: the height from the length
        h = obs.values["horizontal"]
        centre = np.array([values["pivot_x"], values["pivot_y"]])
        if free & {"pivot_x", "pivot_y"}:
            centre = h.mean(axis=0)
        rel2 = h - centre
        rho = np.minimum(np.hypot(rel2[:, 0], rel2[:, 1]), 0.999 * ell)
        return np.column_stack([rel2, -np.sqrt(ell * ell - rho * rho)])
    if "angles" in obs.values:
        th, ph = obs.values["angles"][:, 0], obs.values["angles"][:, 1]
        return ell * np.column_stack([np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), -np.cos(th)])
    if "planar_angle" in obs.values:
        th = obs.values["planar_angle"][:, 0]
        return ell * np.column_stack([np.sin(th), np.zeros(len(th)), -np.cos(th)])
    return None


def _length_from_above(obs: Observations, values: Mapping[str, float], free: set[str]) -> float:
    """A length [m] for data seen from above, which show the sway but not the height: l = g/ω² from
    the period of the sway's principal component (small swings), with g known; with g free too,
    the given length unless the sway is wider than half of it."""
    h = obs.values["horizontal"]
    centred = h - h.mean(axis=0)
    axis = np.linalg.svd(centred, full_matrices=False)[2][0]
    period = crossings_period(obs.t, despiked(centred @ axis))
    ell = values["length"]
    wide = float(np.max(np.hypot(centred[:, 0], centred[:, 1]))) > 0.5 * ell
    if period is None or ("g" in free and not wide):
        return ell
    return abs(values["g"]) / (2.0 * math.pi / period) ** 2


def check_length_hint(radius: float, length: float, free: bool) -> None:
    """The positions' distance from the pivot [m] against the given length [m]: a fixed length that
    the data contradict (by more than a factor 2) is an error, a starting value off by more than a
    factor 10 (m against mm, cm or pixels) a warning (the start is taken from the data)."""
    ratio = radius / length if length > 0.0 else math.inf
    if (0.5 <= ratio <= 2.0) or (free and 0.1 <= ratio <= 10.0):
        return
    said = (
        f"the positions lie {radius:.4g} m from the pivot, but the pendulum's length is {length:.4g} m: "
        "are the positions in m (not mm, cm or pixels) and is the pivot right (pivot=..., or fit 'pivot')?"
    )
    if not free:
        raise InvalidInputError(said)
    warn_user(said + " The fit starts from the data's distance instead.", UserWarning)


def check_upright(rel: FloatArray, g: float) -> None:
    """Positions that never come below the pivot (for g > 0; above it for g < 0) are upside down: a
    spherical pendulum's lower turning height u₁ = z₁/l is always negative, since the roots of the
    cubic T-4.1 have pairwise products summing to −1 while u₃ ≥ 1 and u₂ ≥ u₁. The usual cause is
    image coordinates, whose vertical axis points down."""
    if g != 0.0 and len(rel) >= 8 and bool(np.all(np.sign(g) * rel[:, 2] > 0.0)):
        side = "above" if g > 0.0 else "below"
        raise InvalidInputError(
            f"every position lies {side} the pivot, where a pendulum with g = {g:g} m/s² never stays: "
            "does the data's vertical axis point down (image rows)? z points up here: negate that column "
            "(or, if gravity really points the other way, give a pendulum with the opposite g)"
        )


def starting_values(obs: Observations, values: Mapping[str, float], free: set[str]) -> dict[str, Any]:
    """Values for the free parameters read off the data (the given ones stay where they are); the
    result has the same keys as ``values``."""
    out = dict(values)
    if "horizontal" in obs.values and "length" in free:
        out["length"] = _length_from_above(obs, values, free)
        values = out
    rel = _relative_positions(obs, values, free)
    if rel is None:
        return _frame_free_start(obs, out, free)
    _pivot_start(obs, rel, free, out)
    radius = float(np.median(np.linalg.norm(rel, axis=1)))
    if "positions" in obs.values:
        check_upright(rel, values["g"])
        check_length_hint(radius, values["length"], "length" in free)
        if "length" in free:
            out["length"] = radius
    rel = np.column_stack([despiked(rel[:, j]) for j in range(3)])  # a tracked video's spikes
    period = _swing_start(obs.t, rel, free, out)
    span = _angles_start(obs.t, rel, free, out, period)
    if "stiffness" in values:  # the swinging spring: r₀, ṙ₀, k, l₀ (spring_model.py)
        _spring_rest(obs, rel, free, out, (period, span))
    return out


def _pivot_start(obs: Observations, rel: FloatArray, free: set[str], out: dict[str, Any]) -> None:
    """The free pivot coordinates [m]: the first sample's position less its pivot-relative one."""
    if free & {"pivot_x", "pivot_y"} and "horizontal" in obs.values:
        centre = obs.values["horizontal"] - rel[:, :2]
        for k, name in enumerate(("pivot_x", "pivot_y")):
            if name in free:
                out[name] = float(centre[0, k])
    if free & set(PIVOT_NAMES) and "positions" in obs.values:
        p = obs.values["positions"]
        centre = p - (rel if p.shape[1] == 3 else rel[:, [0, 2]])
        pivot = centre[0]
        for k, name in enumerate(PIVOT_NAMES if p.shape[1] == 3 else ("pivot_x", "pivot_z")):
            if name in free:
                out[name] = float(pivot[k])


def _swing_start(t: FloatArray, rel: FloatArray, free: set[str], out: dict[str, Any]) -> float | None:
    """g [m/s²] or l [m] from the swing's period (amplitude-corrected), the damping [1/s] from its
    decay; returns the period [s] (None without two crossings)."""
    horizontal = rel[:, :2] - rel[:, :2].mean(axis=0)
    axis = np.linalg.svd(horizontal, full_matrices=False)[2][0]
    swing = horizontal @ axis
    theta = np.arctan2(np.hypot(rel[:, 0], rel[:, 1]), -rel[:, 2])
    amplitude = float(np.max(theta))
    period = crossings_period(t, swing)
    if period is not None:
        omega0 = (2.0 * math.pi / period) / max(1.0 - amplitude**2 / 16.0, 0.3)
        if "g" in free:  # the length is known, or read off the positions above
            out["g"] = omega0**2 * out["length"]
        elif "length" in free:
            out["length"] = out["g"] / omega0**2
    if "damping" in free:
        out["damping"] = decay_rate(t, swing)
    return period


def _angles_start(
    t: FloatArray, rel: FloatArray, free: set[str], out: dict[str, Any], period: float | None
) -> float:
    """θ₀, φ₀ [rad], θ̇₀, φ̇₀ [rad/s] from the first samples (a quadratic over a twentieth of the
    period); returns that span [s]."""
    ell = out["length"]
    unit = rel / np.linalg.norm(rel, axis=1)[:, None]
    x = ell * unit
    theta = np.arctan2(np.hypot(rel[:, 0], rel[:, 1]), -rel[:, 2])
    phi = np.unwrap(np.arctan2(x[:, 1], x[:, 0]))
    period_guess = period or 2.0 * math.pi * math.sqrt(ell / max(abs(out["g"]), 1e-9))
    span = period_guess / 20.0
    th0, thd0 = value_and_rate(t, theta, span)  # a monotone run is kept exactly
    ph0, phd0 = value_and_rate(t, phi, span)
    for name, value in zip(("theta0", "phi0", "theta_dot0", "phi_dot0"), (th0, ph0, thd0, phd0), strict=True):
        if name in free:
            out[name] = value
    if "theta0" in free:
        out["theta0"] = min(max(out["theta0"], 0.0), math.pi)
    return span


def _spring_rest(
    obs: Observations,
    rel: FloatArray,
    free: set[str],
    out: dict[str, Any],
    times: tuple[float | None, float],
) -> None:
    """The swinging spring: the rest length l₀ = l − m g/k [m] below the hanging length, r₀ [m], ṙ₀
    [m/s] over ``times`` = (period, span) [s], then the spring's own start (spring_model.py)."""
    period, span = times
    if "length" in free:  # the rest length l₀ = l − m g/k below the hanging length
        sag = out["g"] * out["mass"] / out["stiffness"]
        out["length"] = max(out["length"] - sag, 0.1 * out["length"])
    if "positions" in obs.values and obs.values["positions"].shape[1] == 3:
        r0, rd0 = value_and_rate(obs.t, np.linalg.norm(rel, axis=1), span)
        out |= {k: v for k, v in (("r0", r0), ("r_dot0", rd0)) if k in free}
        spring_start(obs.t, rel, out, free, period)


def signed_start(obs: Observations, start: Mapping[str, float], free: set[str]) -> dict[str, float]:
    """θ₀ and θ̇₀ of a hinge (φ₀ = 0 held) from the signed planar angle itself (a quadratic through the
    first samples, spikes removed): |angle|, which the 3-D start uses, has a corner where the swing
    crosses the bottom."""
    angle = despiked(np.unwrap(obs.values["planar_angle"][:, 0]))
    period = 2.0 * math.pi * math.sqrt(start["length"] / max(abs(start["g"]), 1e-9))
    th0, thd0 = value_and_rate(obs.t, angle, period / 20.0)
    out = {}
    if "theta0" in free:
        out["theta0"] = min(max(th0, -math.pi), math.pi)
    if "theta_dot0" in free:
        out["theta_dot0"] = thd0
    return out


def _frame_free_start(obs: Observations, out: dict[str, Any], free: set[str]) -> dict[str, Any]:
    f = obs.values.get("specific_force")
    w = obs.values.get("angular_speed")
    g = out["g"]
    cos_a = None
    if f is not None:
        f_min, f_max = float(np.min(f)), float(np.max(f))
        g_est = (f_max + 2.0 * f_min) / 3.0
        if "g" in free and g_est > 0.0:
            out["g"] = g = g_est
        cos_a = min(max(f_min / g, -1.0), 1.0) if g > 0 else None
    if w is not None and cos_a is not None and "length" in free and cos_a < 1.0:
        w_max = float(np.max(w))
        if w_max > 0.0:
            out["length"] = 2.0 * g * (1.0 - cos_a) / w_max**2
    if cos_a is not None and "theta0" in free:
        out["theta0"] = math.acos(cos_a)
    signal = f if f is not None else w
    if signal is not None and "damping" in free:
        out["damping"] = decay_rate(obs.t, signal[:, 0] - np.mean(signal)) / 2.0
    return out


def phase_starts(values: Mapping[str, float], free: set[str], n: int = 8) -> list[dict[str, float]]:
    """Starts along the swing: θ = A cos ψ, θ̇ = −A ω sin ψ for n phases ψ (planar, in the x–z plane,
    negative θ as φ = π) — for data that do not say where the swing was at t₀."""
    if not {"theta0", "theta_dot0"} <= free:
        return [dict(values)]
    amp = values["theta0"]
    omega = math.sqrt(abs(values["g"]) / values["length"])
    starts = []
    for k in range(n):
        psi = 2.0 * math.pi * k / n
        theta, rate = amp * math.cos(psi), -amp * omega * math.sin(psi)
        s = dict(values)
        s["theta0"], s["theta_dot0"] = abs(theta), rate if theta >= 0 else -rate
        if "phi0" in free:
            s["phi0"] = 0.0 if theta >= 0 else math.pi
        if "phi_dot0" in free:
            s["phi_dot0"] = 0.0
        starts.append(s)
    return starts


def gravity_starts(obs: Observations, start: dict[str, Any], free: set[str]) -> list[dict[str, Any]]:
    """[start], plus a start with g (or, g being fixed, l) from energy conservation when that differs
    from the period's by more than 10 % — for 3-D positions and angles, whose speeds are complete
    (a camera's x, z miss ẏ)."""
    has_speed = "angles" in obs.values or (
        "positions" in obs.values and obs.values["positions"].shape[1] == 3
    )
    if not has_speed or not ({"g", "length"} & free) or "stiffness" in start:  # a spring stores energy too
        return [start]
    rel = _relative_positions(obs, start, free)
    g_energy = energy_gravity(obs.t, rel) if rel is not None else None
    if g_energy is None or abs(g_energy / start["g"] - 1.0) <= 0.1:
        return [start]
    other = dict(start)
    if "g" in free:
        other["g"] = g_energy
    elif "positions" not in obs.values:  # angles with g known: the slope is g·l_assumed/l
        other["length"] = start["length"] * start["g"] / g_energy
    else:
        return [start]
    return [start, other]


#: Sideways rates of the extra starts, as fractions of the small-swing frequency √(g/l).
SIDEWAYS = (0.1, 0.5)


def sideways_starts(starts: list[dict[str, float]], free: set[str]) -> list[dict[str, float]]:
    """The starts plus, for each planar one (φ̇₀ = 0), copies with φ̇₀ = κ·√(g/l)/max(sin θ₀, 0.1) for
    κ in :data:`SIDEWAYS` — for data that cannot tell a swing from its mirror image (see the module
    doc); one sign suffices, the mirror image being an equally good fit."""
    if "phi_dot0" not in free:
        return starts
    out = list(starts)
    for s in starts:
        if s["phi_dot0"] != 0.0:
            continue
        omega = math.sqrt(abs(s["g"]) / s["length"])
        for kappa in SIDEWAYS:
            extra = dict(s)
            extra["phi_dot0"] = kappa * omega / max(math.sin(s["theta0"]), 0.1)
            out.append(extra)
    return out
