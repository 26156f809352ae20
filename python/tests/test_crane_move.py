"""Crane moves and paths (pendulab.crane.move/profile/Gantry/Tower, docs/theory.md T-11.3): the limits
hold, the derivatives are those of the position, shaping keeps the distance and adds the shaper's
length, and a shaped move drives the existing moving-pivot model (``Pendulum(pivot_samples=...)``)
with the residual sway |Σ A_i e^{iωt_i}| of the unshaped one."""

from __future__ import annotations

import math

import numpy as np
import pytest

import pendulab as pl
from pendulab import crane


def _derivative(f, t: np.ndarray, h: float = 1e-5) -> np.ndarray:  # type: ignore[no-untyped-def]
    return (f(t + h) - f(t - h)) / (2 * h)


@pytest.mark.parametrize(
    ("dist", "v", "a", "j"),
    [
        (5.0, 0.5, 0.5, None),
        (0.1, 0.5, 0.5, None),
        (-7.0, 1.0, 0.3, 0.5),
        (0.2, 1.0, 0.3, 0.5),
        (3.0, 0.6, 0.4, 0.2),
    ],
)
def test_profiles_meet_the_distance_and_the_limits(dist: float, v: float, a: float, j: float | None) -> None:
    p = crane.profile(dist, v, a, j_max=j, t_start=2.0)
    assert p.distance == pytest.approx(dist, rel=1e-12)
    t = np.linspace(1.0, p.t_end + 1.0, 20001)
    assert np.abs(p.velocity(t)).max() <= v * (1 + 1e-12)
    assert np.abs(p.acceleration(t)).max() <= a * (1 + 1e-12)
    assert p.position(1.5) == 0.0 and p.velocity(p.t_end + 0.5) == pytest.approx(0.0, abs=1e-12)
    inner = t[np.min(np.abs(t[:, None] - p.knots[None, :]), axis=1) > 1e-4]
    np.testing.assert_allclose(_derivative(p.position, inner), p.velocity(inner), atol=1e-8)
    np.testing.assert_allclose(_derivative(p.velocity, inner), p.acceleration(inner), atol=1e-8)
    if j is not None:
        jerk = _derivative(p.acceleration, inner)
        assert np.abs(jerk).max() <= j * (1 + 1e-6)
    # the fastest: at a limit somewhere (the speed, or the acceleration or jerk for short moves)
    ratios = [np.abs(p.velocity(t)).max() / v, np.abs(p.acceleration(t)).max() / a]
    if j is not None:
        ratios.append(np.abs(_derivative(p.acceleration, inner)).max() / j)
    assert max(ratios) == pytest.approx(1.0, rel=1e-6)


def test_trapezoid_timing() -> None:
    p = crane.profile(5.0, 0.5, 0.5)  # 1 s up, 9 s cruise, 1 s down
    np.testing.assert_allclose(p.knots, [0, 1, 10, 11], atol=1e-12)
    q = crane.profile(0.5, 1.0, 0.5)  # triangle: v = √(aD) = 0.5, t_a = 1
    np.testing.assert_allclose(q.knots, [0, 1, 1, 2], atol=1e-12)


def test_shaping_keeps_the_distance_and_adds_the_shaper() -> None:
    s = crane.shaper("zvd", omega=1.1)
    p = crane.profile(4.0, 0.5, 0.5, j_max=2.0)
    q = p.shaped(s)
    assert q.distance == pytest.approx(4.0, rel=1e-12)
    assert q.t_end == pytest.approx(p.t_end + s.duration, rel=1e-12)
    t = np.linspace(0, q.t_end, 1001)
    conv = sum(a * p.acceleration(t - ti) for a, ti in zip(s.amplitudes, s.times, strict=True))
    np.testing.assert_allclose(q.acceleration(t), conv, atol=1e-12)


def test_tower_and_luffing_derivatives() -> None:
    slew = crane.profile(math.radians(90), 0.1, 0.05, j_max=0.1)
    radius = crane.profile(-8.0, 0.6, 0.3, j_max=0.5, start=30.0, t_start=3.0)
    luff = crane.profile(-0.3, 0.05, 0.03, j_max=0.05, start=1.0, t_start=1.0)
    for path in (
        crane.Tower(slew=slew, radius=radius, height=40.0),
        crane.Tower(slew=slew, luff=luff, boom=35.0, height=5.0),
    ):
        t = np.linspace(0.5, 40.0, 777)
        knots = np.concatenate([slew.knots, radius.knots, luff.knots])
        t = t[np.min(np.abs(t[:, None] - knots[None, :]), axis=1) > 1e-4]  # away from the jerk steps
        np.testing.assert_allclose(_derivative(path.position, t), path.velocity(t), atol=1e-6)
        np.testing.assert_allclose(_derivative(path.velocity, t), path.acceleration(t), atol=1e-6)
    r = np.hypot(*crane.Tower(slew=slew, radius=radius).position([100.0])[0, :2])
    assert r == pytest.approx(22.0, rel=1e-11)


