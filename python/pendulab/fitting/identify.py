"""Which parameters the data determine, and how well: the linearised least-squares analysis at the
best fit (docs/theory.md, "Fitting").

With r(p) the residuals divided by the noise σ and J = ∂r/∂p at the optimum, the covariance of the
estimate is C = (JᵀJ)⁻¹ (times the residual variance s² = χ²/(N − k) when σ was not given). The
Jacobian is taken in logarithmic coordinates for strictly positive parameters (l, g > 0, m, c > 0, …),
where a scale symmetry shows up as an exact linear dependence: angles alone depend on g and l only
through g/l (T-2.5), so ∂r/∂ln g = −∂r/∂ln l. The singular value decomposition of the column-scaled J
finds such directions (singular values below 1e-4 of the largest: columns that collinear leave the
combination 10⁴ times less certain than the rest, which the data then cannot separate; Jacobian steps
are equal in ln p, so an exact symmetry gives exactly dependent columns): their parameters are
reported as not determined, with the combination that is (e.g. g/length and its error), and the
covariance of the determined parameters is computed with the undetermined ones free, not held
(:func:`_free_of`: each determined column less its projection on theirs; holding g and l of angles
held g/l and left θ̇₀'s bar 1.4x too narrow, 34 of 40 seeds within 2 bars). A parameter with a share in a cut
direction above 1 % (in column-normalised units) is not determined: along that direction its variance
is unbounded, and leaving it in would drop the direction silently and understate the others' errors.
Before the decomposition, parameters whose column is negligible (≤ 1e-4 of the largest: a symmetry the
data cannot see, or a stationary point such as a sideways rate of 0 seen from the side) are taken out,
so that their normalised noise cannot stand in for a real direction. Every undetermined parameter
carries its reason. Correlated residuals widen the error bars (Newey–West, goodness.py; T-10.5).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from .._core import IntegrationError, InvalidInputError
from ..model import FloatArray
from .goodness import inflation

SINGULAR = 1e-4
"""Relative singular value below which a direction of parameter space is not determined."""

INVOLVED = 0.01
"""A parameter whose share (in column-normalised units) of a cut direction exceeds this is reported as
not determined: along that direction its variance is unbounded."""

COMBINED = "the data determine only a combination of it with "
"""The reason of a parameter in a direction the data cannot see (server/fit_words.py keys it)."""

FLAT = "the residuals do not change with it at the fit"
"""The start of the reason of a parameter whose column is negligible (server/fit_words.py keys it)."""

ROUND_OFF = 1e-10
"""Directions of the undetermined parameters' columns above this share of their largest singular value
are projected out of the determined ones' (:func:`_free_of`); below it, round-off of the columns."""


@dataclass
class Correlation:
    """What the Newey–West widening needs (goodness.py): the σ-weighted residual, the sample index of
    each residual row, the number of samples and the residual's lag-1 autocorrelation."""

    residual: FloatArray
    sample: FloatArray
    samples: int
    lag1: float


@dataclass
class Identifiability:
    """The covariance [units of the parameters] of the free parameters, which are determined, and the
    combinations the data determine where single parameters are not (name → (value, stderr))."""

    covariance: FloatArray
    determined: dict[str, bool]
    combinations: dict[str, tuple[float, float]] = field(default_factory=dict)
    singular_values: FloatArray = field(default_factory=lambda: np.zeros(0))
    reasons: dict[str, str] = field(default_factory=dict)
    inflation: dict[str, float] = field(default_factory=dict)


def jacobian(
    residuals: Callable[[FloatArray], FloatArray],
    u: FloatArray,
    steps: FloatArray,
    logged: FloatArray | None = None,
    centre: FloatArray | None = None,
) -> FloatArray:
    """Central differences of ``residuals`` at ``u`` (error O(h²)), in parameter units. Where
    ``logged`` is True the step is multiplicative, u·e^{±h}: equal steps in ln p for every positive
    parameter, so that an exact scale symmetry (g and l together) gives exactly dependent columns.
    Given ``centre`` = residuals(u), forward differences instead (error O(h), one run per column, not
    two: inference.py's Jacobian after the time limit), backward where the model refuses the step."""
    columns = []
    forward = centre is not None
    for k, h in enumerate(steps):
        up, down = u.copy(), u.copy()
        if logged is not None and logged[k]:
            up[k], down[k] = u[k] * math.exp(h), u[k] * math.exp(-h)
        else:
            up[k], down[k] = u[k] + h, u[k] - h
        r_up = _try(residuals, up)
        if forward and centre is not None and r_up is not None:  # forward: one run
            columns.append((r_up - centre) / (up[k] - u[k]))
            continue
        r_down = _try(residuals, down)
        width = up[k] - down[k]
        if r_up is None or r_down is None:  # the model refuses one side (a limit): one-sided there
            if centre is None:
                centre = residuals(u)
            if r_up is not None:
                r_down, width = centre, up[k] - u[k]
            elif r_down is not None:
                r_up, width = centre, u[k] - down[k]
            else:
                r_up, r_down, width = centre, centre, 1.0  # no information: a zero column
        columns.append((r_up - r_down) / width)
    return np.column_stack(columns)


