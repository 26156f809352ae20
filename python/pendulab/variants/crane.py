"""The slewing crane's small sway in closed form (docs/theory.md T-7.2), beside the nonlinear model
``Pendulum(model="slewing")``: in the boom frame (x radial, y tangential; the payload's horizontal
displacement from the boom tip [m]; ω₀² = g/l)

    ẍ − 2ωẏ + (ω₀² − ω²)x = ω²R,   ÿ + 2ωẋ + (ω₀² − ω²)y = 0   (− c(ż + iωz), z = x + iy, with damping)

with the static offset ω²R/(ω₀² − ω²) (with damping ω²R/(ω₀² − ω² + icω): a lag in y) and the
natural frequencies ω₀ ∓ ω (with damping |Ω ∓ ω|, Ω = √(ω₀² − c²/4)). Computed in the core
(``pendulab_core::model::slewing_linear``). Units: SI (m, s, rad/s, 1/s).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .._core import InvalidInputError, slewing_linear
from ..display import Row, html_table, number, vector
from ..model import FloatArray, Pendulum, State, models


@dataclass(frozen=True)
class SlewingSway:
    """The analytic boom-frame track: times ``t`` [s], ``radial`` and ``tangential`` displacement [m]
    and their rates ``v_radial``, ``v_tangential`` [m/s] in the rotating frame; ``static_offset``
    (radial, tangential) [m]; ``frequencies`` (lower, upper) natural angular frequencies [rad/s]."""

    t: FloatArray
    radial: FloatArray
    tangential: FloatArray
    v_radial: FloatArray
    v_tangential: FloatArray
    static_offset: tuple[float, float]
    frequencies: tuple[float, float]

    def __repr__(self) -> str:
        return (
            f"SlewingSway({len(self.t)} samples, t = {number(self.t[0])} … {number(self.t[-1])} s, "
            f"max |radial| = {number(np.max(np.abs(self.radial), initial=0.0), 4)} m, "
            f"max |tangential| = {number(np.max(np.abs(self.tangential), initial=0.0), 4)} m)"
        )

    def _repr_html_(self) -> str:
        rows: list[Row] = [
            ("samples", len(self.t), ""),
            ("max |radial sway|", float(np.max(np.abs(self.radial), initial=0.0)), "m"),
            ("max |tangential sway|", float(np.max(np.abs(self.tangential), initial=0.0)), "m"),
            ("static offset (radial, tangential)", vector(self.static_offset), "m"),
            ("natural frequencies", vector(self.frequencies), "rad/s"),
        ]
        return html_table("Slewing crane: the small sway (T-7.2)", rows)


def _slewing_params(pendulum: Pendulum) -> dict[str, float]:
    if pendulum.model != "slewing":
        raise InvalidInputError(
            "slewing_sway needs a Pendulum(model='slewing', radius=..., rate=...), "
            f"not model {pendulum.model!r}"
        )
    spec = next(m for m in models() if m["name"] == "slewing")
    return {p["name"]: pendulum.extra.get(p["name"], p["default"]) for p in spec["params"]}


def slewing_sway(pendulum: Pendulum, t: Any, state: State | None = None) -> SlewingSway:
    """The linearised sway of a slewing crane (T-7.2) at times ``t`` [s] (t = 0 when the boom points
    along e₁), from ``state`` at t = 0 (pivot-relative x [m], v [m/s] as for :func:`pendulab.simulate`;
    default: hanging at rest under the tip). ``pendulum`` is a ``model="slewing"`` pendulum (boom
    radius [m], rate ω [rad/s], damping c [1/s]; the pivot height does not enter).

    Raises ``InvalidInputError`` at the resonance ω = ω₀ = √(g/l) without damping (the static offset
    ω²R/(ω₀² − ω²) is infinite), for g ≤ 0, and for c ≥ 2ω₀ (no oscillation).
    """
    par = _slewing_params(pendulum)
    ts = np.ascontiguousarray(np.atleast_1d(np.asarray(t, dtype=np.float64)))
    if state is None:
        x0, v0 = np.zeros(3), np.zeros(3)
    else:
        x0, v0 = np.asarray(state.x, dtype=np.float64), np.asarray(state.v, dtype=np.float64)
    w = par["rate"]
    # boom frame at t = 0 is the inertial one; rates in the rotating frame: ż = (vx + i vy) − iω z
    start = [float(x0[0]), float(x0[1]), float(v0[0] + w * x0[1]), float(v0[1] - w * x0[0])]
    out = slewing_linear(pendulum.spec, start, ts)
    return SlewingSway(
        ts,
        out["x"],
        out["y"],
        out["vx"],
        out["vy"],
        tuple(out["static_offset"]),
        tuple(out["frequencies"]),
    )
