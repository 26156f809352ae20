"""Every public result object shows itself briefly: a one-line ``repr`` of at most a few hundred
characters (EMMap's printed a 14 kB array, Reduced's 26 kB) and an HTML table for notebooks
(``_repr_html_``; Phases and Reduced had none). A movie shows itself as the movie, embedded."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from conftest import REPO

import pendulab as pl
from pendulab import crane

MAX_REPR = 300  # characters


def _objects(tmp_path) -> dict[str, object]:
    p = pl.Pendulum()
    s0 = p.state_from_angles(theta=np.radians(60), phi_dot=2.0)
    tr = pl.simulate(p, s0, t_end=2.0, save_every=10, error_estimate=True)
    sol = pl.exact(p, s0)
    ensemble = pl.simulate_ensemble(p, pl.states_from_angles(p, theta=np.linspace(0.1, 1, 5)), t_end=1.0)
    slewing = pl.Pendulum(model="slewing", radius=0.02, rate=0.5)
    stepper = pl.Stepper(pl.Pendulum(model="damped", damping=0.2), s0, method="rattle4", dt=1e-3)
    stepper.step(100)
    return {
        "Scenario": pl.load_scenario(REPO / "examples" / "scenarios" / "damped.toml"),
        "Stepper": stepper,
        "Pendulum": p,
        "State": s0,
        "Trajectory": tr,
        "ErrorEstimate": tr.error_estimate,
        "ExactSolution": sol,
        "Phases": sol.phases(),
        "Reduced": pl.reduce(tr),
        "EMMap": pl.em_map(p, grid=(200, 200)),
        "MeasuredAdvance": pl.measured_azimuth_advance(pl.simulate(p, s0, t_end=5.0, method="rattle8")),
        "EnsembleResult": ensemble,
        "SweepResult": pl.sweep({"theta0": np.linspace(0.1, 1.0, 5)}, "rotation_number", progress=False),
        "SpringTrajectory": pl.simulate_spring(
            pl.SwingingSpring.resonant(1.0), [0.1, 0, -1.0], [0, 0.1, 0], t_end=1.0
        ),
        "SlewingSway": pl.slewing_sway(slewing, np.linspace(0, 1, 500)),
        "Movie": sol.animate(tmp_path / "m.gif", t=(0.0, 1.0), fps=10, size=(96, 64), progress=False),
        "Comparison": pl.compare_fits([_fit(["length"]), _fit(["length", "damping"])]),
        **_crane_objects(),
    }


def _crane_objects() -> dict[str, object]:
    """The crane's results (their dataclass reprs printed every array)."""
    s = crane.shaper("zvd", omega=1.0)
    path = crane.move(distance=2.0, v_max=0.5, a_max=0.5, shaper=s)
    ropes, ratios = np.linspace(5.0, 10.0, 3), np.array([0.1, 0.2])
    return {
        "crane.Shaper": s,
        "crane.Profile": crane.profile(5.0, 0.5, 0.5, j_max=1.0, shaper=s),
        "crane.CraneRun": crane.Crane(rope=8.0, pivot=path, payload_mass=500.0).simulate(t_end=10.0),
        "crane.GridResult": crane.residual_grid(ropes, ratios, [None, s], progress=False),
        **_crane_inputs(),
    }


def _crane_inputs() -> dict[str, object]:
    """The crane's controller, its run, a gantry path and a crane (LQR printed its K and poles arrays,
    Gantry its axes as np.float64(...), LQRRun and Crane ``<... object at 0x...>``)."""
    ctrl = crane.lqr(8.0, a_max=0.5)
    gantry = crane.Gantry(trolley=crane.profile(4.0, 0.5, 0.5), origin=(0.0, 0.0, 12.0))
    return {
        "crane.LQR": ctrl,
        "crane.LQRRun": ctrl.simulate(3.0, t_end=8.0, progress=False),
        "crane.Gantry": gantry,
        "crane.Tower": crane.Tower(slew=crane.profile(1.5, 0.2, 0.1), height=30.0),
        "crane.Crane": crane.Crane(rope=8.0, pivot=gantry, payload_mass=500.0, hook_mass=50.0, rigging=1.5),
        "crane.Hoist": crane.Hoist([2.0, 12.0], [10.0, 8.0]),
        "crane.Wind": crane.Wind(
            velocity=(0.0, 10.0, 0.0), area=1.5, gust=(0.0, 5.0, 0.0), gust_start=20.0, gust_duration=4.0
        ),
    }