def _try(residuals: Callable[[FloatArray], FloatArray], u: FloatArray) -> FloatArray | None:
    try:
        return residuals(u)
    except (InvalidInputError, IntegrationError):
        return None


def analyse(
    names: Sequence[str],
    values: Mapping[str, float],
    jac: FloatArray,
    variance: float,
    positive: set[str],
    correlation: Correlation | None = None,
) -> Identifiability:
    """The analysis of the module doc for the Jacobian ``jac`` (columns in parameter units) of the
    σ-weighted residuals; ``variance`` multiplies the covariance (1 when σ is known); ``correlation``
    (the residual and its sample index) widens the error bars for correlated residuals (goodness.py)."""
    k = len(names)
    p = np.array([values[n] for n in names], dtype=np.float64)
    log = np.array([n in positive and p[i] > 0.0 for i, n in enumerate(names)])
    reasons: dict[str, str] = {}
    cov = np.full((k, k), math.nan)
    if not np.all(np.isfinite(jac)):  # a model run that overflowed: no linear algebra on it
        bad = np.flatnonzero(~np.all(np.isfinite(jac), axis=0))
        for i in bad.tolist():
            reasons[names[i]] = "the model's response to it is not finite at the fit"
        jac = np.where(np.isfinite(jac), jac, 0.0)
    # z: per unit of ln p (positive parameters) or of a typical size; y: z times the column norms
    size = np.where(log, p, np.maximum(np.abs(p), 1.0))
    jz = jac * size
    raw = np.linalg.norm(jz, axis=0)
    # a parameter that barely moves the residuals (a symmetry the data cannot see, such as φ₀ for
    # frame-free data, or a stationary point such as φ̇₀ = 0 seen from the side): out of the analysis
    # before the others are normalised, so that its noise cannot stand in for a real weak direction
    flat = raw <= SINGULAR * max(float(raw.max()) if raw.size else 0.0, 1e-300)
    for i in np.flatnonzero(flat).tolist():
        reasons.setdefault(
            names[i],
            FLAT + " (a symmetry of the data, or a stationary point such as a sideways rate of 0 seen "
            "from the side)",
        )
    live = np.flatnonzero(~flat)
    combos: dict[str, tuple[float, float]] = {}
    s = np.zeros(0)
    if live.size:
        norms = raw[live]
        _, s, vt = np.linalg.svd(jz[:, live] / norms, full_matrices=False)
        cut = SINGULAR * (s[0] if s.size and s[0] > 0.0 else 1.0)
        keep = s > cut
        # every parameter with a share in a direction the data cannot see is not determined alone
        for n_y in vt[~keep]:
            involved = [int(live[i]) for i in np.flatnonzero(np.abs(n_y) > INVOLVED)]
            for i in involved:
                reasons.setdefault(
                    names[i],
                    COMBINED + ", ".join(names[j] for j in involved if j != i),
                )
            combo = _combination(names, p, log, live, n_y / norms, vt[keep], s[keep], norms, variance)
            if combo is not None:
                combos[combo[0]] = combo[1]
        sub, free_jz, cov_y = _free_of(names, live, jz, raw, cut, reasons)
        if sub.size:
            scale = size[sub] / raw[sub]
            cov[np.ix_(sub, sub)] = variance * cov_y * np.outer(scale, scale)
            jac = jac.copy()
            jac[:, sub] = free_jz / size[sub]  # the sandwich of the same estimator (undetermined free)
    widen = np.ones(k)
    determined_idx = np.array([names[i] not in reasons for i in range(k)])
    if correlation is not None and determined_idx.any():
        widen = inflation(
            jac,
            correlation.residual,
            correlation.sample,
            correlation.samples,
            correlation.lag1,
            np.where(np.isfinite(cov), cov, 0.0),
            determined_idx,
        )
        cov = cov * np.outer(widen, widen)
    for i in range(k):
        if names[i] in reasons:
            cov[i, :] = math.nan
            cov[:, i] = math.nan
            cov[i, i] = math.inf
    determined = {n: n not in reasons for n in names}
    return Identifiability(
        cov, determined, combos, s, reasons, {n: float(widen[i]) for i, n in enumerate(names)}
    )


