"""Error bars of a record shorter than one swing (docs/fit.md, "A record shorter than a swing").

Over less than one small-swing period 2π√(l/|g|) of the result (:data:`SHORT_PERIODS`, as
multistart.FLOOR_PERIODS; l the hanging length, l₀ + m g/k for the swinging spring:
:func:`hanging_length`) the length, g and the pivot's height trade off along a curved valley of the
misfit, and the linearised error bars from its curvature at the optimum are far too narrow there: a
third of a swing (bench/fit_validate.py case 20, seed 38) gave l = 0.384 ± 0.050 m for a truth of
0.6 m (4.3 stderr off) with no warning. For such a record the profile likelihood (profile.py) of the
length and of g is computed: where it stays below the 95 % level out to :data:`DOUBLINGS` doublings
of the curvature's bar (63 bars) or to a bound, the data bound the parameter on one side only, and
length, g and every parameter correlated with them by |ρ| ≥ :data:`CORRELATED` are reported as not
determined, with a warning that names them, the record's span in periods and what would help;
where both profiles close, each profiled bar is widened to its 95 % profile interval (the larger side
over 1.96; an asymmetric interval is said), and the correlated parameters not profiled are widened by
the largest factor of those they are correlated with. Wherever the length or g ends up not
determined (by the curvature, an open profile or the time limit), and where their profiles close,
the bars of the others are linearised (with them free: identify.py) but the valley curves (case 20,
seed 3: φ̇₀ 4.5 such bars off): every other determined parameter, the start's too, is profiled
with every unknown free (:func:`_held`): open, not determined; closed, the bar from the profile.
An end that no checked, converged refit closes is open (profile.py). Every refit is bounded by the
fit's ``time_limit``, counted from the fit's start (checked at each model run): the parameters of a
profile it cuts short, and those not yet profiled, are not determined, and the finding names the
limit. Records of a period or more pay nothing.
Units: each parameter's (SI); times [s].
"""

from __future__ import annotations

import math
from statistics import NormalDist
from typing import Any

import numpy as np

from .multistart import FLOOR_PERIODS
from .problem import STATE_NAMES, bounds_of, scale_of
from .profile import REFIT_EVALUATIONS, REFIT_ROUNDS, Rise, profile_end
from .search import Search, TimeUp

#: A record spanning fewer small-swing periods 2π√(l/|g|) of the result than this has its bars of
#: length and g checked by their profile likelihood.
SHORT_PERIODS = FLOOR_PERIODS

#: Parameters whose correlation with the length or g is at least this share their fate.
CORRELATED = 0.9

#: Steps of doubling size per end of a profile (out to 63 curvature bars), then :data:`BISECTIONS`
#: and the check of the outer point (profile.py); at most :data:`REFITS` refits per end (twice that:
#: room to step on once past a refit the check finds failed).
DOUBLINGS = 6
BISECTIONS = 4
REFITS = 2 * (DOUBLINGS + BISECTIONS + 1)

#: At most this many parameters are profiled: the length and g (when only one of them is fitted, it
#: and the parameter most correlated with it); the others correlated with them take the largest factor.
MAX_PROFILES = 2

#: A bar widened by this factor or more is warned about (the profile then says more than the curvature).
WIDENED = 1.2

#: ... and so is one whose profile interval has a side more than this many times the other.
ASYMMETRIC = 1.5

#: The level of the profile interval.
LEVEL = 0.95


STOPS = {
    "timeLimit": (
        "the fit's time limit of {seconds} s ran out before the profile likelihood was checked; give a "
        "larger limit (pl.fit's time_limit=, pendulab fit's --time-limit) or none (time_limit=None, "
        "--time-limit none)"
    ),
    "ctrlC": "Ctrl-C stopped the fit before the profile likelihood was checked",
    "robust": (
        "the profile likelihood is not computed with a robust loss ({loss}); to check these bars, fit "
        "again with loss='linear' (pendulab fit --loss linear) once the outliers are removed"
    ),
}
"""Why the profile likelihood was not checked -> the English words of the reason (server/fit_words.py
keys them, the page has its own words)."""

STOPPED = "the fit stopped before the profile likelihood was checked"
"""Why the profile likelihood was not checked when none of :data:`STOPS` is known to be the cause."""


class Late(Exception):
    """The fit's time limit passed during a profile's refits, or (``ctrl_c``) Ctrl-C was pressed in one
    (shared with mirror.py)."""

    def __init__(self, ctrl_c: bool = False) -> None:
        super().__init__()
        self.ctrl_c = ctrl_c