def _fit(names: list[str]) -> pl.FitResult:
    """A small fit of a damped swing (for the Comparison of two fits)."""
    p = pl.Pendulum(length=0.5, damping=0.05)
    t = np.linspace(0.0, 6.0, 200)
    tr = pl.simulate(p, p.state_from_angles(0.3), 6.0, method="dop853", save_at=t)
    angle = np.arctan2(tr.x[:, 0], -tr.x[:, 2]) + 1e-3 * np.random.default_rng(0).standard_normal(len(t))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the undamped fit misses the decay, and says so
        return pl.fit(t, planar_angle=angle, pendulum=pl.Pendulum(length=0.5, model="damped"), fit=names)


@pytest.fixture(scope="module")
def objects(tmp_path_factory) -> dict[str, object]:
    return _objects(tmp_path_factory.mktemp("reprs"))


NAMES = [
    "Scenario", "Stepper", "Pendulum", "State", "Trajectory", "ErrorEstimate", "ExactSolution", "Phases",
    "Reduced", "EMMap", "MeasuredAdvance", "EnsembleResult", "SweepResult", "SpringTrajectory", "SlewingSway",
    "Movie", "Comparison", "crane.Shaper", "crane.Profile", "crane.CraneRun", "crane.GridResult",
    "crane.LQR", "crane.LQRRun", "crane.Gantry", "crane.Tower", "crane.Crane", "crane.Hoist",
    "crane.Wind",
]  # fmt: skip


@pytest.mark.parametrize("name", NAMES)
def test_short_repr_and_an_html_table(objects, name):
    obj = objects[name]
    text = repr(obj)
    assert len(text) <= MAX_REPR and "\n" not in text and "array(" not in text, text
    assert text.startswith(name.split(".")[-1] + "("), text
    html = obj._repr_html_()  # type: ignore[attr-defined]
    assert (isinstance(html, str) and len(html) < 20_000) or name == "Movie"
    if name != "Movie":
        assert "<table" in html


def test_a_movie_embeds_itself(objects):
    html = objects["Movie"]._repr_html_()
    assert html.startswith('<img src="data:image/gif;base64,R0lGOD')  # "GIF8" in base64


def test_every_public_result_class_is_covered():
    results = {n for n in pl.__all__ if n[0].isupper()} - {
        "InvalidInputError", "IntegrationError", "ScenarioError", "Pendulum", "State", "Save",
        "SwingingSpring", "FitResult",  # FitResult: test_fit checks its report and tables
        "CompoundPendulum", "Part",  # inputs (a pendulum's geometry), like Pendulum and State
    }  # fmt: skip
    assert results <= set(NAMES), sorted(results - set(NAMES))


def test_scenario_and_stepper_say_what_they_hold(objects):
    """Scenario printed its whole pydantic spec (520 characters), Stepper ``<... object at 0x...>``."""
    sc, st = repr(objects["Scenario"]), repr(objects["Stepper"])
    assert sc.startswith("Scenario('damped.toml': damped, damping=0.05, l=1 m"), sc
    assert "rattle4, dt=0.001 s" in sc, sc
    assert "t=0…60 s" in sc and "θ₀=60°" in sc, sc
    assert st.startswith("Stepper(rattle4, dt=0.001 s, t=0.1 s, θ=") and "steps=100" in st, st
    assert "damping=0.2" in st, st


def test_every_public_class_has_its_own_short_repr():
    """Inputs too (Part, CompoundPendulum, Save, SwingingSpring): a repr of their own, one short line."""
    import inspect

    for name in pl.__all__:
        cls = getattr(pl, name)
        if inspect.isclass(cls) and not issubclass(cls, Exception):
            assert cls.__repr__ is not object.__repr__, f"{name} has no repr of its own"
    compound = pl.CompoundPendulum((pl.Part.rod(0.4, 0.6), pl.Part.sphere(1.5, 0.04, 0.55)))
    for obj in (compound, pl.Save(every_n=10), pl.SwingingSpring.resonant(1.0)):
        text = repr(obj)
        assert len(text) <= MAX_REPR and "\n" not in text and " object at 0x" not in text, text


