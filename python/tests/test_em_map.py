"""The energy–momentum map from Python (T-6.4, T-4.5): W defined exactly on the image, Puiseux's bounds
π < 2π|W| < 2π, agreement with the exact solution of a state with that (J₃, E), the conical boundary,
the SI scaling and the critical values, monodromy ±1 around the top, the mirror g < 0, files, bad input.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import pendulab as pl
from pendulab import _core


@pytest.fixture(scope="module")
def emm() -> pl.EMMap:
    return pl.em_map(pl.Pendulum(length=1.0, g=9.81, mass=1.0), grid=(121, 91))


def image_margin(eps: np.ndarray, j: np.ndarray) -> np.ndarray:
    """max over u ∈ [−1, 1] of P(u) = 2(ε − u)(1 − u²) − j² (T-4.1), by brute force on a fine grid:
    > 0 inside the image of the energy–momentum map, < 0 outside."""
    u = np.linspace(-1.0, 1.0, 2001)[:, None]
    return np.max(2 * (eps[None, :] - u) * (1 - u * u), axis=0) - j * j


def test_w_is_defined_exactly_on_the_image(emm: pl.EMMap) -> None:
    """W is NaN outside the image and on J₃ = 0, finite inside (away from a thin band at the boundary)."""
    ee, jj = np.meshgrid(emm.E / emm.energy_unit, emm.J3 / emm.momentum_unit, indexing="ij")
    margin = image_margin(ee.ravel(), jj.ravel()).reshape(ee.shape)
    finite = np.isfinite(emm.W)
    assert emm.W.shape == (91, 121)
    assert not np.any(finite & ((margin < -1e-5) | (jj == 0)))
    assert np.all(finite[(margin > 1e-5) & (jj != 0)])
    assert np.all(np.isnan(emm.W[emm.E + emm.energy_unit < 0]))
    assert np.count_nonzero(finite) > 0.3 * emm.W.size


def test_puiseux_bounds_and_symmetry(emm: pl.EMMap) -> None:
    """π < 2πW < 2π wherever J₃ > 0 (Puiseux, T-4.5), and W(−J₃) = −W(J₃)."""
    w = emm.W[:, emm.J3 > 0]
    w = w[np.isfinite(w)]
    assert w.size > 1000 and np.all(w > 0.5) and np.all(w < 1.0)
    assert np.allclose(emm.W[:, ::-1], -emm.W, equal_nan=True, rtol=0, atol=1e-12)


def test_puiseux_on_random_points() -> None:
    """The same bounds on 2000 random (ε, j) inside the image, straight from the core."""
    rng = np.random.default_rng(3)
    eps, j = rng.uniform(-1.0, 4.0, 2000), rng.uniform(1e-6, 3.0, 2000)
    w = _core.rotation_numbers(eps, j)
    ok, margin = np.isfinite(w), image_margin(eps, j)
    assert np.all(ok[margin > 1e-5]) and not np.any(ok[margin < -1e-5]) and np.count_nonzero(ok) > 500
    assert np.all((w[ok] > 0.5) & (w[ok] < 1.0))


def test_w_equals_the_exact_solutions_rotation_number(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """The map at the rosette's own (J₃, E) gives the rosette's Δφ/2π."""
    e, j3 = pendulum.energy(rosette), pendulum.j3(rosette)
    m = pl.em_map(pendulum, j_range=(j3, j3 + 1.0), e_range=(e, e + 1.0), grid=(2, 2))
    assert m.W[0, 0] == pytest.approx(pl.exact(pendulum, rosette).rotation_number, rel=1e-12)


def test_boundary_is_the_conical_family_in_si() -> None:
    """The boundary point at height u = −cos α is the conical orbit at polar angle α (T-6.1): its J₃ and E
    match the state circling with Ω² = g/(l cos α); SI scaling E = ε m g l, J₃ = j m l² ω₀; the vertex and
    the critical values are (0, ∓m g l)."""
    p = pl.Pendulum(length=2.0, g=3.0, mass=0.5)
    alpha = math.radians(50)
    cone = p.state_from_angles(theta=alpha, phi_dot=math.sqrt(p.g / (p.length * math.cos(alpha))))
    j, eps = _core.conical_curve(np.array([-math.cos(alpha)]))
    assert j[0] * p.mass * p.length**2 * p.omega0 == pytest.approx(p.j3(cone), rel=1e-13)
    assert eps[0] * p.mass * p.g * p.length == pytest.approx(p.energy(cone), rel=1e-13)
    m = pl.em_map(p, grid=(11, 11))
    mgl = 0.5 * 3.0 * 2.0
    assert m.energy_unit == mgl and m.critical_values == {"bottom": (0.0, -mgl), "top": (0.0, mgl)}
    jb, eb = m.boundary
    assert eb[np.argmin(np.abs(jb))] == -mgl and np.all(eb >= -mgl)
    assert np.allclose(jb, -jb[::-1]) and np.allclose(eb, eb[::-1])


def test_monodromy_around_the_top(emm: pl.EMMap) -> None:
    """T-6.4: W carried continuously once around (0, mgl) changes by ±1 to 1e-9, for several loops; the
    loop's continued W values show the same change."""
    for r, n in ((0.5, 720), (0.2, 360), (1.0, 1440)):
        assert abs(abs(emm.monodromy(r, n)) - 1.0) <= 1e-9
    j3, e, w = emm.loop(0.5)
    assert w[-1] - w[0] == pytest.approx(emm.monodromy(0.5), abs=1e-12)
    assert np.max(np.abs(np.diff(w))) < 0.05
    assert np.allclose(np.hypot(j3 / emm.momentum_unit, e / emm.energy_unit - 1.0), 0.5)
    with pytest.raises(pl.InvalidInputError, match=r"radius|r ="):
        emm.monodromy(5.0)