class TimedRise(Rise):
    """profile.py's rise of the misfit with every refit bounded by the fit's time limit (``clock``: the
    fit's search), raising :class:`Late` once it has passed, before a refit or during one, and for
    Ctrl-C in a refit (the fit then keeps its values, as Ctrl-C in the search does). ``held``: other
    unknowns kept at their values in the start, not refitted (mirror.py: the sideways motion held at
    its plane). Shared with mirror.py."""

    def __init__(self, res: Any, name: str, period: float, clock: Search, held: tuple[str, ...] = ()) -> None:
        super().__init__(res, name, period, clock)
        self.others = [n for n in self.others if n not in held]

    def __call__(self, c: float, start: dict[str, float]) -> tuple[float, dict[str, float], bool]:
        if self.clock is not None and self.clock.time_up():
            raise Late
        try:
            return super().__call__(c, start)
        except TimeUp:
            raise Late from None
        except KeyboardInterrupt:
            raise Late(ctrl_c=True) from None


def check_short_record(res: Any, clock: Search, checkable: bool = True, ctrl_c: bool = False) -> list[str]:
    """For a :class:`pendulab.FitResult` ``res`` of a record shorter than :data:`SHORT_PERIODS` periods:
    the bars of the length, g and the parameters correlated with them checked by their profile
    likelihood and widened, or the parameters reported not determined (``res`` is changed in place);
    the findings to warn. ``clock``: the fit's search, whose ``time_limit`` (from the fit's start)
    bounds every refit of the profiles; once it has passed, at Ctrl-C during them, or when not
    ``checkable`` (an interrupted fit, a robust loss), the profiles not finished are not computed and
    their parameters are not determined (the finding says why: :func:`why_unchecked`; ``ctrl_c``: Ctrl-C
    stopped the error analysis before the check): their curvature bars cannot be trusted."""
    values = {**res.fixed, **res.params}
    length, g = hanging_length(values), float(values.get("g", math.nan))
    if not (length > 0.0 and math.isfinite(length) and math.isfinite(g) and g != 0):
        return []
    period = 2.0 * math.pi * math.sqrt(length / abs(g))
    periods = float(res.t[-1] - res.t[0]) / period
    core = [n for n in ("length", "g") if n in res.params and res.determined[n]]
    if periods >= SHORT_PERIODS:
        return []
    stop = "ctrl_c" if ctrl_c else ""
    if not core:  # the curvature left them not determined: the other bars hold them fixed
        return _held(res, periods, period, clock, checkable, why=why_unchecked(res, clock, stop))
    linked = _linked(res, core)
    profiled: dict[str, tuple[float, float]] = {}
    unsettled: list[str] = []
    if not checkable:
        why = why_unchecked(res, clock, stop)
        said = _undetermined(res, core + linked, periods, period, profiled, why)
        return [said, *_held(res, periods, period, clock, checkable, why=why)]
    try:
        for name in (core + linked)[:MAX_PROFILES]:
            profiled[name] = _profile(res, name, period, clock, unsettled)
            if not all(map(math.isfinite, profiled[name])):
                break  # an open profile: the valley is open
    except Late as e:
        why = why_unchecked(res, clock, "ctrl_c" if e.ctrl_c else "late")
        said = _undetermined(res, core + linked, periods, period, profiled, why)
        return [said, *_held(res, periods, period, clock, checkable and not e.ctrl_c, why=why)]
    if any(not all(map(math.isfinite, ends)) for ends in profiled.values()):
        said = _undetermined(res, core + linked, periods, period, profiled, _open(unsettled))
        return [said, *_held(res, periods, period, clock, checkable)]
    widened = _widened(res, core, linked, periods, period, profiled)
    return widened + _held(res, periods, period, clock, checkable, done=set(profiled))


def hanging_length(values: dict[str, float]) -> float:
    """The length [m] the bob hangs at: a rod's ``length``; the swinging spring's rest length l₀ plus
    its stretch m g/k (spring_model.py), whose small swings have the period 2π√((l₀ + m g/k)/g)
    (shared with mirror.py)."""
    length = float(values.get("length", math.nan))
    if float(values.get("stiffness", 0.0)) > 0.0:
        length += float(values["mass"]) * abs(float(values["g"])) / float(values["stiffness"])
    return length


