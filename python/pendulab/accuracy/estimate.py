"""Global error estimates of a finished run, at every saved sample (``simulate(..., error_estimate=True)``).
The reference run costs at most 1.5× the plain run (total ≤ 2.5× with the plain run), except in the
fixed-step fall-back below.

- Fixed-step methods of order p (RK4, the RATTLE family, RKMK4, RK4 in angles): Richardson
  extrapolation (Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.4). With the global error
  y_h(t) − y(t) = C(t)·hᵖ + O(h^{p+1}), a **coarse companion** at 2·dt saved at the same times gives
  e(t) ≈ (y_{2h}(t) − y_h(t))/(2ᵖ − 1) for the error of the plain run y_h. Extra cost 0.5× (total 1.5×).
  The coarse run must be in the asymptotic regime, where the expansion holds; it is rejected, and the
  **fine companion** at dt/2 used instead, e(t) ≈ (y_h(t) − y_{h/2}(t))·2ᵖ/(2ᵖ − 1) (extra cost 2×,
  plus the rejected coarse run's 0.5×), when
  1. the save times would cost the coarse run too many shortened steps: the stepper shortens the one
     step that would cross a save time and re-anchors its grid there, so every interval between save
     times that is not a whole number of 2·dt adds one irregular step, whose local error departs from
     the C·(2h)^{p+1} pattern by at most that of one step. Up to every sample at most
     ``MAX_IRREGULAR`` (1/8) of the coarse steps may be irregular (``save_every`` even and
     ``save_at`` on the 2·dt grid: none; sparse ``save_at`` times off the grid: a few; ``save_every``
     = 1 or 3: every one, so the fine companion); a sampled pivot's samples count alike, for a fixed
     step holding one is split there (2·dt spanning the 10-ms spacing: the coarse estimate was 46×
     too low; docs/integrators.md, "Sampled pivot"). There the fine companion is the plain run with
     every (sub-)step taken as two halves (``run_halved``), not a run at dt/2, which splits on the
     samples elsewhere (with dt above the spacing it read 0.57 … 0.87 of the true error);
  2. the coarse run fails: raises (unstable, leaves TS²), is not finite;
  3. round-off may rival the truncation error: Richardson sees only what changes with h, so the
     difference y_{2h} − y_h carries round-off at its own size, and dividing it by 2ᵖ − 1 hides it
     (the fine companion multiplies by 2ᵖ/(2ᵖ − 1) and keeps it). Ruled out when the 2·dt estimate
     is below ``ROUNDOFF_MARGIN`` (2) × ε·N·l, the round-off N steps can gather unamplified
     (RKMK4 over the top at 1e-12 m: 2·dt said 0.1 … 10× the truth, dt/2 within 1.1×), and by the
     energy test below where round-off is amplified (RATTLE8 0.01° from the top: 200× too low);
  4. it is evidently outside the asymptotic regime: it differs from the plain run by more than
     ``MAX_COARSE_GAP`` (5 %) of l somewhere — the error expansion linearises a deviation, not a lost
     phase — or, for a conservative model, its energy error is not 2ᵖ times that of the plain run
     within a factor ``ORDER_BAND`` (2). The energy error at a saved time is a smooth function of the
     state times hᵖ for every method (drift for RK4, a bounded oscillation for the symplectic ones),
     so the ratio max|E_{2h} − E₀| / max|E_h − E₀| is the observed order of the pair at no extra
     integration; the estimate's own error follows it, e ≈ e_true·(ratio − 1)/(2ᵖ − 1). Too
     large a ratio is measured against max(the plain run's energy error, its round-off
     ``ENERGY_NOISE``·ε·√N·scale); too small a one means the energy error is round-off (amplified
     round-off, item 3) unless the two runs agree to within 100× unamplified round-off of x.
  ``ErrorEstimate.reference`` says which companion was used (``"companion": "2dt"`` or ``"dt/2"``)
  and, for the fall-back, why.
- DOP853: a companion run at rtol·``COMPANION_FACTOR`` (1/10; atol likewise), clamped at
  ``RTOL_MIN``, saved at the same times by dense output. Its global error follows the tolerance
  (docs/integrators.md), so with q = rtol/rtol_c the plain run's error is e ≈ (y − y_c)·q/(q − 1)
  (1.11 for q = 10). Work ∝ tol^{−1/8}: 10^{1/8} = 1.33× extra (total ≈ 2.3×); 1/16 would leave
  the companion's error at 6 % instead of 10 % of the estimate (either is far inside the factor 10
  the validation asks) for 1.41× extra, too close to the 2.5× bound once rejected steps are counted.
  When rtol is within a factor 2 of RTOL_MIN, no tighter run exists: the companion is then *looser*,
  at rtol·10, and e ≈ (y_c − y)/(q − 1) with q = 10 (cost 0.75×).
- The ideal pendulum also gets the true error against the exact solution (T-4.x, ``pl.exact``),
  ``Trajectory.error``.

Errors are |Δx| [m] and |Δv| [m/s] per sample. Where both runs sit at the float64 floor the
estimate is round-off noise of that size, not the error (see docs/integrators.md, "Error estimates").
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from .._core import ExactSolution as _CoreExact
from .._core import IntegrationError, InvalidInputError
from ..error_estimate import ErrorEstimate
from ..integrators import _method_table, unknown_method
from ..model import Pendulum, State
from ..trajectory import Trajectory

#: The companion run of DOP853 is this much tighter in rtol and atol.
COMPANION_FACTOR = 0.1
#: The smallest rtol DOP853 accepts (crates/pendulab-core/src/integrate/dop853/mod.rs, RTOL_MIN).
RTOL_MIN = 1e-15
#: At most this share of the coarse (2·dt) run's steps, up to any sample, may be shortened ones.
MAX_IRREGULAR = 1.0 / 8.0
#: The coarse run may differ from the plain one by at most this much [l] at any sample.
MAX_COARSE_GAP = 0.05
#: The coarse/plain energy error ratio must lie in [2ᵖ/ORDER_BAND, 2ᵖ·ORDER_BAND].
ORDER_BAND = 2.0
#: The 2·dt estimate must stand this far above ε·N·l, the round-off N steps can gather unamplified
#: (above it, round-off the estimate cannot see moves the truth by at most ±1/ROUNDOFF_MARGIN of it).
ROUNDOFF_MARGIN = 2.0
#: ``reference["halved"]`` of the dt/2 companion on a sampled pivot.
HALVED = "each step of the plain run (each sub-step between the pivot's samples) taken as two halves"
#: Energy errors below ENERGY_NOISE·ε·√(steps)·scale are round-off, not truncation.
ENERGY_NOISE = 10.0

Runner = Callable[..., Trajectory]


def _order(method: str) -> int:
    info = _method_table().get(method)
    if info is None:
        raise InvalidInputError(unknown_method(method))
    return int(info["order"])


def _is_adaptive(method: str) -> bool:
    return bool(_method_table()[method]["adaptive"])


def _work(tr: Trajectory) -> float:
    return float(tr.stats.get("rhs_evals", 0) or tr.stats.get("steps", 0) or 1)


def reference_settings(method: str, options: dict[str, Any]) -> dict[str, Any]:
    """The settings of the first reference run for ``method`` and ``options`` (dt, rtol, atol): the
    coarse companion (2·dt) of a fixed-step method, the tighter (or looser) one of DOP853."""
    if _is_adaptive(method):
        rtol = float(options["rtol"])
        factor = COMPANION_FACTOR if rtol * COMPANION_FACTOR >= 2 * RTOL_MIN else 1 / COMPANION_FACTOR
        rtol_c = max(rtol * factor, RTOL_MIN)
        return {"rtol": rtol_c, "atol": float(options["atol"]) * rtol_c / rtol}
    return {"dt": 2.0 * float(options["dt"])}


def irregular_share(t: np.ndarray, dt_coarse: float) -> float:
    """The largest share, up to any sample, of the coarse run's steps that saving at ``t`` [s]
    shortens: one per interval between save times that is not a whole number of ``dt_coarse`` [s]."""
    n = np.diff(np.asarray(t, dtype=float)) / dt_coarse
    if n.size == 0:
        return 0.0
    whole = np.abs(n - np.round(n)) <= 1e-6 * np.maximum(1.0, n)
    irregular = np.cumsum(~whole & (n > 0))
    steps = np.cumsum(np.maximum(np.ceil(n - 1e-6), 1.0))
    return float(np.max(irregular / steps))


def estimate(
    run: Runner, tr: Trajectory, state: State, kwargs: dict[str, Any], run_halved: Runner | None = None
) -> ErrorEstimate:
    """The error estimate of ``tr``, the result of ``run(pendulum, state, t_end, **kwargs)``.

    ``run`` is the plain simulation (``pendulab.simulate`` without ``error_estimate``); the reference
    runs are the same call with the settings of :func:`reference_settings` (or dt/2), saved at ``tr.t``.
    ``run_halved``, the same call with every (sub-)step taken as two halves, is the dt/2 companion on
    a sampled pivot (its samples split the steps: a run at dt/2 splits them elsewhere)."""
    method = tr.method
    base = {k: v for k, v in kwargs.items() if k not in ("save_every", "save_at", "dt", "progress")}
    base |= {"method": method, "progress": kwargs.get("progress")}
    every = int(kwargs.get("save_every") or 1) if kwargs.get("save_at") is None else 0

    def companion(settings: dict[str, Any], runner: Runner = run) -> Trajectory:
        kw = base | settings
        if "dt" not in settings and kwargs.get("dt") is not None:
            kw["dt"] = kwargs["dt"]
        # the same samples: with save_every where the plain run used it (the tight stepping loop; a
        # fixed-step run with save_at steps one call per sample), else save_at = the plain run's t
        ratio = float(tr.options["dt"]) / settings["dt"] if "dt" in settings else 0.0
        n = every * ratio
        by_every = every > 0 and ratio > 0 and n >= 1 and abs(n - round(n)) < 1e-9
        out = runner(
            tr.pendulum,
            state,
            float(tr.t[-1]),
            **kw,
            **({"save_every": round(n)} if by_every else {"save_at": tr.t}),
        )
        if len(out) != len(tr) and out.interrupted:
            raise RuntimeError("the reference run was interrupted: no error estimate")
        if by_every and (
            len(out) != len(tr) or np.max(np.abs(out.t - tr.t)) > 1e-9 * max(1.0, abs(tr.t[-1]))
        ):
            out = runner(tr.pendulum, state, float(tr.t[-1]), **kw, save_at=tr.t)
        if len(out) != len(tr):
            raise RuntimeError("the reference run was interrupted: no error estimate")
        return out

    ref = reference_settings(method, tr.options)
    if _is_adaptive(method):
        c = companion(ref)
        q = float(tr.options["rtol"]) / ref["rtol"]
        scale = q / (q - 1.0) if q > 1 else 1.0 / (1.0 / q - 1.0)  # tighter: q/(q−1); looser: 1/(1/q − 1)
        dx = np.linalg.norm(tr.x - c.x, axis=1) * scale
        dv = np.linalg.norm(tr.v - c.v, axis=1) * scale
        return ErrorEstimate(dx, dv, "companion", ref | {"method": method}, cost=_work(c) / _work(tr))
    p = _order(method)
    dt = float(tr.options["dt"])
    why = _coarse_refusal(tr, dt)
    cost = 0.0
    if why is None:
        try:
            coarse = companion(ref)
        except (IntegrationError, InvalidInputError) as e:
            why = f"the 2·dt run failed: {str(e).splitlines()[0][:200]}"
        else:
            cost += _work(coarse)
            why = _not_asymptotic(tr, coarse, p)
            if why is None:
                scale = 1.0 / (2.0**p - 1.0)
                dx = np.linalg.norm(coarse.x - tr.x, axis=1) * scale
                dv = np.linalg.norm(coarse.v - tr.v, axis=1) * scale
                info = ref | {"method": method, "companion": "2dt"}
                return ErrorEstimate(dx, dv, "richardson", info, cost=cost / _work(tr))
    # on a sampled pivot every step of the plain run is halved (the same dt, each step as two halves):
    # a run at dt/2 splits on the samples elsewhere, its steps next to a sample are not halves of the
    # plain run's, and with dt above the spacing the estimate read 0.57 … 0.87 of the true error
    halver = run_halved if _pivot_kinks(tr, float(tr.options.get("t0", tr.t[0]))).size else None
    fine = companion({"dt": dt}, halver) if halver is not None else companion({"dt": dt / 2.0})
    cost += _work(fine)
    scale = 2.0**p / (2.0**p - 1.0)
    dx, dv = np.linalg.norm(tr.x - fine.x, axis=1) * scale, np.linalg.norm(tr.v - fine.v, axis=1) * scale
    halved = {"halved": HALVED} if halver is not None else {}
    info = {"dt": dt / 2.0, "method": method, "companion": "dt/2", "why": why} | halved
    return ErrorEstimate(dx, dv, "richardson", info, cost=cost / _work(tr))


def _coarse_refusal(tr: Trajectory, dt: float) -> str | None:
    """Why the save times, or a sampled pivot's kinks, rule out the coarse companion (None: they allow
    it). A fixed step that holds a sample of the pivot's path is split there (``Model::next_break``):
    like a shortened step, each split breaks the C·(2h)^{p+1} pattern, and where 2·dt spans a sample
    interval every coarse step is split (estimate 46× too low at dt = 16 ms on samples every 10 ms)."""
    t0 = float(tr.options.get("t0", tr.t[0]))
    times = np.concatenate([[t0], tr.t]) if tr.t[0] > t0 else tr.t
    kinks = _pivot_kinks(tr, t0)
    share = irregular_share(np.union1d(times, kinks) if kinks.size else times, 2.0 * dt)
    if share > MAX_IRREGULAR:
        what = "the save times and the pivot's samples are" if kinks.size else "the save times are"
        return (
            f"{what} off the 2·dt grid: {share:.0%} of the 2·dt run's steps would be "
            f"{'shortened or split' if kinks.size else 'shortened'} (at most {MAX_IRREGULAR:.1%})"
        )
    return None


def _pivot_kinks(tr: Trajectory, t0: float) -> np.ndarray:
    """The sampled pivot's sample times [s] inside the run (where its p̈ is kinked), else none."""
    samples = tr.pendulum.pivot_samples
    if samples is None:
        return np.empty(0)
    times = np.asarray(samples[0], dtype=float)
    return times[(times > t0) & (times < float(tr.t[-1]))]


