"""Does the fit hold along the whole record? The record cut into consecutive blocks, each fitted on its
own, and the error bars widened by the blocks' disagreement (issue 24, item 3; docs/fit.md, "When
the model is incomplete").

A model that lacks something the data have (an amplitude-dependent friction or stiffness, a drifting
sensor) fits each stretch of a record with slightly different physical parameters, and the fit of
the whole record is a compromise that depends on which amplitudes and how much of each the recording
happens to contain. Its error bars from (JᵀJ)⁻¹ (T-10.2), even widened for correlated residuals, only
say how well the compromise is located, so two recordings of one pendulum can disagree by twenty of
them. The blocks measure that dependence directly:

- the record is cut into BLOCKS consecutive blocks of equal sample count (fewer, down to two, where
  the record is too short for each to be at least MIN_PERIODS swings long); each block is fitted
  with the same free physical parameters, starting from the whole record's values and the fitted
  motion's state at the block's first sample (its own θ₀, θ̇₀, …);
- for each physical parameter p the blocks' values pᵢ ± σᵢ (σᵢ from the block's own analysis,
  identify.py, widened for correlation like the whole fit's) are averaged with weights 1/σᵢ², and
  the scale factor of the Particle Data Group is formed,

      S = √(χ²/(N − 1)),  χ² = Σᵢ (pᵢ − p̄)²/σᵢ²,

  over the N blocks with σᵢ < 3√N σ̄ (σ̄ = (Σ 1/σᵢ²)^(−1/2)), as the PDG does for inconsistent
  measurements (R. L. Workman et al. (Particle Data Group), "Review of Particle Physics",
  Prog. Theor. Exp. Phys. 2022, 083C01, Introduction §5.2.2);
- where S > 1 the parameter's error bar (and its rows of the covariance) are multiplied by S; the
  finding that the blocks disagree is said only where their χ² is improbable for blocks that agree
  (p < BLOCKS_ALARM), so that a misfit the blocks share (a wrong fixed length) is not blamed on
  something that changes along the record.

It runs only when the goodness of fit (goodness.py) has found a misfit — for a right model the blocks
agree within their errors by construction, and scaling by a chance S > 1 would make honest bars
too wide — and only for models without explicit time dependence (no forcing, no moving pivot, no
time offset; AUTONOMOUS), where a block's motion is fixed by its own start. Where it is due but the
fit's time limit or Ctrl-C stops the fit before it or during it, it is not made: ``res.blocks`` says so
(``made`` False, ``stop`` what stopped it, ``unmade`` its finding, ``scale`` NaN: not measured, not
widened) and its one finding, warned, what stopped it, that the bars were not widened and how to let it
run (:data:`UNMADE`; where the search itself was cut, that the misfit may be the search's). The
statistics are in block_stats.py. Units: SI, as the parameters'.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from .._core import IntegrationError, InvalidInputError
from ..model import FloatArray
from .block_stats import disagreement_p, lag1_of, scale_factor, trend_z
from .identify import Correlation, Identifiability, analyse, jacobian
from .problem import POSITIVE, STATE_NAMES, Problem, unit_of
from .settings import angles_of

if TYPE_CHECKING:
    from .search import Search

#: The record is cut into this many consecutive blocks (fewer for a short record, at least 2).
BLOCKS = 4
#: Each block must span at least this many swing periods (otherwise no block check).
MIN_PERIODS = 2.0
#: Model runs a block's search may use.
BLOCK_EVALUATIONS = 60
#: The blocks are said to disagree only when their scatter is this improbable for blocks that agree
#: (χ² of N − 1 degrees of freedom): 1.06x apart over 4 blocks (p = 0.3) is agreement.
BLOCKS_ALARM = 0.05
#: The damping's weighted slope over the blocks, in standard errors, from which a damping law is named.
TREND_Z = 3.0
#: The models whose motion a block's own start fixes (no pivot path, hoist or other clock; the
#: damped model's forcing is checked separately).
AUTONOMOUS = ("ideal", "damped", "rotating")

#: How to give a check the time limit cut more time, and how to let one Ctrl-C stopped finish.
_LARGER = (
    "give a larger limit (pl.fit's time_limit=, pendulab fit's --time-limit, the lab's pendulab serve "
    "--fit-time-limit) or none (time_limit=None, --time-limit none)"
)
_FINISH = "fit again and let it finish"
_UNCHECKED = (
    "The error bars are not checked against the scatter of the record's blocks fitted on their own, so "
    "for a model that misses the data they may be too narrow; "
)
_SEARCH_CUT = (
    " before it converged, so the misfit found may be the search's (values short of the best fit), not "
    "the model's; the block check of the misfit was not made and the error bars were not widened by it; "
)
UNMADE = {
    "timeLimit": (
        "the block check of the misfit was not made: the fit's time limit of {seconds} s ran out before it "
        "was done. " + _UNCHECKED + _LARGER
    ),
    "ctrlC": (
        "the block check of the misfit was not made: Ctrl-C stopped the fit before it was done. "
        + _UNCHECKED
        + _FINISH
    ),
    "ctrlCIn": (
        "Ctrl-C stopped the block check of the misfit (fits to the record's {blocks} blocks on their own) "
        "before it was done: the error bars were not widened by the blocks' disagreement, so for a model "
        "that misses the data they may be too narrow; " + _FINISH + " (the check takes up to "
        f"{BLOCK_EVALUATIONS} model runs per block)"
    ),
    "searchTimeLimit": "the fit's time limit of {seconds} s cut the search short" + _SEARCH_CUT + _LARGER,
    "searchCtrlC": "Ctrl-C cut the search short" + _SEARCH_CUT + _FINISH,
}
"""Why the block check of a misfit was not made -> its finding (server/fit_words.py keys them): the time
limit ran out after the search, before the check or in it; Ctrl-C stopped the fit before it (in the
polish) or stopped the check itself; the time limit or Ctrl-C cut the search itself, so that the misfit
may be the unfinished search's."""