def _held(
    res: Any,
    periods: float,
    period: float,
    clock: Search,
    checkable: bool,
    done: set[str] | None = None,
    why: str | None = None,
) -> list[str]:
    """Length or g fitted and not determined by the curvature. identify.py computes the others' bars
    with them free, but only to first order: along the curved valley where they move, a third of a
    swing leaves those bars too narrow still (case 20, seed 3: φ̇₀ = 0.09 ± 0.16 rad/s for 0.8,
    4.5 bars off; with them held it had been ± 0.029, and pivot_x ± 0.0009 m, 6–21 bars off). Every
    determined parameter, the start's too (the pivot and damping first), is profiled with every other
    unknown free: an open profile, not determined; a closed one, the bar taken from it (never
    narrower); one the time limit leaves unprofiled, not determined. With the length and g
    determined and their profiles closed (``done``: those profiled), the others are profiled too: the
    curvature's bars along the same valley were too narrow (case 20, seed 31: φ̇₀ = 3.03 ± 0.56 rad/s
    for 0.8, 4 bars off, with length and g from their profiles). ``why``: the reason given to those
    not profiled when the check was already stopped (default: :func:`why_unchecked`)."""
    if done is None and not any(n in res.params and not res.determined[n] for n in ("length", "g")):
        return []
    determined = [n for n in res.names if res.determined[n] and n not in (done or set())]
    chosen = [n for n in determined if n not in STATE_NAMES] + [n for n in determined if n in STATE_NAMES]
    profiled: dict[str, tuple[float, float]] = {}
    unsettled: list[str] = []
    why = why or why_unchecked(res, clock)
    try:
        for name in chosen if checkable else []:
            profiled[name] = _profile(res, name, period, clock, unsettled)
    except Late as e:
        why = why_unchecked(res, clock, "ctrl_c" if e.ctrl_c else "late")
    closed = {n: e for n, e in profiled.items() if all(map(math.isfinite, e))}
    unchecked = [n for n in chosen if n not in profiled]
    said = [_undetermined(res, unchecked, periods, period, {}, why)] if unchecked else []
    open_ = {n: e for n, e in profiled.items() if n not in closed}
    if open_:
        said.append(_undetermined(res, list(open_), periods, period, open_, _open(unsettled)))
    return said + (_widened(res, [], [], periods, period, closed) if closed else [])


def why_unchecked(res: Any, clock: Search, stop: str = "") -> str:
    """Why a profile was not computed or not finished: the fit's time limit (named, with how to raise
    it in Python and on the command line; ``stop`` "late": a refit stopped for it, maybe a Jacobian's
    run ahead of it), Ctrl-C (``stop`` "ctrl_c": in a refit; or in the search), or a robust loss,
    with which the profiles are not computed (server/fit_words.py keys each: :data:`STOPS`); else
    :data:`STOPPED`. Shared with mirror.py."""
    limit = clock.time_limit
    if clock.loss != "linear":  # never profiled, whatever else stopped the fit
        return STOPS["robust"].format(loss=clock.loss)
    if stop == "ctrl_c" or (stop != "late" and "Ctrl-C" in str(res.message)):
        return STOPS["ctrlC"]
    if limit is not None and (stop == "late" or clock.time_up() or "time limit" in str(res.message)):
        return STOPS["timeLimit"].format(seconds=f"{limit:g}")
    return STOPPED


def _open(unsettled: list[str]) -> str:
    """Why a profile is open: it does not close, or (``unsettled``) a refit of it did not converge."""
    if not unsettled:
        return "the profile likelihood does not close"
    return (
        f"the profile likelihood does not close, or a refit of it ({', '.join(unsettled)}) did not "
        f"converge in {REFIT_ROUNDS} x {REFIT_EVALUATIONS} model runs"
    )


def _linked(res: Any, core: list[str]) -> list[str]:
    """The determined parameters other than ``core`` correlated with one of them by |ρ| ≥ CORRELATED,
    the most correlated first."""
    i = {n: k for k, n in enumerate(res.names)}
    rho = {
        n: max(abs(float(np.nan_to_num(res.correlation[i[n], i[c]]))) for c in core)
        for n in res.names
        if n not in core and res.determined[n]
    }
    return sorted((n for n, r in rho.items() if r >= CORRELATED), key=lambda n: -rho[n])


def _profile(res: Any, name: str, period: float, clock: Search, unsettled: list[str]) -> tuple[float, float]:
    """The 95 % profile interval of ``name`` [its unit], each end at most DOUBLINGS doublings of the
    curvature's bar out (else ±inf) and BISECTIONS bisections; a bound of the parameter reached
    below the level is returned as ±inf (the data do not bound it there), and so is an end that no
    converged refit closes (profile.py; ``name`` is then added to ``unsettled``)."""
    from scipy import stats

    rise = TimedRise(res, name, period, clock)

    values = {**res.fixed, **res.params}
    value, err = values[name], res.stderr[name]
    bounds = bounds_of(res._problem.model, name, value)
    step0 = err if math.isfinite(err) and err > 0 else scale_of(name, value, values["length"], period)
    target = float(stats.chi2.ppf(LEVEL, 1))
    ends = [
        profile_end(rise, values, step0, bounds, d, REFITS, target, DOUBLINGS, BISECTIONS)
        for d in (-1.0, 1.0)
    ]
    if not all(settled for _, settled in ends):
        unsettled.append(name)
    lo, hi = (e if e not in bounds else math.copysign(math.inf, e - value) for e, _ in ends)
    return lo, hi


