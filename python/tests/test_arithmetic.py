"""The opt-in fused arithmetic of the RATTLE family (``arithmetic="fused"``; issue 29, docs/performance.md
"How fast, and why"): ``simulate_ensemble`` gives every trajectory the numbers of ``simulate`` with the
same arithmetic bit for bit, the fused numbers are other bits than the default's (so the option does
something), the default is unchanged by the option's existence (the ensemble still equals the
single-trajectory RATTLE, and the golden files are untouched: test_golden.py), and bad values are
refused before any work with a message naming them. SI units: m, m/s, s."""

from __future__ import annotations

import numpy as np
import pytest

import pendulab as pl


@pytest.fixture(scope="module")
def setup() -> tuple[pl.Pendulum, np.ndarray]:
    p = pl.Pendulum(length=1.3, g=9.81)
    # rosette-like starts and one planar swing over the top (x ≡ 0: signed zeros in the lanes)
    starts = pl.states_from_angles(p, theta=np.linspace(0.2, 2.8, 70), phi=0.3, phi_dot=1.2)
    over = p.state([0.0, 0.0, -1.3], [0.0, 8.0, 0.0]).as_array()
    return p, np.vstack([starts, over])


@pytest.mark.parametrize("arithmetic", ["unfused", "fused"])
def test_the_ensemble_is_the_single_trajectory_of_its_arithmetic_bit_for_bit(
    setup: tuple[pl.Pendulum, np.ndarray], arithmetic: str
) -> None:
    p, starts = setup
    ens = pl.simulate_ensemble(p, starts, 1.5, dt=1e-3, save_every=500, progress=False, arithmetic=arithmetic)
    for k in (0, 33, 69, 70):  # the first and the last block's lanes, the planar start
        start = p.state(starts[k, :3], starts[k, 3:])
        tr = pl.simulate(p, start, 1.5, dt=1e-3, save_every=500, arithmetic=arithmetic)
        assert np.array_equal(tr.x, ens.x[k]) and np.array_equal(tr.v, ens.v[k]), (arithmetic, k)
    assert ens.metadata.get("arithmetic", "unfused") == arithmetic


def test_fused_gives_other_bits_to_round_off(setup: tuple[pl.Pendulum, np.ndarray]) -> None:
    p, starts = setup
    a, b = (
        pl.simulate_ensemble(p, starts, 1.0, dt=1e-3, progress=False, arithmetic=ar)
        for ar in ("unfused", "fused")
    )
    assert not np.array_equal(a.x, b.x)
    # both are RATTLE: the difference is round-off, far below the method's error at dt = 1 ms
    assert np.max(np.abs(a.x - b.x)) < 1e-13


def test_fused_single_trajectory_compositions_and_stepper() -> None:
    p = pl.Pendulum()
    s0 = p.state_from_angles(theta=1.0, phi_dot=1.5)
    for method in ("rattle", "rattle4", "rattle8"):
        plain, fused = (
            pl.simulate(p, s0, 0.5, method=method, dt=1e-3, arithmetic=ar) for ar in ("unfused", "fused")
        )
        assert not np.array_equal(plain.x, fused.x), method
        assert np.max(np.abs(plain.x - fused.x)) < 1e-13, method
        assert fused.options["arithmetic"] == "fused" and "arithmetic" not in plain.options


def test_bad_arithmetic_is_refused_before_any_work(setup: tuple[pl.Pendulum, np.ndarray]) -> None:
    p, starts = setup
    s0 = p.state(starts[0, :3], starts[0, 3:])
    with pytest.raises(pl.InvalidInputError, match=r"arithmetic.*'fma'.*'unfused', 'fused'"):
        pl.simulate_ensemble(p, starts, 1.0, arithmetic="fma")
    with pytest.raises(pl.InvalidInputError, match=r"RATTLE family.*'dop853'"):
        pl.simulate_ensemble(p, starts, 1.0, method="dop853", arithmetic="fused")
    for method in ("dop853", "rk4", "rkmk4"):
        with pytest.raises(pl.InvalidInputError, match=rf"RATTLE family.*'{method}'"):
            pl.simulate(p, s0, 1.0, method=method, arithmetic="fused")
    with pytest.raises(pl.InvalidInputError, match="arithmetic"):
        pl.simulate(p, s0, 1.0, arithmetic=None)  # type: ignore[arg-type]
