"""Fuzzed data files and scenario text (issue 30 item 7): whatever the text, the data-file reader
returns the data kinds of pl.fit (arrays of one length, finite or NaN, within their bounds) or raises
InvalidInputError; the nesting check returns or raises InvalidInputError; a scenario from the text
loads or raises ScenarioError. Texts are built from the characters that steer the readers (separators,
quotes, brackets, comment and unit marks, a BOM, CR) around valid headers and rows, and grown to sizes
near the caps for the slow paths (linear time: test_text_linear.py)."""

from __future__ import annotations

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import pendulab as pl
from pendulab.fitting.cells import BOUNDS
from pendulab.fitting.table import parse_table
from pendulab.scenario import Scenario, ScenarioError
from pendulab.validate import check_nesting

ALPHABET = "0123456789.,;\t \n\r\"'#()[]/:eE+-tTxyzaNAnif°\ufeffµ\x00\x1b"
PIECES = [
    "t,x,z\n",
    "t;x;z\n",
    "t\tx\ty\n",
    '"Time (s)","Acceleration x (m/s^2)","Acceleration y (m/s^2)","Acceleration z (m/s^2)"\n',
    "t / s\tα / °\n",
    "mass A\n",
    "Latest: Time (s),Latest: X (m),Latest: Y (m)\n",
    "0,0.1,-0.5\n",
    "0,1;2,5;-0,5\n",
    "1e308,",
    "5e-324",
    "inf",
    ",,",
    "NA",
    '""',
    "#",
]
TEXT = st.lists(st.one_of(st.sampled_from(PIECES), st.text(ALPHABET, max_size=12)), max_size=40).map("".join)
FUZZ = settings(
    max_examples=150, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow]
)


@FUZZ
@given(TEXT, st.sampled_from([None, ["t", "x", "z"], ["t", "-", "angle"], ["t", "x", "y"]]))
def test_any_text_is_data_or_a_clear_error(text: str, columns: list[str] | None) -> None:
    try:
        data = parse_table(text, columns, "fuzz.csv")
    except pl.InvalidInputError as e:
        assert str(e) and len(str(e)) < 2000
        return
    n = len(data["t"])
    assert n >= 1 and len(data) >= 2
    for kind, values in data.items():
        a = np.asarray(values, dtype=np.float64)
        assert a.shape[0] == n, kind
        assert not np.isinf(a).any(), kind
        assert (np.abs(a[np.isfinite(a)]) <= max(BOUNDS.values()) * 2).all(), kind


@FUZZ
@given(TEXT.map(lambda s: s.replace("t,x,z", "a = [").replace("mass A", 'b = """')))
def test_any_text_passes_the_nesting_check_or_is_refused(text: str) -> None:
    try:
        check_nesting(text)
    except pl.InvalidInputError as e:
        assert "nest more than" in str(e)
    try:
        Scenario.from_toml_str(text, "fuzz.toml")
    except ScenarioError as e:
        assert "fuzz.toml" in str(e)