def _undetermined(
    res: Any,
    names: list[str],
    periods: float,
    period: float,
    profiled: dict[str, tuple[float, float]],
    why: str,
) -> str:
    """``names`` marked not determined in ``res`` (``why``: the profile did not close, or was not
    computed); the finding."""
    mark_not_determined(res, names, f"a record of {periods:.2g} of a swing does not determine it ({why})")
    shown = "; ".join(shown_interval(res, n, lo, hi) for n, (lo, hi) in profiled.items())
    return (
        f"the record spans only {periods:.2g} of a small-swing period 2π√(l/g) = {period:.3g} s: "
        f"{', '.join(names)} {'is' if len(names) == 1 else 'are'} not determined (the curvature's error "
        "bars are too narrow along the "
        f"valley where they trade off; {why}"
        + (f": 95 % profile {shown}" if shown else "")
        + f"). Record at least one full swing to determine {'it' if len(names) == 1 else 'them'}"
    )


def _widened(
    res: Any,
    core: list[str],
    linked: list[str],
    periods: float,
    period: float,
    profiled: dict[str, tuple[float, float]],
) -> list[str]:
    """The bars in ``res`` widened to the profile intervals (those of ``linked`` not profiled by the
    largest factor of the core parameters); the finding when a bar grew by WIDENED or more."""
    z = NormalDist().inv_cdf(0.5 + LEVEL / 2.0)
    i = {n: k for k, n in enumerate(res.names)}
    factor: dict[str, float] = {}
    for n, (lo, hi) in profiled.items():
        v = res.params[n]
        factor[n] = max(max(hi - v, v - lo) / z / res.stderr[n], 1.0)
    for n in linked:
        if n not in factor:
            factor[n] = max(factor[c] for c in core)
    for n, f in factor.items():
        res.stderr[n] *= f
        res.covariance[i[n], :] *= f
        res.covariance[:, i[n]] *= f
    lopsided = [n for n, (lo, hi) in profiled.items() if _asymmetric(res.params[n], lo, hi)]
    said = [n for n, f in factor.items() if f >= WIDENED or n in lopsided]
    if not said:
        return []
    shown = "; ".join(shown_interval(res, n, lo, hi) for n, (lo, hi) in profiled.items())
    return [
        f"the record spans only {periods:.2g} of a small-swing period 2π√(l/g) = {period:.3g} s: the "
        f"error bars of {', '.join(said)} were taken from their 95 % profile-likelihood intervals "
        f"({shown}; the error bar is the larger side over 1.96), which the curvature at the fit "
        "understates. Record at least one full swing to narrow them"
    ]


def mark_not_determined(res: Any, names: list[str], reason: str) -> None:
    """``names`` marked not determined in the :class:`pendulab.FitResult` ``res`` (in place) with the
    ``reason``: no bar (stderr inf), their rows and columns of the covariance and correlation NaN, the
    covariance's diagonal inf (as identify.py leaves a parameter the data do not determine; shared
    with mirror.py)."""
    i = {n: k for k, n in enumerate(res.names)}
    for n in names:
        res.determined[n] = False
        res.reasons[n] = reason
        res.stderr[n] = math.inf
        res.covariance[i[n], :] = math.nan
        res.covariance[:, i[n]] = math.nan
        res.covariance[i[n], i[n]] = math.inf
        res.correlation[i[n], :] = math.nan
        res.correlation[:, i[n]] = math.nan


def shown_interval(res: Any, name: str, lo: float, hi: float) -> str:
    """``name`` lo … hi [unit], with ≥ lo or ≤ hi for an open end, and the sides when asymmetric."""
    unit = res.units.get(name, "")
    unit = f" {unit}" if unit and unit != "1" else ""
    v = res.params[name]
    if not math.isfinite(hi) and not math.isfinite(lo):
        return f"{name} not bounded"
    if not math.isfinite(hi):
        return f"{name} ≥ {lo:.3g}{unit}"
    if not math.isfinite(lo):
        return f"{name} ≤ {hi:.3g}{unit}"
    up, down = hi - v, v - lo
    side = f", asymmetric: +{up:.2g}/−{down:.2g}" if _asymmetric(v, lo, hi) else ""
    return f"{name} {lo:.4g} … {hi:.4g}{unit}{side}"


def _asymmetric(value: float, lo: float, hi: float) -> bool:
    """Whether one side of the interval lo … hi is more than ASYMMETRIC times the other."""
    up, down = hi - value, value - lo
    return max(up, down) > ASYMMETRIC * max(min(up, down), 0.0)