def test_plot_methods_take_the_path_first_or_as_a_keyword(tmp_path, objects):
    """sol.plot("x.png") failed (its first argument was t); every plot method now has path first."""
    pytest.importorskip("matplotlib")
    import inspect

    import matplotlib

    matplotlib.use("Agg")
    for name in ("Trajectory", "ExactSolution"):
        method = objects[name].plot
        first = next(iter(inspect.signature(method).parameters))
        assert first == "path", (name, first)
    sol = objects["ExactSolution"]
    sol.plot(tmp_path / "a.png")
    sol.plot(path=tmp_path / "b.png", t=np.linspace(0.0, 2.0, 50))
    assert (tmp_path / "a.png").stat().st_size > 0 and (tmp_path / "b.png").stat().st_size > 0
    with pytest.raises(pl.InvalidInputError, match="give the times as t="):
        sol.plot(np.linspace(0.0, 1.0, 5))


def test_a_shaper_shows_its_tolerance_only_where_it_was_designed_to_one() -> None:
    """ZV-family shapers have no V_tol (it was shown as ``tolerance=nan``); the EI kinds do."""
    zv = repr(crane.shaper("zv", omega=1.0))
    assert zv == "Shaper(kind=zv, impulses=2, duration=3.142 s, omega=1 rad/s, damping=0)", zv
    assert "tolerance=0.05," not in zv and "nan" not in zv
    assert "tolerance=0.05" in repr(crane.shaper("ei", omega=1.0))
    both = crane.shaper("zv", omega=1.0) * crane.shaper("zv", omega=2.0)
    assert "nan" not in repr(both) and "omega" not in repr(both), repr(both)


def test_an_lqr_names_its_rope_poles_and_slowest_pole(objects) -> None:
    """Its dataclass repr printed the K and poles arrays; now the rope, the poles' count and the
    least damped pole (smallest |Re p|, here computed from the poles directly), and a_max."""
    ctrl = objects["crane.LQR"]
    text = repr(ctrl)
    poles = np.linalg.eigvals(np.array([[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1], [0, 0, -9.81 / 8.0, 0]])
                              - np.array([[0.0], [1.0], [0.0], [-1.0 / 8.0]]) @ ctrl.K)  # fmt: skip
    slow = poles[np.argmin(np.abs(poles.real))]
    assert text.startswith("LQR(rope=8 m, poles=4, slowest_pole="), text
    assert f"slowest_pole={slow.real:.4g} ± {abs(slow.imag):.4g}j 1/s" in text, text
    assert text.endswith("a_max=0.5 m/s²)"), text
    assert "inf" not in repr(crane.lqr(8.0)) and "a_max" not in repr(crane.lqr(8.0))


def test_an_lqr_run_names_its_distance_and_span(objects) -> None:
    run = objects["crane.LQRRun"]
    text = repr(run)
    assert text == f"LQRRun(distance=3 m, t=0 … 8 s, switches={run.switches.size})", text
    assert run.switches.size > 0  # a_max = 0.5 m/s² clips the first push of a 3 m move


def test_a_gantry_names_its_travel_and_end(objects) -> None:
    text = repr(objects["crane.Gantry"])
    t_end = objects["crane.Gantry"].trolley.t_end
    assert text == f"Gantry(trolley=4 m, bridge=—, origin=[0, 0, 12] m, t_end={t_end:.4g} s)", text
    assert "np.float64" not in text
    tilted = repr(crane.Gantry(bridge=crane.profile(2.0, 0.5, 0.5), bridge_axis=(0.0, 0.6, 0.8)))
    assert "bridge=2 m, bridge_axis=[0, 0.6, 0.8]" in tilted, tilted


