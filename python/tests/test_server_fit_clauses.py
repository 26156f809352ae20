"""The clauses a fit warning carries after its own words (``pendulab/server/fit_words.py``, CLAUSES): the
band scan's power near a frequency (goodness.py) and the damping law the record's blocks point to
(blocks.py) reach the page as keyed ``clauses`` with their numbers, so that a German or French page says
them too (web/tests/unit/fitwords.test.ts checks every language words every key of ``fit_words.json``).
Before, ``keyed`` matched only a warning's opening words and these clauses were dropped on every page,
English included, without a failing test; every number a finding states now lies in its keyed words,
a clause, or one of the few the page's words leave out (UNWORDED)."""

from __future__ import annotations

import re
from dataclasses import replace

import pytest
from test_server_fit_words import BRANCHES, _check

from pendulab.fitting.blocks import BlockCheck
from pendulab.fitting.goodness import findings
from pendulab.server.fit_words import CLAUSES, KEYS, NOTES, keyed

# numbers of a finding that the page's words leave out on purpose (the English text has them)
UNWORDED = re.compile(
    r"(lag-1 autocorrelation -?[0-9.]+|runs test z = -?[0-9.]+|correlation time [-+0-9.einf]+ s|AR\(1\)"
    r"|residual rms [0-9.e+-]+ against a spread of [0-9.e+-]+|noise floor \([0-9.e+-]+\)"
    r"|×[0-9.e+-]+|chi2/dof = [0-9.e+-]+|for [0-9]+ degrees of freedom|p = [0-9.e+-]+\))"
)
NUMBER = re.compile(r"(?<![A-Za-z_])[-+]?[0-9]+(?:\.[0-9]+)?(?:e[-+]?[0-9]+)?")

BAND = dict(band_p=6.5e-8, band_hz=0.55, band_ratio=5.0)


def _blocks(damping: list[float]) -> BlockCheck:
    return BlockCheck(
        starts=[0.0, 7.5, 15.0, 22.5],
        values={"length": [0.5, 0.501, 0.502, 0.503], "damping": damping},
        stderr={"length": [1e-4] * 4, "damping": [1e-4] * 4},
        scale={"length": 3.2, "damping": 9.0},
        units={"length": "m", "damping": "1/s"},
    )


def _uncovered(note: dict, text: str) -> list[str]:
    """The numbers of ``text`` outside its keyed opening words, its clauses and UNWORDED."""
    spans = []
    for key, pattern in NOTES:
        if key == note["key"] and (m := pattern.match(text)) is not None:
            spans.append(m.span())
    for _, pattern in CLAUSES:
        spans += [m.span() for m in pattern.finditer(text)]
    spans += [m.span() for m in UNWORDED.finditer(text)]
    return [m.group() for m in NUMBER.finditer(text) if not any(a <= m.start() < b for a, b in spans)]


@pytest.mark.parametrize("key", ["systematic", "correlatedSmall", "systematicDrift"])
def test_the_band_scans_clause_is_keyed_with_its_numbers(key: str) -> None:
    check = next(c for c, k in BRANCHES if k == key)
    said = findings({"positions": replace(check, **BAND)}, None, 1.0, 10)
    note = keyed(said[0])
    assert note["key"] == key
    assert note["clauses"] == [{"key": "bandPower", "values": {"hz": "0.55", "ratio": "5", "p": "6.5e-08"}}]


@pytest.mark.parametrize(
    ("damping", "clause"),
    [([0.010, 0.012, 0.014, 0.016], "dampingDry"), ([0.016, 0.014, 0.012, 0.010], "dampingDrag")],
)
def test_the_damping_laws_hint_is_keyed(damping: list[float], clause: str) -> None:
    (text,) = _blocks(damping).findings()
    note = keyed(text)
    assert note["key"] == "blocksDisagree"
    param = "friction" if clause == "dampingDry" else "drag"
    assert note["clauses"] == [{"key": clause, "values": {"param": param}}]
    assert "{param}" in KEYS[clause]
    assert keyed(_blocks([0.012, 0.011, 0.013, 0.012]).findings()[0])["clauses"] == []


def test_every_number_a_finding_states_reaches_the_page() -> None:
    texts = []
    for check, _ in BRANCHES:
        texts += findings({"positions": check}, None, 1.0, 10)
        texts += findings({"positions": replace(check, **BAND)}, None, 1.0, 10)
    texts += findings({}, 1e-12, 400.0, 100) + findings({}, 1.0, 20.0, 100)
    texts += _blocks([0.010, 0.012, 0.014, 0.016]).findings()
    for text in texts:
        note = keyed(text)
        assert note["key"] is not None, text
        assert not _uncovered(note, note["text"]), (note["key"], _uncovered(note, note["text"]), text)
    # a new clause with a number, unkeyed, fails
    above = findings({"positions": _check(rms=0.01, robust_rms=0.01)}, None, 1.0, 10)[0]
    extra = keyed(above + "; at 3.5 Hz")
    assert _uncovered(extra, extra["text"]) == ["3.5"]
