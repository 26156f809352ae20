"""pl.fit(body=pl.CompoundPendulum(...)): a physical pendulum of known geometry (fitting/body.py,
docs/fit.md; T-7.7), on data from SciPy's DOP853 of the rigid body's own equation
I_O θ̈ = −M g h sin θ − b θ̇ (not our model: the mapping to the point pendulum is what is tested).
SI units."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import pendulab as pl

BODY = pl.CompoundPendulum((pl.Part.rod(0.4, 0.6), pl.Part.sphere(1.5, 0.04, 0.55)))
G, TORQUE, SIGMA = 9.81, 0.002, 1e-3  # m/s², N m s, rad


@pytest.fixture(scope="module")
def swing() -> tuple[np.ndarray, np.ndarray]:
    """20 s of the body released at 0.4 rad, an encoder angle with 1 mrad white noise."""
    i_o, mh = BODY.inertia, BODY.mass * BODY.centre

    def rhs(_t: float, y: np.ndarray) -> list[float]:
        return [y[1], -(mh * G * np.sin(y[0]) + TORQUE * y[1]) / i_o]

    t = np.linspace(0.0, 20.0, 2001)
    sol = solve_ivp(rhs, (0.0, 20.0), [0.4, 0.0], method="DOP853", t_eval=t, rtol=1e-12, atol=1e-13)
    noise = SIGMA * np.random.default_rng(7).standard_normal(t.size)
    return t, sol.y[0] + noise


def fitted(t: np.ndarray, theta: np.ndarray, fit: list[str], g: float = 9.7) -> pl.FitResult:
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a right model on white noise: no finding
        return pl.fit(
            t, planar_angle=theta, pendulum=pl.Pendulum(g=g, model="damped", damping=0.01), body=BODY, fit=fit
        )


def test_the_geometry_gives_g_and_the_pivot_torque(swing: tuple) -> None:
    res = fitted(*swing, ["g", "damping"])
    assert res.params["g"] == pytest.approx(G, abs=3 * res.stderr["g"])
    assert res.stderr["g"] < 2e-4
    b, sb = res.body.torques["damping_torque"]
    assert b == pytest.approx(TORQUE, abs=3 * sb) and sb < 0.05 * TORQUE
    assert res.fixed["length"] == pytest.approx(BODY.equivalent_length, rel=1e-15)
    assert "compound pendulum: l_eq = I_O/(M h)" in res.report()


def test_a_fitted_length_gives_the_position_of_a_part(swing: tuple) -> None:
    res = fitted(*swing, ["length", "damping"], g=G)
    d, sd = res.body.distance(1)
    assert d == pytest.approx(0.55, abs=3 * sd) and 0.0 < sd < 1e-4
    assert "standard errors from the geometry's l_eq" in res.report()


def test_the_lab_words_the_body_and_the_information_criteria(swing: tuple) -> None:
    """The lab's keyed report (pendulab.server.fit_words, issue 28): the compound pendulum's lines and
    AIC/BIC with the report's numbers, for a page that words them in its language."""
    from pendulab.server.fit_words import report_items

    for fit, held in ((["g", "damping"], True), (["length", "damping"], False)):
        res = fitted(*swing, fit, g=G)
        items = {i["key"]: i["values"] for i in report_items(res)}
        assert items["aicBic"] == {"aic": f"{res.aic:.6g}", "bic": f"{res.bic:.6g}"}
        assert items["compound"]["leq"] == f"{BODY.equivalent_length:.6g}"
        assert ("compoundLengthHeld" in items) is held and ("compoundLength" in items) is not held
        value, err = res.body.torques["damping_torque"]
        assert items["compoundTorque"] == {
            "param": "damping_torque",
            "value": f"{value:.6g}",
            "err": f"{err:.2g}",
            "unit": "N m s",
        }


def test_bad_bodies_are_refused(swing: tuple) -> None:
    t, theta = swing
    with pytest.raises(pl.InvalidInputError, match=r"body must be a pendulab\.CompoundPendulum"):
        pl.fit(t, planar_angle=theta, body=pl.Pendulum(), fit=["g"])  # type: ignore[arg-type]
    with pytest.raises(pl.InvalidInputError, match=r"needs a pendulab\.Pendulum"):
        pl.fit(t, planar_angle=theta, pendulum=pl.SwingingSpring.resonant(0.5), body=BODY, fit=["g"])  # type: ignore[arg-type]
    res = fitted(t, theta, ["g", "damping"])
    with pytest.raises(pl.InvalidInputError, match="the length was not fitted"):
        res.body.distance(1)
