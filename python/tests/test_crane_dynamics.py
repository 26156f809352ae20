"""The crane dynamics (pendulab.crane.Crane, core ``crane`` module; docs/theory.md T-11.4 – T-11.8)
against references worked out from the physics: the hook + payload modes of the characteristic
equation in the spectrum of a simulated swing, adiabatic hoisting (θ ∝ l^(−3/4)), a wind step
(equilibrium atan(F/mg), the first peak of a lightly damped step response) and the energy balance
dE/dt = hoist + pivot + wind + damping power."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pendulab import InvalidInputError, crane

G = 9.81


def _peak_frequency(t: np.ndarray, x: np.ndarray, lo: float, hi: float) -> float:
    """The strongest angular frequency [rad/s] of x(t) in (lo, hi), a local maximum of the spectrum
    (Hann window, zero padding, parabolic interpolation of the log spectrum)."""
    dt = t[1] - t[0]
    x = (x - x.mean()) * np.hanning(len(x))
    nfft = 1 << 20
    spec = np.abs(np.fft.rfft(x, nfft))
    w = 2 * np.pi * np.fft.rfftfreq(nfft, dt)
    band = np.flatnonzero((w > lo) & (w < hi))
    i = int(band[np.argmax(spec[band])])
    assert band[0] < i < band[-1], "the strongest component in the band is at its edge"
    a, b, c = np.log(spec[i - 1 : i + 2])
    return float(w[i] + 0.5 * (a - c) / (a - 2 * b + c) * (w[1] - w[0]))


def test_hook_and_payload_modes_from_the_characteristic_equation() -> None:
    l1, l2, m1, m2 = 8.0, 3.0, 200.0, 1000.0
    c = crane.Crane(rope=l1, payload_mass=m2, hook_mass=m1, rigging=l2)
    modes = c.modes()
    r = m2 / m1
    for w in modes:  # roots of L₁L₂ω⁴ − (1 + R) g (L₁ + L₂) ω² + (1 + R) g² = 0
        assert l1 * l2 * w**4 - (1 + r) * G * (l1 + l2) * w**2 + (1 + r) * G**2 == pytest.approx(0, abs=1e-9)
    run = c.simulate(t_end=400.0, sway=(0.001, 0.0), rigging_sway=(0.002, math.pi), output_spacing=0.05)
    for w in modes:  # small swing: the nonlinear shift (∝ amplitude², 1e-3 at 0.02 rad) is ~1e-5 here
        assert _peak_frequency(run.t, run.payload[:, 0], 0.7 * w, 1.3 * w) == pytest.approx(w, rel=1e-4)
    # one body: √(g/l)
    assert crane.Crane(rope=l1).modes()[0] == pytest.approx(math.sqrt(G / l1), rel=1e-15)


def test_adiabatic_hoisting_sway_scales_as_l_to_the_minus_three_quarters() -> None:
    hoist = crane.Hoist(t=[20.0, 620.0], length=[12.0, 4.0])
    c = crane.Crane(rope=12.0, payload_mass=1000.0, hoist=hoist)
    run = c.simulate(t_end=680.0, sway=(0.03, 0.0), output_spacing=0.02)
    before = run.sway[run.t < 20.0, 0].max()
    after = run.sway[run.t > 625.0, 0].max()
    assert before == pytest.approx(0.03, rel=1e-6)
    assert after / before == pytest.approx((4.0 / 12.0) ** -0.75, rel=5e-3)
    assert np.all(run.tension[:, 0] > 0)


def test_wind_step_equilibrium_and_first_peak() -> None:
    m, rope = 1000.0, 10.0
    wind = crane.Wind(velocity=(20.0, 0.0, 0.0), area=1.0, drag_coefficient=1.2, air_density=1.225)
    c = crane.Crane(rope=rope, payload_mass=m, wind=wind)
    run = c.simulate(t_end=400.0, output_spacing=0.01)
    force = wind.force(20.0)
    alpha = math.atan(force / (m * G))
    theta = run.sway[:, 0]
    # after the swing has died out (aerodynamic damping), the load hangs at atan(F/mg)
    assert theta[run.t > 380].mean() == pytest.approx(alpha, rel=2e-3)
    # the first peak: a step onto a lightly damped oscillator overshoots by exp(−ζπ/√(1−ζ²)), ζ from
    # the linearised drag ρ c_W A w/m = 2ζω; without damping it would be exactly 2α
    omega = math.sqrt(G / rope)
    zeta = 1.225 * 1.2 * 1.0 * 20.0 / m / (2 * omega)
    first_peak = theta[run.t < math.pi / omega * 1.3].max()
    assert first_peak == pytest.approx(
        alpha * (1 + math.exp(-zeta * math.pi / math.sqrt(1 - zeta**2))), rel=5e-3
    )
    assert 1.9 * alpha < first_peak < 2 * alpha


@pytest.mark.parametrize("hooked", [False, True])
def test_energy_balance_with_hoist_pivot_wind_and_damping(hooked: bool) -> None:
    path = crane.move(distance=6.0, v_max=0.8, a_max=0.4, t_start=2.0)
    hoist = crane.Hoist(t=[1.0, 9.0, 14.0], length=[9.0, 6.5, 7.0])
    wind = crane.Wind(
        velocity=(3.0, 5.0, 0.0), area=2.0, hook_area=0.3, gust=(0, 8, 0), gust_start=5, gust_duration=4
    )
    kw = {"hook_mass": 150.0, "rigging": 2.5} if hooked else {}
    c = crane.Crane(rope=9.0, pivot=path, payload_mass=800.0, wind=wind, damping=0.02, hoist=hoist, **kw)
    run = c.simulate(t_end=30.0, sway=(0.1, 0.4), output_spacing=0.05, rtol=1e-12, atol=1e-12)
    scale = 800.0 * G * 9.0
    assert np.abs(run.energy_residual()).max() < 1e-9 * scale
    for k in ("hoist", "pivot", "wind", "damping"):
        assert np.abs(run.work[k]).max() > 1e-3 * scale, k  # each power source did work
    for k in ("hoist", "pivot"):  # the reported powers integrate to the works (trapezoid, dt = 0.05 s)
        from scipy.integrate import cumulative_trapezoid

        integral = cumulative_trapezoid(run.power[k], run.t, initial=0.0)
        assert np.abs(integral - run.work[k]).max() < 2e-3 * np.abs(run.work[k]).max(), k
    np.testing.assert_allclose(
        np.linalg.norm(run.payload[:, :] - (run.hook if hooked else run.pivot), axis=1),
        2.5 if hooked else run.rope,
        rtol=1e-12,
    )


def test_residual_vibration_after_a_shaped_move_in_the_nonlinear_model() -> None:
    rope = 10.0
    w = math.sqrt(G / rope)
    s = crane.shaper("zv", omega=0.85 * w)  # designed for the wrong frequency: V(ω) ≈ 0.23
    expected = crane.residual_vibration(s, [w])[0]

    def residual(shaper: crane.Shaper | None) -> float:
        path = crane.move(distance=5.0, v_max=0.5, a_max=0.5, shaper=shaper, t_start=1.0)
        run = crane.Crane(rope=rope, pivot=path, payload_mass=1000.0).simulate(
            t_end=path.t_end + 30.0, output_spacing=0.01
        )
        after = run.t > path.t_end + 1.0
        x = run.offset()[after, 0]
        v = (run.payload_velocity - path.velocity(run.t))[after, 0]
        return float(np.mean(np.hypot(x, v / w)))

    assert residual(s) / residual(None) == pytest.approx(expected, rel=1e-2)
    assert residual(crane.shaper("zvd", omega=w)) / residual(None) < 1e-3


@pytest.mark.parametrize(
    ("make", "word"),
    [
        (lambda: crane.Crane(rope=-1.0), "rope"),
        (lambda: crane.Crane(rope=5.0, hook_mass=100.0), "rigging"),
        (lambda: crane.Crane(rope=5.0, hoist=crane.Hoist(t=[0, 10], length=[6, 3])), "hoist"),
        (lambda: crane.Hoist(t=[0, 10], length=[6, -3]), r"length\[1\] = -3"),
        (lambda: crane.Crane(rope=5.0).simulate(t_end=-1.0), "t_end"),
        (lambda: crane.Crane(rope=5.0, payload_mass=0.0), "payload_mass"),
        (lambda: crane.Crane(rope=2.0, hoist=crane.Hoist(t=[0, 0.3], length=[2, 12])).simulate(1.0), "slack"),
        (lambda: crane.move(distance=0.0, v_max=1.0, a_max=1.0), "distance"),
        (lambda: crane.move(distance=1.0, v_max=1.0, a_max=-1.0), "a_max"),
        (lambda: crane.Crane(rope=5.0, wind=crane.Wind(velocity=(1.0, 2.0))).simulate(1.0), "wind.velocity"),
        (lambda: crane.Crane(rope=5.0, wind=crane.Wind(gust=(0, math.nan, 0))).simulate(1.0), "wind.gust"),
        (lambda: crane.Crane(rope=5.0, wind=crane.Wind(velocity="east")).simulate(1.0), "wind.velocity"),
    ],
)
def test_bad_crane_input(make, word: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(InvalidInputError, match=word):
        make()


def test_seeded_turbulence_has_its_intensity_and_repeats() -> None:
    wind = crane.Wind(velocity=(10.0, 0.0, 0.0), area=1.0, turbulence=2.0, turbulence_scale=50.0, seed=7)
    _, amp, _ = wind.modes()
    assert np.sum(amp[:, 0] ** 2) / 2 == pytest.approx(4.0, rel=2e-3)  # Σ a²/2 = σ² (tails cut at 1e∓3/T)
    t = np.arange(0.0, 20000.0, 0.25)
    w = wind.velocity_at(t)
    assert w[:, 0].mean() == pytest.approx(10.0, abs=0.15)
    assert w[:, 1].std() == pytest.approx(2.0, rel=0.08)
    c = crane.Crane(rope=10.0, payload_mass=500.0, wind=wind)
    a, b = c.simulate(t_end=20.0, output_spacing=0.1), c.simulate(t_end=20.0, output_spacing=0.1)
    np.testing.assert_array_equal(a.payload, b.payload)
    other = crane.Crane(rope=10.0, payload_mass=500.0, wind=crane.Wind(**{**wind.__dict__, "seed": 8}))
    assert np.abs(other.simulate(t_end=20.0, output_spacing=0.1).payload - a.payload).max() > 1e-3
    assert np.abs(a.energy_residual()).max() < 1e-6 * 500 * G * 10
    with pytest.raises(InvalidInputError, match="steady wind"):
        crane.Wind(turbulence=1.0).modes()


def test_tower_and_luffing_cranes_keep_the_rope_and_the_energy_balance() -> None:
    slew = crane.profile(math.radians(60), 0.1, 0.05, j_max=0.1, t_start=1.0)
    luff = crane.profile(-0.2, 0.05, 0.05, start=1.0, t_start=2.0)
    radius = crane.profile(-5.0, 0.5, 0.3, start=25.0, t_start=3.0)
    for path in (
        crane.Tower(slew=slew, radius=radius, height=40.0),
        crane.Tower(slew=slew, luff=luff, boom=30.0),
    ):
        c = crane.Crane(
            rope=12.0, pivot=path, payload_mass=2000.0, hook_mass=200.0, rigging=3.0, damping=0.01
        )
        run = c.simulate(t_end=40.0, output_spacing=0.05, rtol=1e-11, atol=1e-11)
        assert np.abs(run.energy_residual()).max() < 1e-7 * 2200 * G * 12
        # the core follows the path's quintic Hermite interpolant (knots every 0.05 s): the rope ends there
        rope = np.linalg.norm(run.hook - run.pivot, axis=1)
        np.testing.assert_allclose(rope, 12.0, rtol=1e-7)
        assert run.work["pivot"][-1] != 0.0


def test_against_an_independent_planar_model_in_minimal_coordinates() -> None:
    # payload at (x_p + l sin θ, −l cos θ) with l(t) prescribed: l θ̈ + 2 l̇ θ̇ + ẍ_p cos θ + g sin θ = 0
    # (Euler–Lagrange, hand-written), integrated by SciPy's DOP853 and compared with the core's run
    from scipy.integrate import solve_ivp

    path = crane.move(4.0, 0.6, 0.4, j_max=0.8, t_start=1.0)
    hoist = crane.Hoist(t=[2.0, 12.0], length=[10.0, 6.0])
    run = crane.Crane(rope=10.0, pivot=path, payload_mass=700.0, hoist=hoist).simulate(
        t_end=25.0, sway=(0.05, 0.0), output_spacing=0.05, rtol=1e-12, atol=1e-12
    )

    def rhs(t: float, y: np.ndarray) -> list[float]:
        th, om = y
        (rope,), (dl,) = hoist.length([t]), hoist.velocity([t])[:, 0]
        acc = path.acceleration([t])[0, 0]
        return [om, -(2 * dl * om + acc * math.cos(th) + G * math.sin(th)) / rope]

    sol = solve_ivp(rhs, (0.0, 25.0), [0.05, 0.0], method="DOP853", rtol=1e-12, atol=1e-12, t_eval=run.t)
    x_ref = hoist.length(run.t) * np.sin(sol.y[0])
    np.testing.assert_allclose(run.offset()[:, 0], x_ref, atol=1e-7)
    np.testing.assert_allclose(run.payload[:, 2], -hoist.length(run.t) * np.cos(sol.y[0]), atol=1e-7)