@dataclass
class BlockCheck:
    """The blocks' fits: their first sample times ``starts`` [s], per physical parameter the blocks'
    values and standard errors (``nan`` where a block does not determine it; units of the parameter),
    and the scale factor S ≥ 1 its error bar was multiplied by (module doc).

    A check that was due but not made (``made`` False; ``stop`` the key of :data:`UNMADE` naming what
    stopped it, ``unmade`` its finding) has no blocks (``starts``, ``values``, ``stderr`` empty) and
    ``scale`` NaN for each parameter it would have compared: not measured, the bar not widened (NaN,
    not 1, which would say the blocks agree). The report, ``repr`` and the lab's answer show it so."""

    starts: list[float]
    values: dict[str, list[float]] = field(default_factory=dict)
    stderr: dict[str, list[float]] = field(default_factory=dict)
    scale: dict[str, float] = field(default_factory=dict)

    units: dict[str, str] = field(default_factory=dict)
    #: Why the check was not made (a finding of :data:`UNMADE`: no blocks, no widening); "" if it was.
    unmade: str = ""
    #: The key of :data:`UNMADE` that stopped it ("timeLimit", "ctrlC", "ctrlCIn", "searchTimeLimit",
    #: "searchCtrlC"); "" if it was made.
    stop: str = ""

    @property
    def made(self) -> bool:
        """Whether the blocks were fitted (False: the time limit or Ctrl-C stopped the fit first)."""
        return not self.unmade

    @classmethod
    def not_made(
        cls, stop: str, units: dict[str, str], seconds: float | None = None, blocks: int = 0
    ) -> BlockCheck:
        """The check of the physical parameters of ``units`` (name -> unit) over ``blocks`` blocks that
        ``stop`` (a key of :data:`UNMADE`: Ctrl-C, or the time limit of ``seconds`` [s]) did not let run."""
        text = UNMADE[stop].format(seconds=f"{seconds:g}" if seconds else "", blocks=blocks)
        return cls(starts=[], scale=dict.fromkeys(units, math.nan), units=units, unmade=text, stop=stop)

    def __repr__(self) -> str:
        scales = ", ".join(f"{n}={s:.3g}" for n, s in self.scale.items())
        if not self.made:
            return f"BlockCheck(not made: {self.stop}; scale {scales}: not widened)"
        shown = ", ".join(f"{t:.4g}" for t in self.starts)
        return f"BlockCheck({len(self.starts)} blocks from t = {shown} s; scale {scales})"

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready (the lab's answer): ``made``, ``stop`` (None if made), ``starts`` [s], and per
        parameter ``scale``, ``values``, ``stderr`` with None for NaN (a scale not measured, a block
        that does not determine the parameter)."""

        def shown(v: float) -> float | None:
            return float(v) if math.isfinite(v) else None

        return {
            "made": self.made,
            "stop": self.stop or None,
            "starts": [float(t) for t in self.starts],
            "scale": {n: shown(s) for n, s in self.scale.items()},
            "values": {n: [shown(v) for v in vs] for n, vs in self.values.items()},
            "stderr": {n: [shown(v) for v in vs] for n, vs in self.stderr.items()},
            "units": dict(self.units),
        }

    def findings(self) -> list[str]:
        """The plain-language finding for the parameters whose blocks disagree: a scatter improbable
        for blocks that agree (p < BLOCKS_ALARM; none if none do). A chance S > 1 still widens. A check
        not made says so."""
        if self.unmade:
            return [self.unmade]
        widened = [n for n, s in self.scale.items() if s > 1.0]
        apart = [
            n
            for n in widened
            if disagreement_p(np.array(self.values[n]), np.array(self.stderr[n])) < BLOCKS_ALARM
        ]
        if not apart:
            return []
        worst = max(apart, key=lambda n: self.scale[n])
        shown = ", ".join(f"{v:.6g}" if math.isfinite(v) else "-" for v in self.values[worst])
        names = ", ".join(f"{n} ×{self.scale[n]:.3g}" for n in widened)
        law = self.damping_law()  # a sentence of its own: after a full stop
        return [
            f"the record's {len(self.starts)} consecutive blocks, fitted on their own, disagree: {worst} = "
            f"{shown} {self.units.get(worst, '')} (the blocks in time order), {self.scale[worst]:.3g}x "
            "their error bars apart. The model misses something that changes along the record "
            "(friction or stiffness that depend on the amplitude, a drifting sensor, a hinge that is "
            f"not ideal), so the error bars are widened by the blocks' scale factor: {names} "
            "(the Particle Data Group's rule for inconsistent measurements; res.blocks)"
            + (f".{law}" if law else "")
        ]

    def damping_law(self) -> str:
        """A hint at the damping law the blocks point to (empty where none): the viscous damping fitted
        to each block rises steadily along a free decay, as the swing dies down, where the real loss
        per swing falls more slowly than in proportion to the amplitude (dry friction: c ∝ 1/amplitude)
        and falls where it falls faster (drag: c ∝ amplitude). Steadily: a weighted slope over the blocks
        of more than TREND_Z of its standard errors that explains block_stats.TREND_SHARE of their scatter."""
        if "damping" not in self.values:
            return ""
        z = trend_z(np.array(self.values["damping"]), np.array(self.stderr["damping"]))
        if z > TREND_Z:
            return (
                " The damping fitted to the blocks rises as the swing dies down: the amplitude decays "
                "more linearly than exponentially, as dry friction makes: fit 'friction' beside 'damping'"
            )
        if z < -TREND_Z:
            return (
                " The damping fitted to the blocks falls as the swing dies down: the large swings lose "
                "more, as air drag makes: fit 'drag' beside 'damping'"
            )
        return ""


def applicable(problem: Problem, period: float) -> list[int] | None:
    """The blocks' first sample indices (and the end), or None where no block check can be made."""
    values = problem.values
    if problem.model not in AUTONOMOUS or "t_offset" in problem.free or values.get("t_offset", 0.0) != 0.0:
        return None
    if values.get("forcing_amplitude", 0.0) != 0.0 or "forcing_amplitude" in problem.free:
        return None
    t = problem.obs.t
    n = len(t)
    if not (math.isfinite(period) and period > 0.0):
        return None
    count = min(BLOCKS, int((t[-1] - t[0]) / (MIN_PERIODS * period)))
    if count < 2:
        return None
    edges = [round(i * n / count) for i in range(count + 1)]
    long_enough = all(
        edges[i + 1] - edges[i] >= 20 and t[edges[i + 1] - 1] - t[edges[i]] >= MIN_PERIODS * period
        for i in range(count)
    )
    return edges if long_enough else None


def block_start(problem: Problem, values: dict[str, float], x: FloatArray, v: FloatArray) -> dict[str, float]:
    """The whole fit's values with the start replaced by the fitted motion's state (x [m], v [m/s]) at
    a block's first sample (a held φ₀ takes the state's, so that the block starts where the motion
    is); a hinge's (φ₀ and φ̇₀ held, φ̇₀ = 0) θ₀ signed in its plane, as the whole fit's."""
    from ..model import State

    angles = angles_of(State(x, v))
    start = dict(values) | {k: angles[k] for k in STATE_NAMES}
    hinge = not {"phi0", "phi_dot0"} & set(problem.free) and values["phi_dot0"] == 0.0
    if hinge:  # the swing stays in its plane φ₀: θ signed, as the whole fit's
        sign = 1.0 if math.cos(angles["phi0"] - values["phi0"]) >= 0.0 else -1.0
        start.update(
            theta0=sign * angles["theta0"],
            phi0=values["phi0"],
            theta_dot0=sign * angles["theta_dot0"],
            phi_dot0=0.0,
        )
    return start


def _fit_block(
    search: Search, block: Problem, start: dict[str, float], known: bool
) -> tuple[FloatArray, FloatArray] | None:
    """One block's values and standard errors (inf where not determined), or None if it fails; the
    time limit passing in its search raises :class:`search.TimeUp`."""
    from .search import Search

    free = search.free
    inner = Search(
        block,
        start,
        search.scales,
        (search.lower, search.upper),
        search.sigma,
        loss="linear",
        max_evaluations=BLOCK_EVALUATIONS,
        clock=search.clock,
        logged=search.logged,
    )
    try:
        res = inner.run(np.array([start[n] for n in free], dtype=np.float64))
        u, r = res.x, res.fun[: res.fun.size - len(free)]  # the data's residuals at u (no anchor)
        jac = inner.exact_jacobian(block, u)
        if jac is None:
            jac = jacobian(lambda uu: block.safe_residuals(uu, search.sigma), u, 1e-7 * search.scales)
    except (InvalidInputError, IntegrationError, OverflowError, ValueError):
        return None
    if not (np.all(np.isfinite(r)) and np.all(np.isfinite(jac))):
        return None
    dof = max(r.size - len(free), 1)
    variance = 1.0 if known else float(r @ r) / dof
    positive = {n for i, n in enumerate(free) if n in POSITIVE and u[i] > 0.01 * search.scales[i]}
    obs = block.obs
    sample = np.concatenate([np.repeat(np.arange(len(obs)), obs.columns[k]) for k in obs.values])
    lag1 = lag1_of(r, obs.columns, list(obs.values))
    ident = analyse(free, block.with_free(u), jac, variance, positive, Correlation(r, sample, len(obs), lag1))
    cov = ident.covariance
    err = np.array(
        [
            math.sqrt(cov[i, i]) if ident.determined[n] and math.isfinite(cov[i, i]) else math.inf
            for i, n in enumerate(free)
        ]
    )
    return u, err


def check_blocks(
    search: Search, values: dict[str, float], ident: Identifiability, known: bool
) -> BlockCheck | None:
    """The block check of the module doc for the whole fit's ``values``; ``ident`` (the whole fit's
    analysis) has its covariance and inflation widened in place. ``known``: σ was given. None where
    no check can be made (a robust loss, a timed model, blocks shorter than MIN_PERIODS swings). The
    fit's time limit passed before it or in a block's fit raises :class:`search.TimeUp` (nothing widened)."""
    from .search import TimeUp

    problem = search.problem
    plan = planned(search, values, ident)
    if plan is None:
        return None
    edges, physical = plan
    if search.time_up():
        raise TimeUp
    _, x, v, _ = problem.motion(values)
    obs = problem.obs
    fits = []
    for i in range(len(edges) - 1):
        a, b = edges[i], edges[i + 1]
        part = type(obs)(
            t=obs.t[a:b],
            values={k: val[a:b] for k, val in obs.values.items()},
            sigma=obs.sigma,
            dropped=0,
            columns=obs.columns,
        )
        start = block_start(problem, values, x[a], v[a])
        block = Problem(problem.model, start, search.free, part)
        try:
            fits.append(_fit_block(search, block, start, known))
        finally:
            problem.evaluations += block.evaluations
    if any(f is None for f in fits):
        return None
    check = BlockCheck(
        starts=[float(obs.t[a]) for a in edges[:-1]],
        units={n: unit_of(problem.model, n) for n in physical},
    )
    for n in physical:
        j = search.free.index(n)
        vals = np.array([f[0][j] for f in fits if f is not None])
        errs = np.array([f[1][j] for f in fits if f is not None])
        check.values[n] = [
            float(a) if math.isfinite(e) else math.nan for a, e in zip(vals, errs, strict=True)
        ]
        check.stderr[n] = [float(e) if math.isfinite(e) else math.nan for e in errs]
        check.scale[n] = scale_factor(vals, errs)
    widen(ident, search.free, check.scale)
    return check


def planned(
    search: Search, values: dict[str, float], ident: Identifiability
) -> tuple[list[int], list[str]] | None:
    """The blocks' edges (:func:`applicable`) and the physical parameters the block check of the whole
    fit's ``values`` would compare, or None where it cannot be made (:func:`check_blocks`)."""
    if search.loss != "linear":
        return None
    period = 2.0 * math.pi * math.sqrt(values["length"] / max(abs(values["g"]), 1e-9))
    edges = applicable(search.problem, period)
    physical = [n for n in search.free if n not in STATE_NAMES and ident.determined.get(n, False)]
    return (edges, physical) if edges is not None and physical else None


def not_made(
    search: Search, values: dict[str, float], ident: Identifiability, stop: str
) -> BlockCheck | None:
    """The block check of the whole fit's ``values`` said not made for ``stop`` (a key of :data:`UNMADE`),
    or None where none would have been made (:func:`planned`)."""
    plan = planned(search, values, ident)
    if plan is None:
        return None
    edges, physical = plan
    units = {n: unit_of(search.problem.model, n) for n in physical}
    return BlockCheck.not_made(stop, units, search.clock.time_limit, len(edges) - 1)


def widen(ident: Identifiability, free: list[str], scale: dict[str, float]) -> None:
    """Multiplies the rows and columns of ``ident``'s covariance by each parameter's scale factor and
    records it in ``ident.inflation``."""
    s = np.array([scale.get(n, 1.0) for n in free])
    if np.all(s == 1.0):
        return
    ident.covariance = ident.covariance * np.outer(s, s)
    for n, f in scale.items():
        if f > 1.0:
            ident.inflation[n] = ident.inflation.get(n, 1.0) * f