def _not_asymptotic(tr: Trajectory, coarse: Trajectory, p: int) -> str | None:
    """Why the coarse run ``coarse`` is outside the asymptotic regime (None: nothing says so)."""
    if not (np.all(np.isfinite(coarse.x)) and np.all(np.isfinite(coarse.v))):
        return "the 2·dt run is not finite"
    ell = tr.pendulum.length
    gap = float(np.max(np.linalg.norm(coarse.x - tr.x, axis=1))) / ell
    if gap > MAX_COARSE_GAP:
        return f"the 2·dt run is {gap:.1e} l off the plain run (at most {MAX_COARSE_GAP} l)"
    steps = max(float(tr.stats.get("steps", 1) or 1), 1.0)
    eps = float(np.finfo(float).eps)
    truncation = gap * ell / (2.0**p - 1.0)
    if truncation <= ROUNDOFF_MARGIN * eps * steps * ell:
        return (
            f"the 2·dt estimate, {truncation:.1e} m, is within {ROUNDOFF_MARGIN:g}× the round-off "
            f"{steps:.0f} steps can gather (ε·N·l = {eps * steps * ell:.1e} m), which it cannot see"
        )
    if not (tr.is_conservative and coarse.is_conservative):
        return None
    e_h, e_2h = tr.energy, coarse.energy
    d_h, d_2h = float(np.max(np.abs(e_h - e_h[0]))), float(np.max(np.abs(e_2h - e_2h[0])))
    m, g = tr.pendulum.mass, abs(tr.pendulum.g)
    speed2 = float(np.max(np.sum(tr.v * tr.v, axis=1)))
    scale = m * (0.5 * speed2 + g * ell) + float(np.max(np.abs(e_h)))
    noise = ENERGY_NOISE * eps * math.sqrt(steps) * scale
    expected = 2.0**p
    if d_2h > ORDER_BAND * expected * max(d_h, noise):
        return (
            f"the 2·dt run's energy error is {d_2h / max(d_h, noise):.3g}× the plain run's, "
            f"not 2^{p} = {expected:g} (within ×{ORDER_BAND:g}): not yet asymptotic"
        )
    # too small a ratio: the energy error is not truncation but round-off (or the pair is not yet
    # asymptotic). Round-off is the same size in both runs, so the difference y_2h − y_h carries it
    # at its full size and dividing by 2ᵖ − 1 would hide it (RATTLE8 0.01° from the top: 200× too
    # low); the dt/2 companion keeps it (× 2ᵖ/(2ᵖ − 1)). Not needed where the runs agree to within
    # unamplified round-off of the position (the estimate is then at the float64 floor either way).
    floor = ENERGY_NOISE * eps * math.sqrt(steps) * ell
    if d_2h < expected / ORDER_BAND * max(d_h, 1e-300) and gap * ell > 100 * floor:
        return (
            f"the 2·dt run's energy error is only {d_2h / max(d_h, 1e-300):.3g}× the plain run's, "
            f"not 2^{p} = {expected:g} (within ×{ORDER_BAND:g}): round-off or not asymptotic"
        )
    return None


def true_error(pendulum: Pendulum, state: State, tr: Trajectory) -> ErrorEstimate | None:
    """|x − x_exact| [m] and |v − v_exact| [m/s] at the samples for the ideal pendulum (None otherwise)."""
    if not pendulum.is_ideal or pendulum.force is not None:
        return None
    sol = _CoreExact(pendulum.spec, (np.ascontiguousarray(state.x), np.ascontiguousarray(state.v)))
    # the start state is at t0, which is not a sample when save_at leaves it out
    t0 = float(tr.options.get("t0", tr.t[0]))
    x, v, _ = sol.states(np.ascontiguousarray(tr.t - t0))
    return ErrorEstimate(
        np.linalg.norm(tr.x - x, axis=1), np.linalg.norm(tr.v - v, axis=1), "exact", {"method": "exact"}
    )
