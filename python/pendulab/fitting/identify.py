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
covariance is the pseudo-inverse on the determined subspace.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from .._core import IntegrationError, InvalidInputError
from ..model import FloatArray

SINGULAR = 1e-4
"""Relative singular value below which a direction of parameter space is not determined."""


@dataclass
class Identifiability:
    """The covariance [units of the parameters] of the free parameters, which are determined, and the
    combinations the data determine where single parameters are not (name → (value, stderr))."""

    covariance: FloatArray
    determined: dict[str, bool]
    combinations: dict[str, tuple[float, float]] = field(default_factory=dict)
    singular_values: FloatArray = field(default_factory=lambda: np.zeros(0))


def jacobian(
    residuals: Callable[[FloatArray], FloatArray],
    u: FloatArray,
    steps: FloatArray,
    logged: FloatArray | None = None,
) -> FloatArray:
    """Central differences of ``residuals`` at ``u`` (error O(h²)), in parameter units. Where
    ``logged`` is True the step is multiplicative, u·e^{±h}: equal steps in ln p for every positive
    parameter, so that an exact scale symmetry (g and l together) gives exactly dependent columns."""
    columns = []
    centre: FloatArray | None = None
    for k, h in enumerate(steps):
        up, down = u.copy(), u.copy()
        if logged is not None and logged[k]:
            up[k], down[k] = u[k] * math.exp(h), u[k] * math.exp(-h)
        else:
            up[k], down[k] = u[k] + h, u[k] - h
        r_up, r_down = _try(residuals, up), _try(residuals, down)
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
    names: Sequence[str], values: Mapping[str, float], jac: FloatArray, variance: float, positive: set[str]
) -> Identifiability:
    """The analysis of the module doc for the Jacobian ``jac`` (columns in parameter units) of the
    σ-weighted residuals; ``variance`` multiplies the covariance (1 when σ is known)."""
    k = len(names)
    p = np.array([values[n] for n in names], dtype=np.float64)
    log = np.array([n in positive and p[i] > 0.0 for i, n in enumerate(names)])
    # z: per unit of ln p (positive parameters) or of a typical size; y: z times the column norms
    size = np.where(log, p, np.maximum(np.abs(p), 1.0))
    jz = jac * size
    norms = np.linalg.norm(jz, axis=0)
    norms = np.where(norms > 0.0, norms, 1.0)
    _, s, vt = np.linalg.svd(jz / norms, full_matrices=False)
    cut = SINGULAR * (s[0] if s.size and s[0] > 0.0 else 1.0)
    keep = s > cut
    cov_y = (vt[keep].T / s[keep] ** 2) @ vt[keep]
    cov_z = cov_y / np.outer(norms, norms)
    cov = variance * cov_z * np.outer(size, size)
    # a parameter that barely moves the residuals (a symmetry the data cannot see, such as φ₀ for
    # frame-free data): its column is negligible before normalisation
    raw = np.linalg.norm(jz, axis=0)
    undetermined: set[int] = {int(i) for i in np.flatnonzero(raw <= SINGULAR * max(float(raw.max()), 1e-300))}
    combos: dict[str, tuple[float, float]] = {}
    for n_y in vt[~keep]:
        n_z = n_y / norms
        n_z = n_z / np.max(np.abs(n_z))
        involved = [int(i) for i in np.flatnonzero(np.abs(n_z) > 0.05)]
        undetermined |= set(involved)
        if len(involved) == 2 and all(log[i] for i in involved):
            a, b = involved
            if names[a] == "length":  # say g/length, the squared angular frequency, not its inverse
                a, b = b, a
            e = float(n_z[a] / n_z[b])
            w = np.zeros(k)
            w[a], w[b] = 1.0, -e
            value = float(p[a] / p[b] ** e)
            err = value * math.sqrt(max(float(variance * (w @ cov_z @ w)), 0.0))
            if abs(e - 1.0) < 1e-3:
                label = f"{names[a]}/{names[b]}"
            elif abs(e + 1.0) < 1e-3:
                label = f"{names[a]}*{names[b]}"
            else:
                label = f"{names[a]}/{names[b]}^{e:.4g}"
            combos[label] = (value, err)
    for i in undetermined:
        cov[i, :] = math.nan
        cov[:, i] = math.nan
        cov[i, i] = math.inf
    determined = {n: i not in undetermined for i, n in enumerate(names)}
    return Identifiability(cov, determined, combos, s)