def test_a_tower_names_its_slew_radius_height_and_end(objects) -> None:
    """Tower had the dataclass repr: its profiles' knots and coefficients as arrays."""
    tower = objects["crane.Tower"]
    assert repr(tower) == f"Tower(slew=0 … 1.5 rad, radius=10 m, height=30 m, t_end={tower.t_end:.4g} s)"
    luffing = crane.Tower(luff=crane.profile(0.25, 0.1, 0.1, start=0.5), boom=40.0, height=25.0)
    end = f"{luffing.t_end:.4g}"
    assert repr(luffing) == f"Tower(slew=0 rad, luff=0.5 … 0.75 rad, boom=40 m, height=25 m, t_end={end} s)"
    trolley = crane.Tower(radius=crane.profile(5.0, 0.5, 0.5, start=10.0))
    assert "radius=10 … 15 m" in repr(trolley) and "array" not in repr(trolley), repr(trolley)
    assert ">rad</td>" in tower._repr_html_()


def test_a_crane_names_its_rope_masses_and_pivot(objects) -> None:
    text = repr(objects["crane.Crane"])
    assert text == "Crane(rope=8 m, payload_mass=500 kg, hook_mass=50 kg, rigging=1.5 m, pivot=Gantry)", text
    hoisted = crane.Crane(rope=8.0, hoist=crane.Hoist([0.0, 5.0], [8.0, 4.0]), damping=0.1)
    assert repr(hoisted) == "Crane(rope=4 … 8 m, payload_mass=1000 kg, damping=0.1 1/s, pivot=Gantry)"


def test_a_hoist_names_its_samples_span_and_length_range(objects) -> None:
    """Hoist had no repr of its own (``<pendulab.crane.system.Hoist object at 0x…>``)."""
    assert repr(objects["crane.Hoist"]) == "Hoist(samples=2, t=2 … 12 s, length=8 … 10 m)"
    html = objects["crane.Hoist"]._repr_html_()
    assert "<th style='text-align:left;padding-right:1em'>length</th>" in html and ">m</td>" in html


def test_a_wind_names_its_velocity_and_what_differs_from_the_defaults(objects) -> None:
    """Wind's dataclass repr listed all 13 fields without units (248 characters for the default)."""
    text = repr(objects["crane.Wind"])
    assert text == (
        "Wind(velocity=[0, 10, 0] m/s, area=1.5 m², gust=[0, 5, 0] m/s, gust_start=20 s, gust_duration=4 s)"
    ), text
    assert repr(crane.Wind()) == "Wind(velocity=[0, 0, 0] m/s)"
    gusty = crane.Wind(velocity=(10.0, 0.0, 0.0), turbulence=2.0, seed=7, air_density=1.2, hook_area=0.5)
    assert repr(gusty) == (
        "Wind(velocity=[10, 0, 0] m/s, air_density=1.2 kg/m³, hook_area=0.5 m², turbulence=2 m/s, "
        "turbulence_scale=50 m, seed=7)"
    ), repr(gusty)
    every = crane.Wind(
        velocity=(12.5, -3.25, 0.5), area=2.5, drag_coefficient=1.05, air_density=1.18, gust=(1.5, 2.5, 0.25),
        gust_start=12.5, gust_duration=3.5, hook_area=0.75, hook_drag_coefficient=0.9, turbulence=1.5,
        turbulence_scale=80.0, turbulence_modes=128, seed=123456,
    )  # fmt: skip
    assert len(repr(every)) <= MAX_REPR and "\n" not in repr(every), repr(every)
    assert "m²" in crane.Wind(area=1.0)._repr_html_()


def test_a_run_shows_the_hoists_true_rope_range_not_its_saved_samples() -> None:
    """The run's rope range came from the saved samples; a spline overshooting between them (here
    above 10 m between t = 0 and 10 s, below 5 m between 20 and 30 s) was not shown."""
    hoist = crane.Hoist([0.0, 10.0, 20.0, 30.0], [10.0, 10.0, 5.0, 5.0])
    lo, hi = hoist.length_range()
    assert lo < 5.0 and hi > 10.0
    c = crane.Crane(rope=10.0, hoist=hoist)
    assert repr(c).startswith(f"Crane(rope={lo:.6g} … {hi:.6g} m,"), repr(c)
    run = c.simulate(t_end=30.0, output_spacing=10.0)  # saved at the samples only
    assert run.rope.min() == pytest.approx(5.0) and run.rope.max() == pytest.approx(10.0)
    assert run.rope_range == (lo, hi) and f"rope={lo:.6g} … {hi:.6g} m" in repr(run), repr(run)