def test_negative_gravity_is_the_mirror_image() -> None:
    """E, J₃ and Δφ are unchanged by z → −z with g → −g, so the map for g < 0 equals that for |g|."""
    a = pl.em_map(pl.Pendulum(g=-4.0), grid=(15, 13))
    b = pl.em_map(pl.Pendulum(g=4.0), grid=(15, 13))
    assert np.array_equal(a.W, b.W, equal_nan=True) and a.critical_values == b.critical_values


def test_files(emm: pl.EMMap, tmp_path: Path) -> None:
    """.nc and .csv hold E [J], J3 [kg m²/s] and W with units; other suffixes are refused."""
    import xarray as xr

    emm.save(tmp_path / "em.nc")
    with xr.open_dataset(tmp_path / "em.nc", engine="scipy") as ds:
        assert ds["W"].shape == (91, 121) and ds["E"].attrs["units"] == "J"
        assert np.array_equal(ds["W"].values, emm.W, equal_nan=True)
    emm.save(tmp_path / "em.csv")
    lines = (tmp_path / "em.csv").read_text().splitlines()
    assert lines[0].startswith("# pendulab em-map") and lines[1] == "E [J],J3 [kg m^2/s],W [1]"
    assert len(lines) == 2 + 91 * 121
    with pytest.raises(pl.InvalidInputError, match="xlsx"):
        emm.save(tmp_path / "em.xlsx")


def test_bad_input() -> None:
    """g = 0, reversed or non-finite ranges, bad grids: InvalidInputError naming the value."""
    p = pl.Pendulum()
    with pytest.raises(pl.InvalidInputError, match="g = 0"):
        pl.em_map(pl.Pendulum(g=0.0))
    with pytest.raises(pl.InvalidInputError, match="e_range"):
        pl.em_map(p, e_range=(3.0, 1.0))
    with pytest.raises(pl.InvalidInputError, match="j_range"):
        pl.em_map(p, j_range=(0.0, float("inf")))
    with pytest.raises(pl.InvalidInputError, match="n_E"):
        pl.em_map(p, grid=(10, 1))
    with pytest.raises(pl.InvalidInputError, match="exceeds"):
        pl.em_map(p, grid=(5000, 5000))
    with pytest.raises(pl.InvalidInputError, match="two integers"):
        pl.em_map(p, grid=400)  # type: ignore[arg-type]
