"""The lab's fit report as message keys (``pendulab/server/fit_words.py``; docs/web.md, "Languages"): every
warning pl.fit can give is recognised by its words and keyed with the values its words need, so that a
German or French page shows it in its language (issue 28); a changed wording in pendulab.fitting fails here
instead of falling back to English unnoticed. The page's tables are checked against ``fit_words.json`` in
web/tests/unit/fitwords.test.ts."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from pendulab.fitting.blocks import BlockCheck
from pendulab.fitting.data import observations
from pendulab.fitting.goodness import KindCheck, findings
from pendulab.fitting.inference import LATE_REASON
from pendulab.fitting.short_record import STOPS
from pendulab.fitting.start import check_length_hint
from pendulab.server.fit_words import CLAUSES, KEYS, NOTES, REASONS, keyed, report_items

SOURCE = Path(__file__).resolve().parents[1] / "pendulab" / "server" / "fit_words.py"


def _check(**kw: float) -> KindCheck:
    base = dict(
        rms=1e-3,
        robust_rms=1e-3,
        floor=1e-3,
        spread=0.1,
        lag1=0.0,
        ljung_box_p=0.5,
        runs_z=0.0,
        outliers=0,
        trend=0.0,
        whitened_p=0.5,
        whitened_runs_z=0.0,
        dt=0.01,
    )
    base.update(kw)
    return KindCheck(**base)  # type: ignore[arg-type]


# one KindCheck per branch of goodness.findings, and the key its sentence must get
BRANCHES = [
    (_check(rms=0.09), "explainsLittle"),
    (_check(lag1=0.8, ljung_box_p=1e-9, runs_z=-9.0, whitened_p=0.5), "correlatedNoise"),
    (
        _check(rms=0.01, lag1=0.8, ljung_box_p=1e-9, runs_z=-9.0, whitened_p=1e-9, trend=0.5),
        "systematicDrift",
    ),
    (_check(rms=0.01, lag1=0.8, ljung_box_p=1e-9, runs_z=-9.0, whitened_p=1e-9), "systematic"),
    (_check(lag1=0.3, ljung_box_p=1e-9, runs_z=-9.0, whitened_p=1e-9), "correlatedSmall"),
    (_check(rms=0.01, robust_rms=0.01), "aboveFloor"),
    (_check(outliers=7), "outliers"),
]


@pytest.mark.parametrize(("check", "key"), BRANCHES)
def test_every_finding_of_the_residual_checks_is_keyed(check: KindCheck, key: str) -> None:
    said = findings({"positions": check}, None, 1.0, 10)
    assert said, f"the branch for {key} said nothing: the test's KindCheck no longer reaches it"
    got = [keyed(s) for s in said]
    assert got[0]["key"] == key, got[0]["text"]
    assert all(g["key"] is not None for g in got), [g["text"] for g in got if g["key"] is None]
    assert got[0]["values"]["kind"] == "positions"
    for g in got:  # every placeholder of the key's words is filled from the sentence
        words = KEYS[g["key"]]
        for name in g["values"]:
            assert "{" + name + "}" in words
        assert all(
            ("{" + h + "}") not in words or h in g["values"] for h in ("rms", "ratio", "floor", "lag1")
        )


def test_the_chi2_findings_are_keyed_with_their_numbers() -> None:
    big = [keyed(s) for s in findings({}, 1e-12, 400.0, 100)]
    assert [g["key"] for g in big] == ["chi2Large"]
    assert big[0]["values"] == {"factor": "2", "chi2": "400"}
    small = [keyed(s) for s in findings({}, 1.0, 20.0, 100)]
    assert [(g["key"], g["values"]) for g in small] == [("chi2Small", {"reduced": "0.2", "dof": "100"})]


def test_the_data_and_start_warnings_are_keyed() -> None:
    t = np.array([0.3, 0.1, 0.2, np.nan, *np.arange(1.0, 10.0)])
    x = np.column_stack([np.sin(t), np.zeros_like(t), -np.cos(t)])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        observations(t, {"positions": x})
        check_length_hint(50.0, 1.0, True)
    got = [keyed(str(w.message)) for w in caught]
    assert [(g["key"], g["values"]) for g in got] == [
        ("dropped", {"n": "1", "total": "13"}),
        ("sorted", {}),
        ("lengthHint", {"radius": "50", "length": "1"}),
    ]


@pytest.mark.parametrize(
    ("text", "key", "values"),
    [  # the estimator's sentences (pendulab/fitting/estimator.py), as it writes them
        (
            "the fitted g = 9810 m/s² is far from any planet's (Earth 9.81): are the data in SI units",
            "gFar",
            {"g": "9810"},
        ),
        (
            "the positions do not hang from the origin: the pivot's position is fitted too (give pivot=...)",
            "pivotFitted",
            {},
        ),
        (
            "fit interrupted (the time limit of 20 s): returning the best values reached",
            "timeLimit",
            {"seconds": "20"},
        ),
        ("the fit did not converge (max evaluations); the values are the best reached", "notConverged", {}),
    ],
)
def test_the_estimators_warnings_are_keyed(text: str, key: str, values: dict[str, str]) -> None:
    assert (keyed(text)["key"], keyed(text)["values"]) == (key, values)


def test_the_block_checks_finding_is_keyed() -> None:
    blocks = BlockCheck(
        starts=[0.0, 10.0, 20.0],
        values={"length": [0.61, 0.62, 0.635], "g": [9.8, 9.81, 9.82]},
        stderr={"length": [1e-3, 1e-3, 1e-3], "g": [0.01, 0.01, 0.01]},
        scale={"length": 7.5, "g": 1.0},
        units={"length": "m", "g": "m/s^2"},
    )
    got = [keyed(s) for s in blocks.findings()]
    assert [(g["key"], g["values"]) for g in got] == [
        (
            "blocksDisagree",
            {"n": "3", "param": "length", "values": "0.61, 0.62, 0.635 m", "scale": "7.5"},
        )
    ]


def test_a_sentence_without_a_key_keeps_its_english_words() -> None:
    assert keyed("something   new\n happened") == {
        "key": None,
        "values": {},
        "text": "something new happened",
    }


def test_every_reason_for_an_undetermined_parameter_is_keyed() -> None:
    for text, key in [
        ("the model's response to it is not finite at the fit", "notFinite"),
        ("the residuals do not change with it at the fit (a symmetry of the data, or ...)", "flat"),
        ("the data determine only a combination of it with g, pivot_z", "combination"),
        (LATE_REASON, "lateBars"),
    ]:
        assert keyed(text, REASONS)["key"] == key
    assert keyed("the data determine only a combination of it with g, pivot_z", REASONS)["values"] == {
        "others": "g, pivot_z"
    }


def test_the_keys_are_those_the_server_uses() -> None:
    used = {k for k, _ in NOTES} | {k for k, _ in REASONS} | {k for k, _ in CLAUSES}
    items = {"header", "droppedRows", "combinationValue", "mirror", "planar", "residual", "chi2"}
    items |= {"chi2Estimated", "noise", "fixed", "converged", "notConvergedItem", "aicBic"}
    items |= {"compound", "compoundLengthHeld", "compoundLength", "compoundTorque"}
    items |= {"mirrorSignTold", "mirrorSignNotTold", "mirrorSignNotChecked"}
    assert used | items == set(KEYS)
    text = SOURCE.read_text(encoding="utf-8")
    assert all(f'"{k}"' in text for k in items)
    assert callable(report_items)


@pytest.mark.parametrize(
    ("key", "values"),
    [("timeLimit", {"seconds": "20"}), ("ctrlC", {}), ("robust", {"loss": "huber"})],
)
def test_why_a_short_record_was_not_profiled_is_a_keyed_clause(key: str, values: dict[str, str]) -> None:
    """The reason a short record's profile was not checked (short_record.STOPS) is a clause of the
    finding and of the parameters' reasons: the page words it (the lab's fits stop after 20 s: it says
    how to fit the file without that limit), not only the English text."""
    why = STOPS[key].format(**values)
    clause = [{"key": "stop" + key[0].upper() + key[1:], "values": values}]
    reason = keyed(f"a record of 0.33 of a swing does not determine it ({why})", REASONS)
    assert reason["key"] == "shortRecord" and reason["clauses"] == clause, reason
    note = keyed(
        "the record spans only 0.33 of a small-swing period 2π√(l/g) = 1.5 s: length, g are not "
        f"determined (the curvature's error bars are too narrow along the valley where they trade off; {why})"
        ". Record at least one full swing to determine them"
    )
    assert note["key"] == "shortUndetermined" and note["clauses"] == clause, note


def test_a_block_check_not_made_is_keyed() -> None:
    """The finding that the block check of a misfit was not made (blocks.UNMADE: the time limit, which
    the lab's fits have, or Ctrl-C) is keyed, so that the page words it, with the limit's seconds."""
    units = {"length": "m", "damping": "1/s"}
    got = [keyed(s) for s in BlockCheck.not_made("timeLimit", units, 20.0, 4).findings()]
    assert [(g["key"], g["values"]) for g in got] == [("blocksTimeLimit", {"seconds": "20"})]
    got = [keyed(s) for s in BlockCheck.not_made("ctrlC", units, None, 4).findings()]
    assert [(g["key"], g["values"]) for g in got] == [("blocksCtrlC", {})]
    # Ctrl-C in the check itself, and the time limit or Ctrl-C cutting the search (the misfit may be its)
    got = [keyed(s) for s in BlockCheck.not_made("ctrlCIn", units, None, 4).findings()]
    assert [(g["key"], g["values"]) for g in got] == [("blocksCtrlCIn", {"n": "4"})]
    got = [keyed(s) for s in BlockCheck.not_made("searchTimeLimit", units, 20.0, 4).findings()]
    assert [(g["key"], g["values"]) for g in got] == [("blocksSearchTimeLimit", {"seconds": "20"})]
    got = [keyed(s) for s in BlockCheck.not_made("searchCtrlC", units, None, 4).findings()]
    assert [(g["key"], g["values"]) for g in got] == [("blocksSearchCtrlC", {})]
