"""Figures (matplotlib, Agg): the energy–momentum map, Holm's Figure 2, the trajectory on the sphere and
from above, and the phase split render to non-empty PNGs of the expected pixel size (figure size ×
150 dpi), are written atomically, and refuse unknown suffixes; ``pendulab plot`` and
``pendulab phases --plot`` write them from the command line."""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np
import pytest
from conftest import SCENARIOS
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab import plot

ROSETTE = str(SCENARIOS / "rosette.toml")
PLANAR = str(SCENARIOS / "planar_large.toml")


def scenario_solution(name: str) -> pl.ExactSolution:
    sc = pl.load_scenario(SCENARIOS / f"{name}.toml")
    return pl.exact(sc.pendulum(), sc.initial_state())


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


@pytest.mark.parametrize(
    ("kind", "size"), [("both", (1950, 975)), ("sphere", (1050, 1050)), ("top", (1050, 1050))]
)
def test_trajectory_png(
    kind: str, size: tuple[int, int], pendulum: pl.Pendulum, rosette: pl.State, tmp_path: Path
) -> None:
    """The path on the sphere and/or the rosette from above, with the exact turning heights z₁, z₂ as
    circles: PNGs of the default sizes, axes in m."""
    sol = pl.exact(pendulum, rosette)
    tr = pl.simulate(pendulum, rosette, 5.0, method="rattle", dt=1e-3, save_every=10)
    out = tmp_path / f"{kind}.png"
    fig = plot.plot_trajectory(tr, out, exact=sol, kind=kind)
    assert png_size(out) == size and drawn_fraction(out) > 0.05
    assert len(fig.axes) == (2 if kind == "both" else 1)
    assert all(ax.get_xlabel() == "x [m]" and ax.get_ylabel() == "y [m]" for ax in fig.axes)
    labels = [line.get_label() for ax in fig.axes for line in ax.get_lines()]
    z1, z2 = sol.turning_heights[:2]
    assert f"turning height z₁ = {z1:.6g} m" in labels and f"turning height z₂ = {z2:.6g} m" in labels
    assert [p.name for p in tmp_path.iterdir()] == [out.name]


