"""``LQR.simulate`` runs SciPy's DOP853 in Python (~0.5 ms a step), so a long loop runs in chunks of
``CHUNK_STEPS`` settled steps (pendulab.crane.lqr): the same loop as one call to the integrator's
tolerance, bit for bit the same on every call and with or without the progress bar, which is shown
for long loops; Ctrl-C returns the loop up to the last chunk's end (``interrupted``, its ``t_end``
there) with a RuntimeWarning at the caller's line, as ``pendulab.simulate`` does. docs/cranes.md."""

from __future__ import annotations

import sys
from typing import Any

import numpy as np
import pytest
from conftest import ctrl_c_after

from pendulab import InvalidInputError, crane

LQR_MODULE = sys.modules["pendulab.crane.lqr"]  # pendulab.crane.lqr is the function of that name
CTRL = crane.lqr(0.5, q=(1.0, 1.0, 50.0, 1.0), a_max=0.6)  # |p| = 4.5 1/s: ~750 steps over 1000 s


def _loop(**kw: Any) -> crane.LQRRun:
    return CTRL.simulate(3.0, t_end=1000.0, sway=0.1, **kw)


def test_a_long_loop_runs_in_chunks_as_one_call_and_the_same_on_every_call(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    chunked = _loop(progress=False)
    assert len(chunked._dense.sols) >= 4 and chunked.switches.size == 1 and not chunked.interrupted
    again = _loop(progress=False)
    t = np.linspace(0.0, 1000.0, 100_001)
    for a, b in zip(chunked.trolley(t), again.trolley(t), strict=True):  # chunk ends depend on the input
        assert a.tobytes() == b.tobytes()
    monkeypatch.setattr(LQR_MODULE, "CHUNK_STEPS", 10**9)
    whole = _loop(progress=False)
    assert len(whole._dense.sols) == 2  # the two modes, one call each
    np.testing.assert_allclose(chunked.switches, whole.switches, rtol=0, atol=1e-10)
    # measured 2e-11 rad, 2e-11 m, 5e-10 m/s²: a restart of DOP853 at each chunk's end, rtol 1e-11
    np.testing.assert_allclose(chunked.sway(t), whole.sway(t), rtol=0, atol=1e-10)
    for a, b in zip(chunked.trolley(t), whole.trolley(t), strict=True):
        np.testing.assert_allclose(a, b, rtol=0, atol=5e-9)


def test_the_progress_bar_shows_for_long_loops_and_changes_nothing(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    quiet = _loop(progress=False)
    assert "LQR loop" not in capsys.readouterr().err
    shown = _loop(progress=True)
    assert "LQR loop" in capsys.readouterr().err
    t = np.linspace(0.0, 1000.0, 10_001)
    assert shown.sway(t).tobytes() == quiet.sway(t).tobytes()
    _loop()  # ~750 steps: no bar by default
    assert "LQR loop" not in capsys.readouterr().err
    monkeypatch.setattr(LQR_MODULE, "PROGRESS_AFTER_STEPS", 100)
    _loop()
    assert "LQR loop" in capsys.readouterr().err


def _stop_at_call(monkeypatch: pytest.MonkeyPatch, n: int) -> None:
    """Ctrl-C during the n-th chunk (1-based)."""
    piece = LQR_MODULE._Loop.piece
    calls = [0]

    def interrupted_piece(self: Any, *args: Any) -> Any:
        calls[0] += 1
        if calls[0] == n:
            raise KeyboardInterrupt
        return piece(self, *args)

    monkeypatch.setattr(LQR_MODULE._Loop, "piece", interrupted_piece)


def test_ctrl_c_returns_the_loop_up_to_the_last_chunk_with_a_warning(monkeypatch: pytest.MonkeyPatch) -> None:
    full = _loop(progress=False)
    ends = [float(s.t_max) for s in full._dense.sols]  # the chunks' ends
    _stop_at_call(monkeypatch, 3)
    stopped = r"^LQR\.simulate interrupted at t = \S+ s of t_end = 1000 s"
    with pytest.warns(RuntimeWarning, match=stopped) as w:
        run = _loop(progress=True)
    assert len(w) == 1 and w[0].filename == __file__  # points at the caller's line
    assert run.interrupted and run.t_end == run.span[1] == ends[1] < 1000.0
    t = np.linspace(0.0, run.t_end, 1001)
    assert run.sway(t).tobytes() == full.sway(t).tobytes()  # what was reached, as in the full loop
    with pytest.raises(InvalidInputError, match=rf"ends at t_end = {run.t_end:.10g} s, .* t_end = 1000 s"):
        crane.Crane(rope=0.5, pivot=run).simulate(t_end=1000.0)


def test_ctrl_c_in_the_first_chunk_returns_the_start(monkeypatch: pytest.MonkeyPatch) -> None:
    _stop_at_call(monkeypatch, 1)
    with pytest.warns(RuntimeWarning, match=r"interrupted at t = 2 s of t_end = 1000 s") as w:
        run = CTRL.simulate(3.0, t_end=1000.0, t_start=2.0, sway=0.1, progress=False)
    assert w[0].filename == __file__ and run.interrupted and run.span == (2.0, 2.0)
    x, v, u = run.trolley([0.0, 2.0, 5.0])  # at rest; u steps to −K z₀ at t_start (the path's break)
    assert x.tolist() == v.tolist() == [0.0, 0.0, 0.0] and u.tolist() == [0.0, 0.6, 0.0]
    assert run.sway([2.0]).tolist() == [0.1]


def test_sigint_stops_a_long_loop_cleanly() -> None:
    """A real Ctrl-C (SIGINT) inside SciPy's integrator, as the user sends it: ~45 s of loop asked."""
    script = (
        "import warnings\n"
        "from pendulab import crane\n"
        "c = crane.lqr(0.05, a_max=0.6)\n"
        "print('start', flush=True)\n"
        "with warnings.catch_warnings(record=True) as w:\n"
        "    warnings.simplefilter('always')\n"
        "    r = c.simulate(1.0, t_end=4e4, progress=False)\n"
        "print(r.interrupted, r.t_end, [str(x.message) for x in w])\n"
    )
    proc = ctrl_c_after([sys.executable, "-c", script], "start", wait=1.5)
    out, err = proc.stdout, proc.stderr
    assert proc.returncode == 0, err
    flag, t_end, messages = out.strip().split(" ", 2)
    assert flag == "True" and 0 < float(t_end) < 4e4, out
    assert f"LQR.simulate interrupted at t = {float(t_end):g} s of t_end = 40000 s" in messages, out