def test_a_shaped_move_drives_the_moving_pivot_model() -> None:
    rope, g = 10.0, 9.81
    w = math.sqrt(g / rope)
    s = crane.shaper("zv", omega=0.8 * w)
    expected = crane.residual_vibration(s, [w])[0]

    def residual(shaper: crane.Shaper | None) -> float:
        path = crane.move(distance=3.0, v_max=0.5, a_max=0.3, j_max=1.0, shaper=shaper, t_start=1.0)
        t_end = path.t_end + 25.0
        pend = pl.Pendulum(length=rope, g=g, pivot_samples=path.pivot_samples(t_end + 1.0, spacing=0.01))
        tr = pl.simulate(
            pend,
            pend.state_from_angles(0.0, 0.0, 0.0, 0.0),
            t_end=t_end,
            method="dop853",
            rtol=1e-10,
            atol=1e-10,
            save_every=1,
            dt=0.01,
        )
        after = tr.t > path.t_end + 1.0
        return float(np.mean(np.hypot(tr.x[after, 0], tr.v[after, 0] / w)))

    assert residual(s) / residual(None) == pytest.approx(expected, rel=1e-2)


def test_a_measured_path_from_csv(tmp_path) -> None:  # type: ignore[no-untyped-def]
    path = crane.move(3.0, 0.5, 0.3, j_max=0.5, direction=(1.0, 1.0, 0.0))
    t = np.linspace(0.0, 20.0, 2001)
    p = path.position(t)
    f = tmp_path / "trolley.csv"
    f.write_text(
        "t,x,y,z\n"
        + "\n".join(",".join(repr(float(v)) for v in (a, *row)) for a, row in zip(t, p, strict=True))
    )
    sampled = crane.Sampled.from_csv(str(f))
    mid = np.linspace(0.5, 19.5, 97)
    np.testing.assert_allclose(sampled.position(mid), path.position(mid), atol=1e-9)
    np.testing.assert_allclose(sampled.acceleration(mid), path.acceleration(mid), atol=2e-3)
    run = crane.Crane(rope=8.0, pivot=sampled).simulate(t_end=19.0, output_spacing=0.1)
    ref = crane.Crane(rope=8.0, pivot=path).simulate(t_end=19.0, output_spacing=0.1)
    np.testing.assert_allclose(run.payload, ref.payload, atol=1e-3)
    (tmp_path / "bad.csv").write_text("t,x,y,z\n0,0,0,0\n1,,0,0\n2,0,0,0\n3,0,0,0\n")
    with pytest.raises(pl.InvalidInputError, match="row 2"):
        crane.Sampled.from_csv(str(tmp_path / "bad.csv"))


def test_a_measured_path_is_not_extrapolated_past_its_samples() -> None:
    """crane.Sampled is defined on [t₀, t_n] only: t² sampled on [0, 2] s extrapolated its last cubic
    to 100 m at 10 s. A time outside the samples and a crane run reaching past them are refused,
    naming both times; inside, the run is as before. The Hoist holds its ends instead (its clamped
    spline ends at rest)."""
    t = np.linspace(0.0, 2.0, 9)
    sampled = crane.Sampled(t, np.stack([t**2, 0 * t, 0 * t], axis=1))
    assert sampled.span == (0.0, 2.0)
    np.testing.assert_allclose(sampled.position([0.5, 2.0])[:, 0], [0.25, 4.0], rtol=1e-14)
    with pytest.raises(pl.InvalidInputError, match=r"t = 10 s is outside .* t = 0 … 2 s"):
        sampled.position(10.0)
    with pytest.raises(
        pl.InvalidInputError, match=r"^invalid t = nan: a finite number in \[-1e12, 1e12\] s$"
    ):
        sampled.position(float("nan"))
    with pytest.raises(pl.InvalidInputError, match=r"t = -0.5 s is outside"):
        sampled.pivot_samples(2.0, t_start=-0.5)
    c = crane.Crane(rope=5.0, pivot=sampled)
    with pytest.raises(pl.InvalidInputError, match=r"cover t = 0 … 2 s, .* t_end = 10 s"):
        c.simulate(t_end=10.0)
    run = c.simulate(t_end=2.0, output_spacing=0.5)
    assert run.pivot[-1, 0] == pytest.approx(4.0, rel=1e-14)
    hoist = crane.Hoist([0.0, 2.0], [5.0, 4.0])
    np.testing.assert_allclose(hoist.length([2.0, 10.0]), [4.0, 4.0], rtol=1e-15)
    assert hoist.velocity(10.0)[0, 0] == 0.0


def test_adding_profiles_of_two_kinds_says_which_and_what_is_allowed() -> None:
    """An acceleration-limited move plus a jerk-limited one was a bare "unsupported operand type(s)"."""
    plain, smooth = crane.profile(5.0, 0.5, 0.5), crane.profile(5.0, 0.5, 0.5, j_max=1.0)
    for a, b, first, second in (
        (plain, smooth, "acceleration", "jerk"),
        (smooth, plain, "jerk", "acceleration"),
    ):
        with pytest.raises(TypeError) as err:
            a + b
        text = str(err.value)
        assert f"two kinds, {first}-limited + {second}-limited; " in text, text
        assert "allowed: two profiles of one kind" in text and "j_max" in text, text
    assert (plain + plain).distance == pytest.approx(10.0, rel=1e-12)  # one kind: their sum
    with pytest.raises(TypeError, match="unsupported operand"):  # not a profile: Python's own words
        plain + 1.0  # type: ignore[operator]
