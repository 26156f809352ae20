"""The lab's fit report as message keys with values, so that a page translates it (docs/web.md,
"Languages"; issue 28: the fit report and its warnings were English on German and French pages).

``POST /api/fit`` (:mod:`.fit`) answers with the English text of :meth:`pendulab.FitResult.report`
and the warnings of :func:`pendulab.fit`; beside them this module builds

- ``notes``: each warning as ``{"key", "values", "text"}``: ``key`` one of :data:`NOTES` (``None`` when
  a warning has no key yet: the page then shows ``text``, the English words), ``values`` the numbers
  and names its words need, as the English text has them (strings, SI units as stated there);
- ``items``: the report line by line in the same form (the header, what the data determine instead, the
  plane held, the residuals per data kind against the data's noise floor, χ²/dof with what it means,
  the noise, what was held fixed, convergence), and ``reason`` for every undetermined parameter.

The warnings carry no codes of their own (they are plain sentences of :mod:`pendulab.fitting`), so a
warning is recognised by the pattern of its English words (:data:`NOTES`); every sentence the fit can
say is matched in python/tests/test_server_fit_words.py, so a changed wording fails a test instead of
falling back to English unnoticed. The page's words for each key are in web/src/i18n/fitwords.ts,
one table per language (checked by web/tests/unit/fitwords.test.ts against ``fit_words.json``).
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from typing import Any

from ..fitting import FitResult

_NUM = r"[-+0-9.eE]+|inf|nan"
_KEYS = json.loads(Path(__file__).with_name("fit_words.json").read_text(encoding="utf-8"))
KEYS: dict[str, str] = {k: v for k, v in _KEYS.items() if not k.startswith("_")}
"""Every key of a note or a report item -> its English words with {placeholders} (``fit_words.json``)."""


def _p(pattern: str) -> re.Pattern[str]:
    """A note's pattern: ``{name}`` stands for a number (group ``name``), ``{name:w}`` for a word,
    ``{name:l}`` for any text (a list of values)."""

    def group(m: re.Match[str]) -> str:
        name, kind = m.group(1), m.group(2)
        return f"(?P<{name}>{r'[A-Za-z_]+' if kind == 'w' else r'.+?' if kind == 'l' else _NUM})"

    return re.compile(re.sub(r"\\\{(\w+)(?::(\w))?\\\}", group, re.escape(pattern)))


NOTES: list[tuple[str, re.Pattern[str]]] = [
    # goodness.findings (pendulab/fitting/goodness.py)
    (
        "explainsLittle",
        _p("{kind:w}: the fitted motion explains only {percent} % of the data's variance"),
    ),
    ("correlatedNoise", _p("{kind:w}: the residual is correlated noise (lag-1 autocorrelation {lag1},")),
    (
        "systematicDrift",
        _p(
            "{kind:w}: the fit misses the data systematically with a slow drift over the record: the "
            "residual (rms {rms}, {ratio}x the data's noise floor {floor})"
        ),
    ),
    (
        "systematic",
        _p(
            "{kind:w}: the fit misses the data systematically: the residual (rms {rms}, {ratio}x the "
            "data's noise floor {floor})"
        ),
    ),
    ("correlatedSmall", _p("{kind:w}: the residual is correlated (lag-1 autocorrelation {lag1}, runs test")),
    ("aboveFloor", _p("{kind:w}: the residual rms {rms} is {ratio}x the noise floor {floor} read off")),
    ("outliers", _p("{kind:w}: {n} values lie more than {sigmas} robust standard deviations")),
    ("chi2Large", _p("the fitted motion misses the data by {factor}x their given noise: chi2 = {chi2} ")),
    ("chi2Small", _p("chi2/dof = {reduced} is improbably small for {dof} degrees of freedom")),
    # pendulab/fitting/blocks.py
    (
        "blocksDisagree",
        _p(
            "the record's {n} consecutive blocks, fitted on their own, disagree: {param:w} = {values:l} "
            "(the blocks in time order), {scale}x their error bars apart"
        ),
    ),
    # blocks.UNMADE (pendulab/fitting/blocks.py): the block check of a misfit not made
    (
        "blocksTimeLimit",
        _p("the block check of the misfit was not made: the fit's time limit of {seconds} s ran out"),
    ),
    ("blocksCtrlC", _p("the block check of the misfit was not made: Ctrl-C stopped the fit")),
    ("blocksCtrlCIn", _p("Ctrl-C stopped the block check of the misfit (fits to the record's {n} blocks")),
    ("blocksSearchTimeLimit", _p("the fit's time limit of {seconds} s cut the search short before it")),
    ("blocksSearchCtrlC", _p("Ctrl-C cut the search short before it converged, so the misfit found")),
    # pendulab/fitting/: inference.py (gFar, notConverged), estimator.py (pivotFitted),
    # multistart.py (timeLimit)
    ("gFar", _p("the fitted g = {g} m/s² is far from any planet's")),
    ("pivotFitted", _p("the positions do not hang from the origin: the pivot's position is fitted too")),
    ("timeLimit", _p("fit interrupted (the time limit of {seconds} s): returning the best values")),
    ("notConverged", _p("the fit did not converge (")),
    # pendulab/fitting/short_record.py
    (
        "shortUndetermined",
        _p(
            "the record spans only {periods} of a small-swing period 2π√(l/g) = {period} s: {others:l} "
            "are not determined ("
        ),
    ),
    (
        "shortUndetermined",
        _p(
            "the record spans only {periods} of a small-swing period 2π√(l/g) = {period} s: {others:l} "
            "is not determined ("
        ),
    ),
    (
        "shortWidened",
        _p(
            "the record spans only {periods} of a small-swing period 2π√(l/g) = {period} s: the error "
            "bars of {others:l} were taken from their 95 % profile-likelihood intervals"
        ),
    ),
    # pendulab/fitting/mirror.py
    (
        "mirrorPlanar",
        _p(
            "the data are consistent with a planar swing: held in its plane (phi0 = {plane:l}, phi_dot0 = 0: "
            "the x–z plane) the misfit rises by only {rise} (95 % level for the two: {level})"
        ),
    ),
    (
        "mirrorWidened",
        _p(
            "seen from the side near its plane, the sideways motion shows only at second order: the error "
            "bars of {others:l} were taken from their 95 % profile-likelihood intervals"
        ),
    ),
    (
        "mirrorUndetermined",
        _p("seen from the side, {others:l} are not determined (near its plane the sideways motion shows"),
    ),
    (
        "mirrorUndetermined",
        _p("seen from the side, {others:l} is not determined (near its plane the sideways motion shows"),
    ),
    # pendulab/fitting/mirror_sign.py: x, z data, a model the mirror y -> -y is no symmetry of
    (
        "mirrorSignUndetermined",
        _p(
            "seen from the side, only {told:l} tells the motion from its mirror image y → −y, and the image "
            "fits as well: its misfit is higher by only {rise} (95 % level {level})"
        ),
    ),
    # pendulab/fitting/data.py
    ("dropped", _p("dropped {n} of {total} rows with NaN or inf")),
    ("sorted", _p("the times were not in increasing order: the rows were sorted")),
    # pendulab/fitting/start.py
    (
        "lengthHint",
        _p("the positions lie {radius} m from the pivot, but the pendulum's length is {length} m"),
    ),
]
"""Warning key -> the pattern of its English words (from the start of the sentence)."""

CLAUSES: list[tuple[str, re.Pattern[str]]] = [
    # goodness._band (pendulab/fitting/goodness.py): in the correlated and systematic findings
    ("bandPower", _p("its power near {hz} Hz is {ratio}x that of the rest of its spectrum, p = {p}")),
    # blocks.BlockCheck.damping_law (pendulab/fitting/blocks.py): after the blocks' finding
    ("dampingDry", _p("as dry friction makes: fit '{param:w}' beside 'damping'")),
    ("dampingDrag", _p("as air drag makes: fit '{param:w}' beside 'damping'")),
    # short_record.STOPS (pendulab/fitting/short_record.py): why a short record's profile was not checked,
    # in its finding and in the parameters' reasons
    ("stopTimeLimit", _p("the fit's time limit of {seconds} s ran out before the profile likelihood")),
    ("stopCtrlC", _p("Ctrl-C stopped the fit before the profile likelihood was checked")),
    ("stopRobust", _p("the profile likelihood is not computed with a robust loss ({loss:w})")),
]
"""Clauses a warning may carry after its own words (anywhere in it) -> the pattern of their English
words: a note (and a parameter's reason) lists those it has as ``clauses``, each ``{"key", "values"}``,
which the page words after the note's own words."""

REASONS: list[tuple[str, re.Pattern[str]]] = [
    ("notFinite", _p("the model's response to it is not finite at the fit")),
    ("flat", _p("the residuals do not change with it at the fit")),
    ("combination", re.compile(r"the data determine only a combination of it with (?P<others>.+)$")),
    ("shortRecord", _p("a record of {periods} of a swing does not determine it")),
    (
        "mirrorUnchecked",
        _p("the fit stopped before the profile likelihood of the sideways motion was checked"),
    ),
    (
        "mirrorOpen",
        _p("seen from the side near its plane, the sideways motion's profile likelihood does not close"),
    ),
    (
        "mirrorSign",
        _p(
            "seen from the side, only {told:l} tells the motion from its mirror image y → −y, and the image "
            "fits as well: its misfit is higher by only {rise} (95 % level {level})"
        ),
    ),
    ("mirrorSignUnchecked", _p("the refit of the motion's mirror image y → −y was not finished")),
    ("lateBars", _p("the fit's time limit ran out before its error bars were computed")),
]
"""Why a parameter is not determined (pendulab/fitting/identify.py) -> key."""


def _values(m: re.Match[str]) -> dict[str, str]:
    return {k: v.rstrip(".,;") for k, v in m.groupdict().items() if v is not None}


def keyed(text: str, table: list[tuple[str, re.Pattern[str]]] = NOTES) -> dict[str, Any]:
    """``text`` (one warning, whitespace collapsed) as ``{"key", "values", "text"}``; ``key`` None when
    no pattern of ``table`` matches it. A warning (``table`` NOTES) also gets ``clauses``: those of
    :data:`CLAUSES` it contains, in their order in it, and so does a reason (``table`` REASONS) that has
    any."""
    text = " ".join(text.split())
    for key, pattern in table:
        m = pattern.match(text)
        if m is not None:
            out: dict[str, Any] = {"key": key, "values": _values(m), "text": text}
            if table is NOTES or table is REASONS:
                found = [(c.start(), k, _values(c)) for k, p in CLAUSES if (c := p.search(text)) is not None]
                if found or table is NOTES:
                    out["clauses"] = [{"key": k, "values": v} for _, k, v in sorted(found)]
            return out
    return {"key": None, "values": {}, "text": text}


def _g(v: float, digits: int = 3) -> str:
    return f"{v:.{digits}g}" if math.isfinite(v) else str(v)


def _item(key: str, **values: Any) -> dict[str, Any]:
    assert key in KEYS, key
    return {"key": key, "values": {k: str(v) for k, v in values.items()}}


def report_items(res: FitResult) -> list[dict[str, Any]]:
    """The report of ``res`` as keyed lines (the module doc), in the order of its text; the fitted
    parameters themselves are the answer's ``params`` (the page words them)."""
    from ..fitting.data import KINDS

    kinds = list(res.residuals)
    items = [_item("header", model=res.model, samples=len(res.t), kinds=",".join(kinds), t0=_g(res.t0, 6))]
    if res.dropped:
        items.append(_item("droppedRows", n=res.dropped))
    for label, (value, err) in res.combinations.items():
        items.append(_item("combinationValue", label=label, value=_g(value, 10), err=_g(err)))
    if res.mirror_blind and {"phi0", "phi_dot0"} & set(res.names):
        items.append(_item("mirror"))
    sign = res.mirror_sign
    if sign is not None:  # fitting/mirror_sign.py: x, z data, a held term that breaks the mirror
        if sign.told is None:
            items.append(_item("mirrorSignNotChecked"))
        else:
            key = "mirrorSignTold" if sign.told else "mirrorSignNotTold"
            items.append(
                _item(
                    key,
                    rise=_g(max(sign.rise, 0.0), 3),
                    threshold=_g(sign.threshold, 3),
                    level=_g(sign.level, 3),
                )
            )
    items.append(_item("aicBic", aic=_g(res.aic, 6), bic=_g(res.bic, 6)))
    if res.body is not None:
        items += _body_items(res)
    if res.planar:
        items.append(_item("planar"))
    if res.goodness is not None:
        for kind, c in res.goodness.kinds.items():
            items.append(
                _item(
                    "residual",
                    kind=kind,
                    rms=_g(c.rms),
                    floor=_g(c.floor),
                    unit=KINDS[kind],
                    lag1=f"{c.lag1:.3f}",
                )
            )
    key = "chi2Estimated" if res.sigma_estimated else "chi2"
    items.append(_item(key, chi2=_g(res.chi2, 6), dof=res.dof, reduced=_g(res.reduced_chi2, 4)))
    for kind, s in res.sigma.items():
        items.append(_item("noise", kind=kind, sigma=_g(s), unit=KINDS[kind]))
    for name in ("length", "g", "mass"):
        if name in res.fixed:
            items.append(
                _item("fixed", param=name, value=_g(res.fixed[name], 6), unit=res.units.get(name, ""))
            )
    done = "converged" if res.converged else "notConvergedItem"
    items.append(_item(done, runs=res.evaluations, seconds=_g(res.seconds)))
    return items


def _body_items(res: FitResult) -> list[dict[str, Any]]:
    """The compound pendulum's lines (:meth:`pendulab.fitting.body.BodyFit.report_lines`): the body's
    l_eq = I_O/(M h) (T-8.x of docs/theory.md) [m], the fitted length against it, the torques [N m (s)]."""
    from ..fitting.body import TORQUES

    fit = res.body
    assert fit is not None
    b = fit.body
    items = [
        _item(
            "compound",
            inertia=_g(b.inertia, 6),
            mass=_g(b.mass, 6),
            centre=_g(b.centre, 6),
            leq=_g(b.equivalent_length, 6),
        )
    ]
    if fit.length is None:
        items.append(_item("compoundLengthHeld"))
    else:
        value, err = fit.length
        off = (value - b.equivalent_length) / err if err > 0.0 and math.isfinite(err) else math.inf
        items.append(_item("compoundLength", value=_g(value, 6), err=_g(err, 2), off=f"{off:+.2g}"))
    units = dict(TORQUES.values())
    for name, (value, err) in fit.torques.items():
        items.append(
            _item("compoundTorque", param=name, value=_g(value, 6), err=_g(err, 2), unit=units[name])
        )
    return items


def reasons(res: FitResult) -> dict[str, dict[str, Any]]:
    """Why each undetermined parameter is not determined, keyed (:data:`REASONS`)."""
    return {n: keyed(res.reasons.get(n, ""), REASONS) for n in res.names if not res.determined[n]}