def test_trajectory_top_view_draws_the_path(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """The top view's path is (x, y) of the samples (thinned to max_points, the last one kept), inside
    the circle |x| = l; without a solution no turning circles are drawn."""
    tr = pl.exact(pendulum, rosette).trajectory(np.linspace(0.0, 3.0, 1001))
    fig = plot.plot_trajectory(tr, kind="top", max_points=100)
    lines = {line.get_label(): line for line in fig.axes[0].get_lines()}
    x, y = lines["path (x, y)"].get_data()
    assert len(x) == 100 and x[-1] == tr.x[-1, 0] and y[-1] == tr.x[-1, 1]
    assert np.all(np.hypot(x, y) <= pendulum.length)
    assert not any(k.startswith("turning height") for k in lines)


def test_trajectory_bad_input(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """An unknown kind, or the exact solution of another pendulum, is an InvalidInputError."""
    tr = pl.exact(pendulum, rosette).trajectory(np.linspace(0.0, 1.0, 11))
    with pytest.raises(pl.InvalidInputError, match="unknown kind 'side'"):
        plot.plot_trajectory(tr, kind="side")
    other = pl.Pendulum(length=2.0)
    with pytest.raises(pl.InvalidInputError, match="own pendulum"):
        plot.plot_trajectory(tr, exact=pl.exact(other, other.state_from_angles(1.0, 0.0, 0.0, 1.0)))


def test_phases_png(pendulum: pl.Pendulum, rosette: pl.State, tmp_path: Path) -> None:
    """One orbit: the bars Δφ_dyn, Δφ_geom, their sum (with the values written on them) and the reduced
    orbit in the (σ₁, p_z) plane, whose shaded polygon has the area A = −J Δφ_geom of the quadrature."""
    sol = pl.exact(pendulum, rosette)
    ph = sol.phases()
    out = tmp_path / "phases.png"
    fig = plot.plot_phases(sol, out)
    assert png_size(out) == (1950, 825) and drawn_fraction(out) > 0.1
    bars, orbit = fig.axes
    texts = {t.get_text() for t in bars.texts}
    assert {f"{ph.dynamic:.6g}", f"{ph.geometric:.6g}", f"{ph.sum:.6g}"} <= texts
    assert bars.get_yscale() == "linear" and "[rad]" in bars.get_ylabel()
    assert orbit.get_xlabel() == "σ₁ = z/l [1]" and "[1/s]" in orbit.get_ylabel()
    (shaded,) = orbit.patches
    u, p = shaded.get_xy().T
    area = 0.5 * abs(np.dot(u, np.roll(p, -1)) - np.dot(p, np.roll(u, -1)))
    j = pl.reduce(sol.trajectory(np.array([0.0]))).j[0]  # J₃/(m l²) [1/s]
    assert area == pytest.approx(-j * ph.geometric, rel=1e-5)


def test_phases_several_scenarios(tmp_path: Path) -> None:
    """Several orbits side by side (no orbit panel); near_top's parts (±1.6e5 rad) put the value axis
    on a symmetric-log scale. The orbit panel needs exactly one orbit; planar motion has no split."""
    sols = {name: scenario_solution(name) for name in ("rosette", "near_top", "inverted_g")}
    out = tmp_path / "several.png"
    fig = plot.plot_phases(sols, out)
    assert png_size(out) == (1695, 825) and drawn_fraction(out) > 0.05
    (ax,) = fig.axes
    assert ax.get_yscale() == "symlog"
    assert [t.get_text().split("\n")[0] for t in ax.get_xticklabels()] == list(sols)
    with pytest.raises(pl.InvalidInputError, match="one solution"):
        plot.plot_phases(list(sols.values()), orbit=True)
    with pytest.raises(pl.InvalidInputError, match="planar"):
        plot.plot_phases(scenario_solution("planar_large"))


def test_cli_plot(tmp_path: Path) -> None:
    """pendulab plot SCENARIO --out: simulated (the scenario's settings, --t-end) or --exact, each kind;
    pendulab phases --plot writes the phase figure."""
    top = tmp_path / "top.png"
    code, stdout, stderr = invoke("plot", ROSETTE, "--out", str(top), "--kind", "top", "--t-end", "2")
    assert code == 0, stderr
    assert png_size(top) == (1050, 1050) and "(rattle, t = 0 .. 2 s, 201 samples)" in stdout
    both = tmp_path / "both.png"
    code, stdout, stderr = invoke("plot", PLANAR, "-o", str(both), "--exact", "--t-end", "3")
    assert code == 0, stderr
    assert png_size(both) == (1950, 975) and "(exact, t = 0 .. 3 s, 2001 samples)" in stdout
    split = tmp_path / "split.svg"
    code, stdout, stderr = invoke("plot", ROSETTE, "-o", str(split), "--kind", "phases")
    assert code == 0, stderr
    assert split.stat().st_size > 10_000 and "dphi = 3.831162389" in stdout
    ph = tmp_path / "ph.png"
    code, stdout, stderr = invoke("phases", ROSETTE, "--periods", "1", "--plot", str(ph))
    assert code == 0, stderr
    assert png_size(ph) == (1950, 825) and stdout.rstrip().endswith(f"wrote {ph}")


@pytest.mark.parametrize(
    ("args", "needles"),
    [
        (("plot", ROSETTE, "--out", "fig.bmp"), (".bmp",)),
        (("plot", ROSETTE, "--out", "fig.png", "--kind", "side"), ("--kind", "side", "sphere")),
        (("plot", ROSETTE, "--out", "fig.png", "--t-end", "-1"), ("t_end",)),
        (("plot", PLANAR, "--out", "fig.png", "--kind", "phases"), ("planar", "J3")),
        (("phases", ROSETTE, "--plot", "fig.txt"), ("--plot", ".txt")),
    ],
)
def test_cli_plot_bad_input(
    args: tuple[str, ...], needles: tuple[str, ...], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """One `error: …` line naming the bad value, exit code 2, nothing written."""
    monkeypatch.chdir(tmp_path)
    assert_user_error(*invoke(*args), *needles)
    assert list(tmp_path.iterdir()) == []
