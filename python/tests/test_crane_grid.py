"""The grid of crane runs (pendulab.crane.residual_grid, core ``crane::grid``): each cell is the same
number as one ``Crane.simulate`` of that case, a shaper lowers the sway across the grid, and bad
grids are refused before any work."""

from __future__ import annotations

import math
import sys

import numpy as np
import pytest
from conftest import ctrl_c_after

from pendulab import InvalidInputError, crane
from pendulab.crane import grid as grid_module


def test_grid_cells_equal_single_runs() -> None:
    zvd = crane.shaper("zvd", omega=math.sqrt(9.81 / 10.0))
    res = crane.residual_grid(
        [8.0, 10.0, 12.0], [2.0, 10.0], [None, zvd], settle=15.0, output_spacing=0.05, rtol=1e-10, atol=1e-10
    )
    assert res.sway.shape == (2, 3, 2) and res.labels == ("unshaped", "zvd")
    for i, s in enumerate((None, zvd)):
        for j, rope in enumerate(res.ropes):
            for k, ratio in enumerate(res.ratios):
                path = crane.move(5.0, 0.5, 0.5, shaper=s)
                c = crane.Crane(
                    rope=rope, pivot=path, payload_mass=100.0 * ratio, hook_mass=100.0, rigging=2.0
                )
                # start at rest before the move, on the grid's save times t_end + i dt
                t0 = path.t_end - 0.05 * (math.ceil(path.t_end / 0.05) + 1)
                run = c.simulate(
                    t_end=path.t_end + 15.0, output_spacing=0.05, t_start=t0, rtol=1e-10, atol=1e-10
                )
                after = run.t >= path.t_end - 1e-12
                single = np.hypot(*run.offset()[after].T).max()
                assert res.sway[i, j, k] == pytest.approx(single, rel=1e-6, abs=1e-9)
    assert np.all(res.sway[1] < 0.2 * res.sway[0])  # ZVD for 10 m helps over 8…12 m and both ratios


def test_bad_grids() -> None:
    with pytest.raises(InvalidInputError, match="rope"):
        crane.residual_grid([-1.0], [1.0], [None])
    with pytest.raises(InvalidInputError, match="ratio"):
        crane.residual_grid([5.0], [0.0], [None])
    with pytest.raises(InvalidInputError, match="exceed"):
        crane.residual_grid(np.ones(1001), np.ones(1000), [None, None])


def test_the_grid_runs_in_chunks_and_ctrl_c_keeps_what_is_done(monkeypatch: pytest.MonkeyPatch) -> None:
    """The sweeps' driver: chunks of one shaper × a block of ropes give the same numbers as one call of
    the core; SIGINT stops after the chunks in flight, the rest NaN, ``interrupted`` set, a warning."""
    zv = crane.shaper("zv", omega=1.0)
    args = (np.linspace(6, 12, 5), [2.0, 5.0], [None, zv])
    whole = crane.residual_grid(*args, settle=5.0, progress=False)  # one chunk per shaper
    monkeypatch.setattr(grid_module, "CHUNK_CASES", 4)  # blocks of 2 ropes: 3 chunks per shaper
    chunked = crane.residual_grid(*args, settle=5.0, progress=True, workers=2)
    assert not chunked.interrupted and np.all(np.isfinite(chunked.sway))
    np.testing.assert_array_equal(chunked.sway, whole.sway)
    script = (
        "import numpy as np, warnings\n"
        "from pendulab import crane\n"
        "print('start', flush=True)\n"
        "with warnings.catch_warnings(record=True) as w:\n"
        "    warnings.simplefilter('always')\n"
        "    ropes, ratios = np.linspace(5, 30, 400), np.geomspace(1, 30, 50)\n"
        "    r = crane.residual_grid(ropes, ratios, [None], progress=False)\n"
        "print(r.interrupted, int(np.isnan(r.sway).sum()), r.sway.size, [str(x.message) for x in w])\n"
    )
    proc = ctrl_c_after([sys.executable, "-c", script], "start", wait=1.5)
    out, err = proc.stdout, proc.stderr
    assert proc.returncode == 0, err
    flag, nan, size, messages = out.strip().split(" ", 3)
    assert flag == "True" and 0 < int(nan) < int(size) == 20_000, out
    assert "crane grid interrupted" in messages, out


def test_the_interrupted_grid_warns_at_the_callers_line(monkeypatch: pytest.MonkeyPatch) -> None:
    """The RuntimeWarning names the first frame outside pendulab (``pendulab._warn.warn_user``)."""

    def ctrl_c(*_args: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(grid_module, "drive", ctrl_c)
    with pytest.warns(RuntimeWarning, match=r"^crane grid interrupted: 0 of 4 cases computed") as caught:
        res = crane.residual_grid([4.0, 5.0], [2.0, 3.0], [None], settle=3.0)
    assert len(caught) == 1 and caught[0].filename == __file__
    assert res.interrupted and np.isnan(res.sway).all()
