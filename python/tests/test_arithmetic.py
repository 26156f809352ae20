"""The fused arithmetic of the RATTLE family (``arithmetic="fused"``, and ``"auto"``, the default, which
is fused where the CPU has FMA; issue 29, docs/performance.md
"How fast, and why"): ``simulate_ensemble`` gives every trajectory the numbers of ``simulate`` with the
same arithmetic bit for bit, the fused numbers are other bits than the unfused ones (so the option does
something), "auto" is exactly the named arithmetic the CPU calls for, and bad values are refused before
any work with a message naming them. SI units: m, m/s, s."""

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


@pytest.mark.parametrize("fast", [True, False])
def test_auto_is_fused_where_the_cpu_has_fma_and_unfused_elsewhere(
    setup: tuple[pl.Pendulum, np.ndarray], fast: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The default ``arithmetic="auto"`` of simulate, Stepper and simulate_ensemble resolves by
    ``_core.fused_is_fast()`` (FMA in one instruction at the level the hot loops run at): the numbers
    are then exactly those of the named arithmetic, for the RATTLE family only (DOP853 and the
    string's stepper stay unfused); the run records a fused arithmetic in its metadata."""
    import pendulab.integrators as integrators

    monkeypatch.setattr(integrators, "fused_is_fast", lambda: fast)
    p, starts = setup
    want = "fused" if fast else "unfused"
    s0 = p.state(starts[5, :3], starts[5, 3:])
    auto = pl.simulate(p, s0, 0.5, dt=1e-3, save_every=100)
    named = pl.simulate(p, s0, 0.5, dt=1e-3, save_every=100, arithmetic=want)
    other = pl.simulate(p, s0, 0.5, dt=1e-3, save_every=100, arithmetic="unfused" if fast else "fused")
    assert np.array_equal(auto.x, named.x) and np.array_equal(auto.v, named.v)
    assert not np.array_equal(auto.x, other.x)
    assert auto.options.get("arithmetic", "unfused") == want
    st = pl.Stepper(p, s0, method="rattle4", dt=1e-3)
    st.step(300)
    ref = pl.simulate(p, s0, 0.3, method="rattle4", dt=1e-3, arithmetic=want)
    assert np.array_equal(st.state.x, ref.x[-1]) and np.array_equal(st.state.v, ref.v[-1])
    ens = pl.simulate_ensemble(p, starts[:9], 0.5, dt=1e-3, progress=False)
    ens_named = pl.simulate_ensemble(p, starts[:9], 0.5, dt=1e-3, progress=False, arithmetic=want)
    assert np.array_equal(ens.x, ens_named.x) and np.array_equal(ens.v, ens_named.v)
    assert ens.metadata.get("arithmetic", "unfused") == want
    # DOP853 has no fused form, nor the string's stepper: auto is unfused there whatever the CPU
    assert integrators.check_arithmetic("auto", "dop853") == "unfused"
    assert integrators.check_arithmetic("auto", "rattle", "string") == "unfused"
    assert integrators.check_arithmetic("auto", "rattle8") == want


def test_this_cpu_resolves_auto_by_its_instruction_set() -> None:
    """``fused_is_fast`` is the core's: true at the x86-64-v3/v4 levels (and on aarch64), false at the
    x86-64 baseline; the hot loops' level is reported by the core's benchmarks (bench/roofline)."""
    import platform

    from pendulab import _core

    flags = ""
    if platform.machine() == "x86_64":
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            flags = next((line for line in f if line.startswith("flags")), "")
        expected = all(f" {x}" in flags for x in ("avx2", "fma", "bmi2", "movbe"))
        assert _core.fused_is_fast() is expected
    elif platform.machine() in ("aarch64", "arm64"):
        assert _core.fused_is_fast() is True