def _free_of(
    names: Sequence[str],
    live: npt.NDArray[np.intp],
    jz: FloatArray,
    raw: FloatArray,
    cut: float,
    reasons: dict[str, str],
) -> tuple[npt.NDArray[np.intp], FloatArray, FloatArray]:
    """The determined parameters among ``live`` with the undetermined ones FREE, not held: each
    determined column of ``jz`` less its projection on the span of the undetermined columns, so that
    (J̃ᵀJ̃)⁻¹ is the covariance of the determined ones whatever the others do (the Schur complement;
    holding g and l of angles held g/l and left θ̇₀'s bar 1.4x too narrow). A determined column that
    the projection leaves in a direction below ``cut`` (normalised by its own norm ``raw`` before the
    projection) is a combination of the undetermined ones: not determined either (``reasons`` is
    extended), and the projection is repeated. Returns the determined indices, their projected
    columns [per unit of z] and the covariance in column-normalised units."""
    while True:
        undetermined = np.array([i for i in live.tolist() if names[i] in reasons], dtype=np.intp)
        sub = np.array([i for i in live.tolist() if names[i] not in reasons], dtype=np.intp)
        if not sub.size:
            return sub, np.zeros((jz.shape[0], 0)), np.zeros((0, 0))
        js = jz[:, sub]
        if undetermined.size:
            u, su, _ = np.linalg.svd(jz[:, undetermined] / raw[undetermined], full_matrices=False)
            q = u[:, su > ROUND_OFF * su[0]]
            js = js - q @ (q.T @ js)
        _, s2, vt2 = np.linalg.svd(js / raw[sub], full_matrices=False)
        weak = s2 <= cut
        if not weak.any():
            return sub, js, (vt2.T / s2**2) @ vt2
        for n_y in vt2[weak]:
            involved = [int(sub[i]) for i in np.flatnonzero(np.abs(n_y) > INVOLVED)]
            for i in involved:
                with_ = [names[j] for j in involved if j != i] + [names[j] for j in undetermined.tolist()]
                reasons.setdefault(names[i], COMBINED + ", ".join(with_))


def _combination(
    names: Sequence[str],
    p: FloatArray,
    log: npt.NDArray[np.bool_],
    live: npt.NDArray[np.intp],
    n_z_live: FloatArray,
    vt_keep: FloatArray,
    s_keep: FloatArray,
    norms: FloatArray,
    variance: float,
) -> tuple[str, tuple[float, float]] | None:
    """For a cut direction between two positive parameters (a scale symmetry such as g and l seen
    through angles alone), the power-law combination p_a / p_b^e the data do determine, with its error
    from the covariance on the determined directions."""
    n_z = np.zeros(len(names))
    n_z[live] = n_z_live
    n_z = n_z / np.max(np.abs(n_z))
    involved = [int(i) for i in np.flatnonzero(np.abs(n_z) > 0.05)]
    if len(involved) != 2 or not all(log[i] for i in involved):
        return None
    a, b = involved
    if names[a] == "length":  # say g/length, the squared angular frequency, not its inverse
        a, b = b, a
    e = float(n_z[a] / n_z[b])
    w = np.zeros(len(names))
    w[a], w[b] = 1.0, -e
    cov_y = (vt_keep.T / s_keep**2) @ vt_keep
    cov_z_live = cov_y / np.outer(norms, norms)
    wl = w[live]
    value = float(p[a] / p[b] ** e)
    err = value * math.sqrt(max(float(variance * (wl @ cov_z_live @ wl)), 0.0))
    if abs(e - 1.0) < 1e-3:
        label = f"{names[a]}/{names[b]}"
    elif abs(e + 1.0) < 1e-3:
        label = f"{names[a]}*{names[b]}"
    else:
        label = f"{names[a]}/{names[b]}^{e:.4g}"
    return label, (value, err)
