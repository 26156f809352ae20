"""Figures (matplotlib, Agg): the energy–momentum map and Holm's Figure 2 render to non-empty PNGs of the
expected pixel size (figure size × 150 dpi), are written atomically, and refuse unknown suffixes."""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np
import pytest

import pendulab as pl
from pendulab import plot


def png_size(path: Path) -> tuple[int, int]:
    """(width, height) in pixels from the PNG header; fails if the file is not a PNG."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and data[12:16] == b"IHDR"
    return struct.unpack(">II", data[16:24])


def drawn_fraction(path: Path) -> float:
    """Fraction of pixels that are not plain white (the figure is not blank)."""
    import matplotlib.image as mpimg

    img = mpimg.imread(path)[:, :, :3]
    return float(np.mean(np.any(img < 0.98, axis=2)))


def test_em_map_png(tmp_path: Path) -> None:
    """W as colour with the boundary, the critical line and the monodromy loop: a 1125×900 PNG, mostly
    drawn."""
    emm = pl.em_map(pl.Pendulum(), grid=(80, 60))
    out = tmp_path / "em.png"
    fig = plot.plot_em_map(emm, out)
    assert png_size(out) == (1125, 900) and drawn_fraction(out) > 0.3
    ax = fig.axes[0]
    assert "J₃ [kg m²/s]" in ax.get_xlabel() and "E [J]" in ax.get_ylabel()
    labels = [line.get_label() for line in ax.get_lines()]
    assert any(
        s.startswith("loop around the top: W changes by ") and s.endswith("1.000000000") for s in labels
    )
    assert [p.name for p in tmp_path.iterdir()] == ["em.png"]  # no temporary file left


def test_reduced_png(pendulum: pl.Pendulum, rosette: pl.State, tmp_path: Path) -> None:
    """Holm's Figure 2 for the rosette: a 1125×975 PNG with the orbit, the surface and the plane."""
    sol = pl.exact(pendulum, rosette)
    tr = sol.trajectory(np.linspace(0.0, sol.period_z, 400))
    out = tmp_path / "reduced.png"
    fig = plot.plot_reduced(tr, out, resolution=30)
    assert png_size(out) == (1125, 975) and drawn_fraction(out) > 0.1
    ax = fig.axes[0]
    assert "σ₃" in ax.get_zlabel() and "[1/s²]" in ax.get_zlabel()
    plot.plot_reduced(pl.reduce(tr), tmp_path / "again.svg")
    assert (tmp_path / "again.svg").stat().st_size > 1000


def test_unknown_suffix_is_refused(tmp_path: Path) -> None:
    """A suffix matplotlib should not guess at is an InvalidInputError, and nothing is written."""
    fig = plot.new_figure()
    with pytest.raises(pl.InvalidInputError, match="bmp"):
        plot.save_figure(fig, tmp_path / "x.bmp")
    assert list(tmp_path.iterdir()) == []
