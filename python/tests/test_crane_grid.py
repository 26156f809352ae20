"""The grid of crane runs (pendulab.crane.residual_grid, core ``crane::grid``): each cell is the same
number as one ``Crane.simulate`` of that case, a shaper lowers the sway across the grid, and bad
grids are refused before any work."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pendulab import InvalidInputError, crane


def test_grid_cells_equal_single_runs() -> None:
    zvd = crane.shaper("zvd", omega=math.sqrt(9.81 / 10.0))
    res = crane.residual_grid(
        [8.0, 10.0, 12.0], [2.0, 10.0], [None, zvd], settle=15.0, dt=0.05, rtol=1e-10, atol=1e-10
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
                run = c.simulate(t_end=path.t_end + 15.0, dt=0.05, t_start=t0, rtol=1e-10, atol=1e-10)
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
