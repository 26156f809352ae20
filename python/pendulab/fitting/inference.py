"""The statistics at the fit's optimum, from the search's best values to the :class:`FitResult`:

- the Gauss–Newton polish (search.py) and the Jacobian J of the weighted residual r = (measured −
  predicted)/σ [1] (exact forward sensitivities, T-10.7, or difference quotients, logarithmic for
  positive parameters);
- with a robust loss, the weights ρ'(r²) of iteratively reweighted least squares (:func:`robust_weights`),
  so that outliers leave the error analysis;
- the linearised covariance (JᵀJ)⁻¹ × s² (s² = χ²/dof when σ is not given; T-10.2) and what the data
  determine (identify.py), widened for correlated residuals (Newey–West, goodness.py);
- the goodness of fit per data kind against its noise floor, the χ² probability with σ given, the
  block check of a misfit (blocks.py) and a g far from any planet's (T-10.5), each warned;
- over a record shorter than one swing, the bars of length and g checked by their profile likelihood:
  taken from it, or the parameters not determined (short_record.py), warned;
- for data blind to the mirror y → −y (positions seen as x, z) with the sideways motion near its
  plane, the bars of φ₀ and φ̇₀ from their profile likelihood, and a swing consistent with a planar
  one said (mirror.py); with a model the mirror is no symmetry of (a rotating frame, a pivot moving
  along y: mirror_sign.py), the refit of the fit's mirror image decides whether the sign of the
  sideways motion is determined.

Ctrl-C during the polish or the block check ends that step and skips the profiles (their parameters
not determined, the reason naming Ctrl-C), as Ctrl-C in the search returns the best values so far:
the fit is returned, with one warning naming Ctrl-C and the step (for the block check, its finding).
A block check that was due but that Ctrl-C or the time limit stopped before it or in it is not made:
``res.blocks`` says so and one finding warns what stopped it, that the bars were not widened and how to
let it run (blocks.UNMADE); where they cut the search itself, that the misfit may be the unfinished
search's rather than the model's — the one finding about the misfit then: goodness.py's that put it down
to the model or the noise are left out (:func:`_said`), and where no block check was due it is said all
the same. A fit that Ctrl-C or the time limit
stopped short anywhere — the search, the polish, the block check, a profile — is marked ``interrupted``.
Units: σ and residuals in each data kind's unit (docs/fit.md); g [m/s²]; times [s].
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from .._warn import warn_user
from ..model import FloatArray
from .blocks import UNMADE, BlockCheck, check_blocks, not_made
from .data import KINDS, residual
from .goodness import EXACT, MISFIT_VERDICTS, P_ALARM, Goodness, ar1_rho, check_kind, findings
from .goodness import misfit as misfit_found
from .identify import Correlation, Identifiability, analyse, jacobian
from .mirror import check_mirror
from .mirror_sign import check_sign
from .problem import POSITIVE
from .result import FitResult
from .search import Search, TimeUp, polish
from .short_record import check_short_record
from .whiteness import chi2_tails

#: The step Ctrl-C stopped when it stopped the block check (its finding, blocks.UNMADE "ctrlCIn", says so).
IN_BLOCKS = "the block check of the misfit"
LATE_REASON = "the fit's time limit ran out before its error bars were computed"
"""Every parameter's reason where the Jacobian past the time limit would not end within
:data:`search.LATE_SECONDS` of it (:func:`_late_jacobian`; server/fit_words.py keys it)."""
CUT_VERDICTS = MISFIT_VERDICTS | {"unexplained"}
"""The verdicts a cut search leaves unsaid (:func:`_said`): a misfit put down to the model or the noise,
and "the fitted motion explains only … %", put down to the data, the model or the start — values short
of the best fit explain less, so the one finding is that the search was cut."""


def robust_weights(loss: str, z: FloatArray) -> FloatArray:
    """ρ'(z) of SciPy's robust losses at z = r² (scale 1): the weight each residual has at the
    optimum of ½Σρ(r²), as in iteratively reweighted least squares (1 for the linear loss)."""
    if loss == "soft_l1":
        return 1.0 / np.sqrt(1.0 + z)
    if loss == "huber":
        return np.where(z <= 1.0, 1.0, 1.0 / np.sqrt(np.maximum(z, 1.0)))
    if loss == "cauchy":
        return 1.0 / (1.0 + z)
    if loss == "arctan":
        return 1.0 / (1.0 + z * z)
    return np.ones_like(z)


def conclude(
    search: Search,
    u: FloatArray,
    floors: Mapping[str, float],
    spreads: Mapping[str, float],
    *,
    converged: bool,
    interrupted: bool,
    message: str,
    mirror_blind: bool,
    planar: bool,
    mirror_told: str = "",
    n_starts: int,
) -> FitResult:
    """The polish, the error analysis (identify.py) with the goodness of fit (goodness.py), the
    warnings, and the :class:`FitResult`."""
    problem, free, sig = search.problem, search.free, search.sigma
    stopped: list[str] = []  # the steps Ctrl-C cut short (module doc)
    u, r, jac, positive = _polished(search, u, interrupted, stopped)
    final = problem.with_free(u)
    n_res, k = r.size, len(free)
    dof = max(n_res - k, 1)
    if search.loss != "linear":  # the robust loss's weights (IRLS): outliers leave the error analysis
        w = np.sqrt(robust_weights(search.loss, r * r))
        r, jac = r * w, jac * w[:, None]
    chi2 = float(r @ r)
    obs = problem.obs
    sigma_known = all(s is not None for s in obs.sigma.values())
    variance = 1.0 if sigma_known else chi2 / dof
    pred = problem.predictions(final)
    checks = {
        kind: check_kind(obs.t, residual(kind, obs.values[kind], pred[kind]), floors[kind], spreads[kind])
        for kind in obs.values
    }
    logged = {n for i, n in enumerate(free) if positive[i]}
    ident = _identified(search, final, (r, jac), variance, logged, checks)
    if search.bars_late:  # the late Jacobian did not fit in LATE_SECONDS: no error bars at all
        ident.reasons.update(dict.fromkeys(free, LATE_REASON))
    misfit = chi2  # Σ r² in units of the search's σ (the data's own floor when σ is not given)
    chi2 /= variance  # with σ estimated from the residual, χ²/dof = 1 by construction
    # with σ given, χ² against its distribution (widened for a residual that is AR(1) noise)
    chi2_p = chi2_tails(chi2, dof, ar1_rho(checks))[0] if sigma_known else None
    cut = ("searchCtrlC" if "Ctrl-C" in message else "searchTimeLimit") if interrupted else ""
    said, dropped = _said(checks, chi2_p, chi2, dof, search.loss != "linear", cut)
    # a misfit: the record's blocks fitted on their own, the error bars widened by their disagreement
    blocks = None
    if misfit_found(checks, chi2_p):
        blocks = _blocks(search, final, ident, sigma_known, cut, stopped)
    said += blocks.findings() if blocks is not None else []
    if cut and blocks is None and (dropped or misfit_found(checks, chi2_p)):  # no block check was due
        limit = search.clock.time_limit
        said.append(UNMADE[cut].format(seconds=f"{limit:g}" if limit else "", blocks=0))
    g_fit = final["g"]
    if "g" in free and ident.determined["g"] and not 0.01 <= abs(g_fit) <= 1000.0:
        said.append(
            f"the fitted g = {g_fit:.4g} m/s² is far from any planet's (Earth 9.81): are the data in SI "
            "units (positions in m, not mm or pixels; times in s; angles in rad)?"
        )
    goodness = Goodness(checks, chi2_p, {n: ident.inflation.get(n, 1.0) for n in free}, said)
    res = FitResult.build(
        problem=problem,
        values=final,
        predictions=pred,
        sigma={
            k: (given if (given := obs.sigma[k]) is not None else sig[k] * math.sqrt(variance))
            for k in obs.values
        },
        sigma_estimated=not sigma_known,
        chi2=chi2,
        dof=dof,
        ident=ident,
        converged=converged,
        message=message if message else "interrupted",
        seconds=search.clock.elapsed(),
        starts=n_starts,
        interrupted=interrupted,
        kinds=KINDS,
        mirror_blind=mirror_blind,
        goodness=goodness,
        bounds={n: (float(search.lower[i]), float(search.upper[i])) for i, n in enumerate(free)},
        planar=planar,
        misfit=misfit,
        search_sigma=dict(sig),
        variance=variance,
        blocks=blocks,
    )
    # a record shorter than a swing: the profile likelihood checks the bars of the length and g
    checkable = not interrupted and not stopped and search.loss == "linear"
    said += check_short_record(res, search, checkable, ctrl_c=bool(stopped))
    # data blind to the mirror y -> -y near the plane: the profile likelihood gives φ₀'s and φ̇₀'s bars
    said += check_mirror(res, search, checkable, ctrl_c=bool(stopped))
    # x, z data and a model the mirror is no symmetry of: does the term that breaks it tell the sign?
    said += check_sign(res, search, mirror_told, checkable, ctrl_c=bool(stopped))
    # stopped short anywhere (Ctrl-C, or a step the time limit cut or skipped): some results incomplete
    res.interrupted = interrupted or bool(stopped) or search.clock.ctrl_c or search.clock.ran_out
    unsaid = [s for s in stopped if not (s == IN_BLOCKS and blocks is not None)]  # its finding says it
    if unsaid:
        warn_user(f"Ctrl-C stopped {' and '.join(unsaid)}: returning the fit without it", RuntimeWarning)
    for text in said:
        warn_user(text, UserWarning)
    if not converged and not interrupted:
        warn_user(f"the fit did not converge ({message}); the values are the best reached", RuntimeWarning)
    return res


def _said(
    checks: Mapping[str, Any], chi2_p: float | None, chi2: float, dof: int, robust: bool, cut: str
) -> tuple[list[str], bool]:
    """goodness.findings, and whether any were left out: where the time limit or Ctrl-C cut the search
    (``cut`` a key of blocks.UNMADE, "" if it ran to its end) without those that put a misfit down to
    the model, the noise or the start (:data:`CUT_VERDICTS`' kinds, an improbable χ²): the values are
    short of the best fit, so the misfit may be the search's, and one finding (UNMADE[cut]) says so."""
    if not cut:
        return findings(checks, chi2_p, chi2, dof, robust=robust), False
    kept = {k: c for k, c in checks.items() if c.verdict(robust) not in CUT_VERDICTS}
    chi2_kept = None if chi2_p is not None and chi2_p < P_ALARM and not robust else chi2_p
    return findings(kept, chi2_kept, chi2, dof, robust=robust), len(kept) < len(checks) or chi2_kept != chi2_p


def _polished(
    search: Search, u: FloatArray, interrupted: bool, stopped: list[str]
) -> tuple[FloatArray, FloatArray, FloatArray, Any]:
    """The optimum ``u`` after the Gauss–Newton polish (search.py; not after an interruption nor with a
    robust loss; Ctrl-C in it keeps the search's ``u`` and is noted in ``stopped``), its weighted
    residual r [1], the Jacobian of r (exact forward sensitivities where the core has them, else
    difference quotients: central, forward once the time limit has passed, so that the overrun is one
    run of the whole record per unknown, not two), and which unknowns took logarithmic steps."""
    problem, free, sig = search.problem, search.free, search.sigma

    def weighted(uu: FloatArray) -> FloatArray:
        return problem.residuals(problem.with_free(uu), sig)

    began = search.clock.elapsed()
    r = weighted(u)
    run = search.clock.elapsed() - began  # one run of the whole record [s]: the late Jacobian's unit
    # logarithmic steps for positive parameters well away from 0 (a damping at its bound 0 gets
    # additive ones, one-sided there: jacobian())
    positive = np.array([n in POSITIVE and u[i] > 0.01 * search.scales[i] for i, n in enumerate(free)])
    steps = np.where(positive, 1e-5, search.scales * 1e-5)

    def jac_of(uu: FloatArray) -> FloatArray | None:
        return search.exact_jacobian(problem, uu)  # forward sensitivities (sensitivity.py) or None

    exact = jac_of(u)
    # past the time limit, forward differences: k runs of the whole record instead of 2k, and only
    # while each ends within LATE_SECONDS of the limit (docs/fit.md, "The time limit")
    late = exact is None and search.time_up()
    if exact is not None:
        jac = exact
    elif not late:
        jac = jacobian(weighted, u, steps, positive)
    else:
        jac = _late_jacobian(search, weighted, u, (steps, positive), r, run)
    if search.loss == "linear" and not interrupted:
        bounds = (search.lower, search.upper)
        try:
            u, r, jac = polish(weighted, u, r, jac, steps, positive, *bounds, search.time_up, jac_of)
        except KeyboardInterrupt:
            stopped.append("the polish")
    return u, r, jac, positive


def _late_jacobian(
    search: Search,
    weighted: Callable[[FloatArray], FloatArray],
    u: FloatArray,
    steps: tuple[FloatArray, FloatArray],
    r: FloatArray,
    run: float,
) -> FloatArray:
    """The Jacobian past the time limit: forward differences from ``r`` (identify.jacobian's
    ``centre``), each model run begun only if, at ``run`` [s] per run (the last run of the whole
    record), it ends within :data:`search.LATE_SECONDS` of the limit. Otherwise none of it: a
    Jacobian with columns missing would give the others' bars as if those parameters were held, so
    every column is NaN, ``search.bars_late`` is set, and each parameter gets :data:`LATE_REASON`."""

    def bounded(uu: FloatArray) -> FloatArray:
        if search.clock.late_time_up(run):
            raise TimeUp
        return weighted(uu)

    try:
        return jacobian(bounded, u, steps[0], steps[1], r)
    except TimeUp:
        search.bars_late = True
        return np.full((r.size, len(search.free)), math.nan)


def _blocks(
    search: Search,
    final: Mapping[str, float],
    ident: Identifiability,
    known: bool,
    cut: str,
    stopped: list[str],
) -> BlockCheck | None:
    """The block check of a misfit (blocks.py; ``known``: σ given), None where none can be made; where
    it is due but the fit was stopped short a :class:`BlockCheck` that says it was not made and why
    (blocks.UNMADE): ``cut`` the search ("searchTimeLimit", "searchCtrlC"; "" if it ran to its end),
    so the misfit may be the search's; Ctrl-C before it (``stopped``: the polish); the time limit
    before it or in it; Ctrl-C in it (:data:`IN_BLOCKS` added to ``stopped``)."""
    values = dict(final)
    if cut or stopped:
        return not_made(search, values, ident, cut or "ctrlC")
    try:
        return check_blocks(search, values, ident, known)
    except KeyboardInterrupt:
        stopped.append(IN_BLOCKS)
        return not_made(search, values, ident, "ctrlCIn")
    except TimeUp:
        return not_made(search, values, ident, "timeLimit")


def _identified(
    search: Search,
    final: Mapping[str, float],
    fitted: tuple[FloatArray, FloatArray],
    variance: float,
    logged: set[str],
    checks: Mapping[str, Any],
) -> Identifiability:
    """The covariance and what the data determine (identify.py) from the weighted residual and its
    Jacobian ``fitted`` = (r, J), widened for correlated residuals (Newey–West, goodness.py) unless the
    fit is exact to round-off, which has no statistics."""
    r, jac = fitted
    obs = search.problem.obs
    lag1 = max((c.lag1 for c in checks.values()), default=0.0)
    sample = np.concatenate([np.repeat(np.arange(len(obs)), obs.columns[kind]) for kind in obs.values])
    exact = all(c.spread > 0.0 and c.rms <= EXACT * c.spread for c in checks.values())
    correlation = None if exact else Correlation(r, sample, len(obs), lag1)  # round-off has no statistics
    return analyse(search.free, final, jac, variance, logged, correlation)
