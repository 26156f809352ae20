"""Crane figures (pendulab.crane.plot): each draws what it says (lines with the right data) and saves."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pendulab import crane

pytest.importorskip("matplotlib")

from pendulab.crane.plot import plot_grid, plot_sensitivity, plot_sway, plot_top_view
from pendulab.plot import save_figure


def test_sensitivity_curves_are_the_residual_vibration(tmp_path: Path) -> None:
    shapers = [crane.shaper("zv", 2.0), crane.shaper("ei", 2.0)]
    fig = plot_sensitivity(shapers, ratio=(0.5, 1.5))
    lines = fig.axes[0].get_lines()[:2]
    for line, s in zip(lines, shapers, strict=True):
        x, y = line.get_data()
        np.testing.assert_allclose(y, 100 * crane.residual_vibration(s, np.asarray(x) * 2.0), rtol=1e-12)
    assert save_figure(fig, tmp_path / "v.png").stat().st_size > 1000


def test_sway_top_view_and_grid(tmp_path: Path) -> None:
    path = crane.move(2.0, 0.5, 0.5, direction=(1, 1, 0))
    run = crane.Crane(rope=5.0, pivot=path).simulate(t_end=10.0, output_spacing=0.1)
    fig = plot_sway({"run": run}, t_marks=[path.t_end])
    _, y = fig.axes[0].get_lines()[0].get_data()
    np.testing.assert_allclose(y, run.offset()[:, 0])
    top = plot_top_view({"run": run})
    np.testing.assert_allclose(top.axes[0].get_lines()[0].get_data()[1], run.payload[:, 1])
    res = crane.residual_grid([4.0, 6.0], [2.0, 5.0], [None], settle=3.0, output_spacing=0.1)
    g = plot_grid(res)
    np.testing.assert_allclose(g.axes[0].get_lines()[0].get_data()[1], np.median(res.sway[0], axis=1))
    for name, f in (("s.png", fig), ("t.svg", top), ("g.pdf", g)):
        assert save_figure(f, tmp_path / name).stat().st_size > 500
