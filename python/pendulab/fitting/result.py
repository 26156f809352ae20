"""The result of :func:`pendulab.fit`: best values with standard errors (SI units), covariance and
correlation, residuals per data kind, the fitted pendulum, start and trajectory, what the data could
not determine, a text report, a figure, and the fitted scenario as a file ``pendulab run`` and the lab
accept. The statistics of the result are here (AIC, BIC, linearised and profile intervals: T-10.2);
the text report, the HTML rows and the figure are written by :mod:`pendulab.fitting.report`."""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..model import FloatArray, Pendulum, State
from ..trajectory import Trajectory
from ..variants.spring import SpringTrajectory, SwingingSpring
from .data import residual
from .goodness import Goodness
from .identify import Identifiability
from .problem import STATE_NAMES, unit_of
from .report import _COLUMN_NAMES as _COLUMN_NAMES
from .report import fit_figure, report_html, report_text

if TYPE_CHECKING:
    from ..scenario import Scenario
    from .problem import Problem


@dataclass
class FitResult:
    """See the module doc. ``params``/``stderr``: name → value / standard error for every FITTED
    parameter (stderr is inf for one the data do not determine: see ``determined`` and
    ``combinations``); ``fixed``: the values held fixed; ``covariance``, ``correlation``: (k, k) in the
    order of ``names``; ``residuals``: kind → measured − fitted (N, columns) in the data's unit;
    ``chi2`` = Σ r², ``dof`` = values − unknowns, ``sigma``: the noise per kind (given or estimated);
    ``mirror_blind``: the data cannot tell the motion from its mirror image y → −y (positions seen as
    x, z; a phone's frame-free scalars) and the model is symmetric under it (not a rotating frame with
    Ω_z ≠ 0 or a pivot moving along y: fitting/mirror_sign.py), so the sign of φ₀ and φ̇₀ is a
    choice. ``mirror_sign``: where the data are blind to y but the model is not symmetric (a held term
    breaks the mirror), whether the data tell the sign of φ₀, φ̇₀ and by how much the mirror image's
    misfit rises (fitting/mirror_sign.py's ``SignCheck``; ``line()`` the report's sentence), else None.
    ``goodness``: whether
    the fitted motion explains the data (residual against the noise floor, autocorrelation, runs, χ²
    probability, outliers) with its plain-language ``findings``; ``reasons``: why each undetermined
    parameter is; ``inflation``: the factor each error bar was widened by for correlated residuals;
    ``bounds``: each fitted parameter's allowed range (see :meth:`interval`); ``planar``: fitted as a
    hinge (φ₀ = φ̇₀ = 0 held). ``interrupted``: the fit was stopped short — by Ctrl-C or its
    ``time_limit`` — so some results are incomplete: stopped in the search, the values are the best
    reached (``converged`` False, ``message`` says why); in the error analysis, the values are the
    search's, the parameters whose profiles were cut are not determined (``reasons`` name Ctrl-C or
    the limit), Ctrl-C in the polish or the block check is warned and after the limit both are skipped."""

    names: list[str]
    params: dict[str, float]
    stderr: dict[str, float]
    units: dict[str, str]
    fixed: dict[str, float]
    covariance: FloatArray
    correlation: FloatArray
    determined: dict[str, bool]
    combinations: dict[str, tuple[float, float]]
    residuals: dict[str, FloatArray]
    t: FloatArray
    pendulum: Pendulum | SwingingSpring
    state0: State
    t0: float
    chi2: float
    dof: int
    sigma: dict[str, float]
    sigma_estimated: bool
    converged: bool
    message: str
    evaluations: int
    seconds: float
    starts: int
    interrupted: bool = False
    dropped: int = 0
    mirror_blind: bool = False
    goodness: Goodness | None = None
    reasons: dict[str, str] = field(default_factory=dict)
    inflation: dict[str, float] = field(default_factory=dict)
    bounds: dict[str, tuple[float, float]] = field(default_factory=dict)
    planar: bool = False
    misfit: float = math.nan
    #: A compound pendulum's geometry, pivot torques and implied part position (body.py), or None.
    body: Any = None
    #: The block check (blocks.py): the record's consecutive blocks fitted on their own and the
    #: scale factors the error bars were widened by, when the fit missed the data; a check with
    #: ``made`` False (its ``unmade`` says why: the time limit or Ctrl-C; ``stop`` its key; ``scale``
    #: NaN for each parameter it would have compared: not measured, not widened) when it should have
    #: run but did not, so the bars are not checked; else None (no misfit, or a check that does not apply).
    blocks: Any = None
    mirror_sign: Any = None
    _problem: Any = field(default=None, repr=False)
    _search_sigma: dict[str, float] = field(default_factory=dict, repr=False)
    _variance: float = field(default=1.0, repr=False)

    @classmethod
    def build(
        cls,
        *,
        problem: Problem,
        values: dict[str, float],
        sigma: dict[str, float],
        sigma_estimated: bool,
        chi2: float,
        dof: int,
        ident: Identifiability,
        converged: bool,
        message: str,
        seconds: float,
        starts: int,
        interrupted: bool,
        kinds: dict[str, str],
        mirror_blind: bool = False,
        goodness: Goodness | None = None,
        bounds: dict[str, tuple[float, float]] | None = None,
        planar: bool = False,
        misfit: float = math.nan,
        search_sigma: dict[str, float] | None = None,
        variance: float = 1.0,
        predictions: dict[str, FloatArray] | None = None,
        blocks: Any = None,
    ) -> FitResult:
        names = list(problem.free)
        cov = ident.covariance
        err = np.sqrt(np.where(np.isfinite(np.diag(cov)), np.diag(cov), np.inf))
        with np.errstate(invalid="ignore", divide="ignore"):
            corr = cov / np.outer(err, err)
        pendulum = problem.pendulum(values)
        state0 = problem.state0(pendulum, values)
        pred = problem.predictions(values) if predictions is None else predictions  # one model run
        res = {k: residual(k, problem.obs.values[k], pred[k]) for k in problem.obs.values}
        own = [n for n in values if n not in names]
        return cls(
            names=names,
            params={n: values[n] for n in names},
            stderr={n: float(e) for n, e in zip(names, err, strict=True)},
            units={n: unit_of(problem.model, n) for n in values},
            fixed={n: values[n] for n in own},
            covariance=cov,
            correlation=corr,
            determined=ident.determined,
            combinations=ident.combinations,
            residuals=res,
            t=problem.obs.t,
            pendulum=pendulum,
            state0=state0,
            t0=problem.t0,
            chi2=chi2,
            dof=dof,
            sigma=sigma,
            sigma_estimated=sigma_estimated,
            converged=converged,
            message=message,
            evaluations=problem.evaluations,
            seconds=seconds,
            starts=starts,
            interrupted=interrupted,
            dropped=problem.obs.dropped,
            mirror_blind=mirror_blind,
            goodness=goodness,
            reasons=dict(ident.reasons),
            inflation=dict(ident.inflation),
            bounds=dict(bounds or {}),
            planar=planar,
            misfit=misfit,
            blocks=blocks,
            _problem=problem,
            _search_sigma=dict(search_sigma or {}),
            _variance=variance,
        )

    @property
    def model(self) -> str:
        """The fitted model's name (``pl.models()``)."""
        return str(self._problem.model)

    @property
    def trajectory(self) -> Trajectory | SpringTrajectory:
        """The fitted motion at the data times (model time 0 at the first sample, t₀ [s]); for the
        spring a :class:`pendulab.SpringTrajectory` with its energy [J] and J₃ [kg m²/s]."""
        p, x, v, tau = self._problem.motion({**self.fixed, **self.params})
        if isinstance(p, SwingingSpring):
            r = np.linalg.norm(x, axis=1)
            m = p.mass
            energy = 0.5 * m * np.einsum("ij,ij->i", v, v) + m * p.g * x[:, 2]
            energy += 0.5 * m * p.k_over_m * (r - p.rest_length) ** 2
            j3 = m * (x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0])
            return SpringTrajectory(p, tau, x, v, energy, j3, {"model": "spring", "t0": self.t0})
        assert isinstance(p, Pendulum)
        return Trajectory(p, tau, x, v, "fit", {"t0": self.t0}, {"steps": 0, "samples": len(tau)})

    @property
    def _defaults(self) -> dict[str, float]:
        from .problem import model_params

        return {n: float(spec["default"]) for n, spec in model_params(self.model).items()}

    @property
    def aic(self) -> float:
        """Akaike's information criterion of this fit, for comparing models fitted to the same data
        (smaller is better; docs/fit.md "Which dissipation law"): χ² + 2k with σ given, otherwise
        n ln(S/n) + 2k with S the sum of squared residuals in units of the data's noise floor."""
        return self._deviance + 2.0 * len(self.names)

    @property
    def bic(self) -> float:
        """The Bayesian (Schwarz) information criterion: as :attr:`aic` with k ln n for 2k."""
        return self._deviance + len(self.names) * math.log(self.dof + len(self.names))

    @property
    def _deviance(self) -> float:
        n = self.dof + len(self.names)
        if not self.sigma_estimated:
            return self.chi2
        return n * math.log(max(self.misfit, 1e-300) / n)

    @property
    def reduced_chi2(self) -> float:
        """χ²/dof: about 1 when the model explains the data to their noise."""
        return self.chi2 / self.dof

    @property
    def findings(self) -> list[str]:
        """What looks wrong with the fit, in plain words (empty when nothing does; each was warned)."""
        return list(self.goodness.findings) if self.goodness is not None else []

    def interval(self, name: str, level: float = 0.95) -> tuple[float, float]:
        """The linearised confidence interval of a fitted parameter [its unit] at ``level`` (0.95: ±1.96
        standard errors), clipped to its allowed range: one-sided where the value sits at or near a
        bound (e.g. a damping of 0), (−inf, inf) where the data do not determine it."""
        from statistics import NormalDist

        if name not in self.params:
            raise KeyError(f"{name!r} was not fitted; fitted: {', '.join(self.names)}")
        if not (isinstance(level, float | int) and 0.0 < level < 1.0):
            raise ValueError(f"level = {level!r} must be between 0 and 1")
        if not self.determined[name]:
            return (-math.inf, math.inf)
        half = NormalDist().inv_cdf(0.5 + level / 2.0) * self.stderr[name]
        lo, hi = self.bounds.get(name, (-math.inf, math.inf))
        value = self.params[name]
        return (max(value - half, lo), min(value + half, hi))

    def profile(self, name: str, level: float = 0.95, max_refits: int = 40) -> tuple[float, float]:
        """The profile-likelihood interval of a fitted parameter [its unit] at ``level``: where the
        misfit, minimised over all other unknowns with ``name`` held, has risen by the χ²(1) quantile
        (3.84 at 0.95) in units of the noise (profile.py). Unlike :meth:`interval` it follows a curved
        or one-sided valley; each side costs up to ``max_refits``/2 refits. An end the misfit never
        rises enough to reach (a bound, or a parameter the data do not determine) is ±inf or the bound."""
        from .profile import profile_interval

        return profile_interval(self, name, level, max_refits)

    def report(self) -> str:
        """A table of the fitted parameters ± standard errors (SI units), the combinations the data
        determine where single parameters are not, χ², the noise, what was held fixed, convergence."""
        return report_text(self)

    def __repr__(self) -> str:
        shown = ", ".join(
            f"{n}={self.params[n]:.6g}"
            + (f"±{self.stderr[n]:.2g}" if self.determined[n] else "(undetermined)")
            for n in self.names
            if n not in STATE_NAMES
        )
        state = ("converged" if self.converged else "NOT converged") + (
            ", interrupted" if self.interrupted else ""
        )
        if self.blocks is not None and not self.blocks.made:
            state += ", block check not made"
        return f"FitResult({shown}; chi2/dof={self.reduced_chi2:.3g}, {state})"

    def _repr_html_(self) -> str:
        return report_html(self)

    def to_scenario(self, t_end: float | None = None, title: str | None = None) -> Scenario:
        """The fitted pendulum and start as a :class:`pendulab.Scenario` (t_end [s] default: the data's
        span; the method the model's usual one: ``rattle4`` at dt = 1 ms for the ideal pendulum, else
        ``dop853`` at its default tolerances, with no ``dt``)."""
        from ..scenario import Scenario

        p = self.pendulum
        span = float(self.t[-1] - self.t[0]) if t_end is None else float(t_end)
        if isinstance(p, SwingingSpring):
            return self._spring_scenario(p, span, title)
        pend: dict[str, Any] = {"model": p.model, "length": p.length, "mass": p.mass, "g": p.g, **p.extra}
        theta, phi = self.state0.angles()
        vals = {**self.fixed, **self.params}
        data: dict[str, Any] = {
            "title": title or f"fitted to {len(self.t)} samples (pendulab fit)",
            "pendulum": pend,
            "initial": {
                "theta": theta,
                "phi": phi,
                "theta_dot": vals["theta_dot0"],
                "phi_dot": vals["phi_dot0"],
            },
            # DOP853 chooses its steps (a dt would be its first step); RATTLE4 steps 1 ms, saving every 10 ms
            "simulation": {"t_end": span, "method": "dop853"},
        }
        if p.is_ideal:
            data["simulation"] |= {"method": "rattle4", "dt": 1e-3, "save_every": 10}
        return Scenario.from_dict(data, "<fit>")

    def _spring_scenario(self, p: SwingingSpring, span: float, title: str | None) -> Scenario:
        """The fitted spring as a scenario: the Cartesian start, the triple jump (``rattle4``) at a step
        of 1e-2 of the fastest time scale."""
        from ..scenario import Scenario

        omega = max(math.sqrt(p.k_over_m), math.sqrt(abs(p.g) / p.equilibrium_length))
        dt = min(1e-3, 1e-2 / omega)
        every = max(1, round(0.01 / dt))  # samples 10 ms apart
        data = {
            "title": title or f"fitted to {len(self.t)} samples (pendulab fit)",
            "pendulum": {
                "model": "spring",
                "length": p.rest_length,
                "mass": p.mass,
                "g": p.g,
                "stiffness": p.k_over_m * p.mass,
            },
            "initial": {"x": [float(c) for c in self.state0.x], "v": [float(c) for c in self.state0.v]},
            "simulation": {"t_end": span, "method": "rattle4", "dt": dt, "save_every": every},
        }
        return Scenario.from_dict(data, "<fit>")

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Writes :meth:`to_scenario` as TOML to ``path``, atomically."""
        return self.to_scenario().save(path)

    def plot(self, path: str | os.PathLike[str] | None = None) -> Any:
        """Data and fit, the residuals, and the parameter correlations; saved atomically to ``path``
        if given. Needs matplotlib. Returns the Figure."""
        return fit_figure(self, path)
