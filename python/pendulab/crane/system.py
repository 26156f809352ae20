"""The crane: a load on a hoisted rope below a moving pivot, optionally as hook + payload (a double
spherical pendulum), with wind and damping (docs/cranes.md, docs/theory.md T-11.4 – T-11.8). The
dynamics run in the core (``pendulab_core::crane``: adaptive DOP853 with projection onto the
rheonomic constraints |x₁ − P(t)| = l(t), |x₂ − x₁| = l₂). SI units: m, kg, s, N, J, rad.

Small-sway modes (T-11.8): one body, ω² = g/l; hook (m₁, rope L₁) + payload (m₂, rigging L₂),
R = m₂/m₁: L₁L₂ω⁴ − (1 + R) g (L₁ + L₂) ω² + (1 + R) g² = 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._core import CraneSpec, InvalidInputError, RunOptions, crane_simulate
from ..validate import array, integer, invalid
from . import _spacing
from ._checks import later, nonnegative, number, numbers, positive, time, times, tolerances
from ._checks import rope as _rope
from ._display import Row, Shown, crane_rows, run_rows, wind_rows
from .hoist import Hoist
from .paths import Gantry, Path
from .shaper import FloatArray

MAX_SAVES = 500_000
MAX_STEPS = 20_000_000
DEFAULT_SPACING = 0.02
"""The default ``output_spacing`` [s] of :meth:`Crane.simulate`."""


_WIND_NONNEGATIVE = (
    ("area", "m²"),
    ("drag_coefficient", ""),
    ("air_density", "kg/m³"),
    ("hook_area", "m²"),
    ("hook_drag_coefficient", ""),
    ("turbulence", "m/s"),
)


@dataclass(frozen=True, repr=False)
class Wind(Shown):
    """Wind on the load (T-11.7): steady ``velocity`` w₀ [m/s] plus a (1 − cos) gust of peak ``gust``
    [m/s] from ``gust_start`` [s] lasting ``gust_duration`` [s], plus seeded turbulence of intensity
    ``turbulence`` σ [m/s] per axis and length scale ``turbulence_scale`` L [m] (Dryden-type spectrum
    S(ω) = σ² (2T/π)/(1 + (Tω)²), T = L/|w₀|, as ``turbulence_modes`` cosines of random phase from
    ``seed``); drag ½ρ c_W A |w − v|(w − v) with ``air_density`` ρ [kg/m³], the payload's
    ``drag_coefficient`` c_W and ``area`` A [m²], the hook's ``hook_drag_coefficient`` and
    ``hook_area`` [m²]."""

    velocity: tuple[float, float, float] = (0.0, 0.0, 0.0)
    area: float = 0.0
    drag_coefficient: float = 1.2
    air_density: float = 1.225
    gust: tuple[float, float, float] = (0.0, 0.0, 0.0)
    gust_start: float = 0.0
    gust_duration: float = 1.0
    hook_area: float = 0.0
    hook_drag_coefficient: float = 1.2
    turbulence: float = 0.0
    turbulence_scale: float = 50.0
    turbulence_modes: int = 64
    seed: int = 0

    def __post_init__(self) -> None:
        """Checks every field, named as a crane file's [wind] key (``wind.area``)."""
        for name in ("velocity", "gust"):
            _triple(f"wind.{name}", getattr(self, name))
        for name, unit in _WIND_NONNEGATIVE:
            nonnegative(f"wind.{name}", getattr(self, name), unit)
        time("wind.gust_start", self.gust_start)
        positive("wind.gust_duration", self.gust_duration, "s")
        positive("wind.turbulence_scale", self.turbulence_scale, "m")
        # the counts as Python ints (a float with an integer value is taken: 64.0; NumPy's seed needs an int)
        object.__setattr__(
            self, "turbulence_modes", integer("wind.turbulence_modes", self.turbulence_modes, 8, 4096)
        )
        object.__setattr__(self, "seed", integer("wind.seed", self.seed, 0, 2**63 - 1))

    def _rows(self) -> list[Row]:
        return wind_rows(self)

    def force(self, relative_speed: float) -> float:
        """The payload's drag ½ρ c_W A u² [N] at the air speed u [m/s] relative to it."""
        u = number("relative_speed", relative_speed, "m/s")
        return 0.5 * self.air_density * self.drag_coefficient * self.area * u**2

    def modes(self) -> tuple[FloatArray, FloatArray, FloatArray]:
        """The turbulence as (ω_k [rad/s] (K,), amplitudes a_k [m/s] (K, 3), phases φ_k [rad] (K, 3)):
        w_turb = Σ a_k cos(ω_k t + φ_k) per axis, ω_k log-spaced over [10⁻³, 10³]/T, a_k = √(2 S Δω)."""
        sigma = float(self.turbulence)
        if sigma == 0.0:
            return np.zeros(0), np.zeros((0, 3)), np.zeros((0, 3))
        speed = float(np.linalg.norm(self.velocity))
        if not speed > 0:
            raise InvalidInputError("turbulence needs a steady wind velocity (its time scale is L/|w₀|)")
        scale = float(self.turbulence_scale)
        k = int(self.turbulence_modes)
        tau = scale / speed
        edges = np.geomspace(1e-3 / tau, 1e3 / tau, k + 1)
        om = np.sqrt(edges[:-1] * edges[1:])
        psd = sigma**2 * (2 * tau / math.pi) / (1 + (tau * om) ** 2)
        amp = np.sqrt(2 * psd * np.diff(edges))
        rng = np.random.default_rng(self.seed)
        phases = rng.uniform(0.0, 2 * math.pi, size=(k, 3))
        return om, np.repeat(amp[:, None], 3, axis=1), phases

    def velocity_at(self, t: Any) -> FloatArray:
        """w(t) [m/s], (N, 3): steady + gust + turbulence (as the core evaluates it)."""
        ts = np.atleast_1d(times("t", t))
        w = np.tile(np.asarray(self.velocity, dtype=np.float64), (ts.size, 1))
        s = (ts - self.gust_start) / self.gust_duration
        inside = (s >= 0) & (s <= 1)
        w += np.where(inside, 0.5 * (1 - np.cos(2 * math.pi * s)), 0.0)[:, None] * np.asarray(
            self.gust, dtype=float
        )
        om, amp, ph = self.modes()
        for k in range(om.size):
            w += amp[k] * np.cos(om[k] * ts[:, None] + ph[k])
        return w


@dataclass(frozen=True, repr=False)
class CraneRun(Shown):
    """A simulated crane: ``t`` [s] (N,); ``payload``, ``hook`` (the rope's end: the payload itself
    without a separate hook) and ``pivot`` positions [m] (N, 3) with velocities ``payload_velocity``,
    ``hook_velocity`` [m/s]; ``sway``
    (N, 2): polar angle θ from the downward vertical and azimuth φ [rad] of the rope (pivot → hook,
    or → payload without a hook); ``rigging_sway`` (N, 2) [rad] of hook → payload; ``rope`` l(t)
    [m]; ``tension`` (N, 2) [N] rope, rigging; ``energy`` E = Σ ½m|v|² + m g z [J]; ``work`` the
    works [J] done since the start by the hoist, the pivot, the wind and the damping (dict of (N,));
    ``power`` the hoist's −T₁ l̇ and the pivot's −T₁ (r₁/l)·Ṗ [W] at the saved times (dict of (N,));
    ``rope_range`` the rope's true (least, largest) length [m] over the run, from the hoist's spline
    (:meth:`Hoist.length_range`: it may lie between the saved times; None: the saved ``rope``'s)."""

    t: FloatArray
    payload: FloatArray
    hook: FloatArray
    pivot: FloatArray
    payload_velocity: FloatArray
    hook_velocity: FloatArray
    sway: FloatArray
    rigging_sway: FloatArray | None
    rope: FloatArray
    tension: FloatArray
    energy: FloatArray
    work: dict[str, FloatArray] = field(default_factory=dict)
    power: dict[str, FloatArray] = field(default_factory=dict)
    steps: int = 0
    rope_range: tuple[float, float] | None = None

    def _rows(self) -> list[Row]:
        return run_rows(self)

    def energy_residual(self) -> FloatArray:
        """E(t) − E(0) − (sum of the works) [J]: zero up to the integration error (T-11.6)."""
        return np.asarray(self.energy - self.energy[0] - sum(self.work.values()), dtype=np.float64)

    def offset(self) -> FloatArray:
        """The payload's horizontal displacement from the pivot [m], (N, 2)."""
        return np.asarray(self.payload[:, :2] - self.pivot[:, :2], dtype=np.float64)

    def columns(self) -> dict[str, tuple[str, FloatArray]]:
        """Flat columns name → (unit, values) for a CSV file: t [s]; pivot, hook (a separate hook
        only) and payload x, y, z [m]; rope [m]; the rope's and the rigging's tension [N]; energy and
        each work [J]."""
        cols: dict[str, tuple[str, FloatArray]] = {"t": ("s", self.t)}
        hook = self.hook if self.rigging_sway is not None else None
        for name, arr in (("pivot", self.pivot), ("hook", hook), ("payload", self.payload)):
            if arr is not None:
                for i, ax in enumerate("xyz"):
                    cols[f"{name}_{ax}"] = ("m", arr[:, i])
        cols["rope"] = ("m", self.rope)
        cols["tension_rope"] = ("N", self.tension[:, 0])
        cols["tension_rigging"] = ("N", self.tension[:, 1])
        cols["energy"] = ("J", self.energy)
        for k, v in self.work.items():
            cols[f"work_{k}"] = ("J", v)
        return cols


def _angles(d: FloatArray) -> FloatArray:
    theta = np.arctan2(np.hypot(d[:, 0], d[:, 1]), -d[:, 2])
    return np.stack([theta, np.arctan2(d[:, 1], d[:, 0])], axis=1)


def _triple(name: str, v: Any) -> tuple[float, float, float]:
    """``v`` (the :class:`Wind` vector ``name`` [m/s]) as three Python floats, checked as every velocity
    is (:func:`pendulab.validate.array` with the velocity limit): anything else is refused naming it."""
    x, y, z = array(name, v, "velocity", shape=(3,)).tolist()
    return x, y, z


def _direction(name: str, angles: Any) -> FloatArray:
    th, ph = numbers(name, angles, "rad", shape=(2,)).tolist()
    if not 0 <= th < math.pi:
        raise invalid(name, angles, "(θ, φ): θ in [0, π) and a finite φ [rad]")
    return np.array([math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), -math.cos(th)])


class Crane(Shown):
    """A crane (module doc): ``rope`` length [m] (> 0 and ≤ 1e4 m, a pendulum's ``length`` limit, as
    ``rigging``; the hoist's length at t = 0 when ``hoist`` is given),
    ``pivot`` path (a :mod:`pendulab.crane.paths` path; default fixed at the origin), ``payload_mass``
    [kg], ``hook_mass`` [kg] and ``rigging`` [m] (both or neither: the hook + payload double
    pendulum), ``wind`` (:class:`Wind`), linear ``damping`` [1/s] relative to the pivot, ``g`` [m/s²],
    ``hoist`` (:class:`Hoist`, the rope length l(t))."""

    def __init__(
        self,
        rope: float,
        pivot: Path | None = None,
        payload_mass: float = 1000.0,
        hook_mass: float | None = None,
        rigging: float | None = None,
        wind: Wind | None = None,
        damping: float = 0.0,
        g: float = 9.81,
        hoist: Hoist | None = None,
    ) -> None:
        self.rope = _rope("rope", rope)
        self.pivot = pivot if pivot is not None else Gantry()
        if not isinstance(self.pivot, Path):
            raise InvalidInputError(
                f"pivot must be a crane path (crane.move, crane.Gantry, ...), not {pivot!r}"
            )
        self.payload_mass = positive("payload_mass", payload_mass, "kg")
        if (hook_mass is None) != (rigging is None):
            raise InvalidInputError("give hook_mass [kg] and rigging [m] together (or neither)")
        self.hook_mass = None if hook_mass is None else positive("hook_mass", hook_mass, "kg")
        self.rigging = None if rigging is None else _rope("rigging", rigging)
        self.wind = wind if wind is not None else Wind()
        if not isinstance(self.wind, Wind):
            raise invalid("wind", wind, "a crane.Wind (or None: no wind)")
        if hoist is not None and not isinstance(hoist, Hoist):
            raise invalid("hoist", hoist, "a crane.Hoist (or None: a constant rope)")
        self.damping = nonnegative("damping", damping, "1/s")
        self.g = number("g", g, "m/s²")
        l0 = float(hoist.length(0.0)[0]) if hoist is not None else self.rope
        if not math.isclose(l0, self.rope, rel_tol=1e-9):
            raise InvalidInputError(
                f"rope = {rope!r} m but the hoist's length at t = 0 is {l0!r} m; give the same"
            )
        self.hoist = hoist if hoist is not None else Hoist([0.0, 1.0], [self.rope, self.rope])

    def _rows(self) -> list[Row]:
        return crane_rows(self, Wind())

    def modes(self, rope: float | None = None) -> FloatArray:
        """The small-sway angular frequencies [rad/s] (increasing) at rope length ``rope`` [m] (default
        the rope at t = 0): √(g/l), or the two roots of T-11.8 with a hook."""
        big_l1 = self.rope if rope is None else _rope("rope", rope)
        if self.g <= 0:
            raise InvalidInputError(f"no sway modes for g = {self.g!r} <= 0 m/s²")
        if self.hook_mass is None or self.rigging is None:
            return np.array([math.sqrt(self.g / big_l1)])
        big_l2, r, g = self.rigging, self.payload_mass / self.hook_mass, self.g
        roots = np.roots([big_l1 * big_l2, -(1 + r) * g * (big_l1 + big_l2), (1 + r) * g * g])
        return np.sqrt(np.sort(roots.real))

    def simulate(
        self,
        t_end: float,
        sway: tuple[float, float] = (0.0, 0.0),
        rigging_sway: tuple[float, float] | None = None,
        output_spacing: float | None = None,
        t_start: float = 0.0,
        rtol: float = 1e-10,
        atol: float = 1e-10,
        *,
        dt: float | None = None,
    ) -> CraneRun:
        """Runs from ``t_start`` to ``t_end`` [s], saving every ``output_spacing`` [s] (default 0.02 s;
        the time between saved samples: DOP853 chooses its own steps), from the rope at polar angle
        ``sway`` = (θ₀, φ₀) [rad] and the rigging at ``rigging_sway`` (θ, φ) [rad] (default: in line
        with the rope), moving with the pivot and the hoist. ``dt`` is the deprecated older name of
        ``output_spacing`` (a DeprecationWarning; both given is an error).
        Raises ``InvalidInputError`` for a slack rope or rigging, a rope length ≤ 0, bad parameters."""
        name, given = _spacing.spacing("Crane.simulate", output_spacing, dt, DEFAULT_SPACING)
        t0 = time("t_start", t_start)
        t1 = later("t_end", t_end, t0)
        spacing = positive(name, given, "s")
        rtol, atol = tolerances(rtol, atol)
        self.pivot.check_run(t0, t1)
        ratio = (t1 - t0) / spacing - 1e-9  # inf for a tiny spacing: refused before math.ceil
        if not ratio + 1 <= MAX_SAVES:
            many = math.ceil(ratio) + 1 if math.isfinite(ratio) else ratio
            raise InvalidInputError(f"{many} saved samples exceed {MAX_SAVES}; raise {name} or shorten t_end")
        n = math.ceil(ratio) + 1
        save = np.minimum(t0 + spacing * np.arange(n), t1)
        save[-1] = t1
        u = _direction("sway", sway)
        u2 = u if rigging_sway is None else _direction("rigging_sway", rigging_sway)
        p, dp, _ = (a[0] for a in self.pivot._pva(np.array([t0])))
        lq, ldq, _ = (a[0, 0] for a in self.hoist._pva(np.array([t0])))
        y0 = np.zeros(16)
        y0[0:3], y0[3:6] = p + lq * u, dp + ldq * u
        # (hook mass [kg], rigging [m]) when the payload hangs under a hook
        hook = None if self.hook_mass is None or self.rigging is None else (self.hook_mass, self.rigging)
        hooked = hook is not None
        if hook is not None:
            y0[6:9], y0[9:12] = y0[0:3] + hook[1] * u2, y0[3:6]
        w = self.wind
        cwa_payload = w.drag_coefficient * w.area
        body2: tuple[float, float, float] | None
        if hook is not None:
            body1 = (hook[0], w.hook_drag_coefficient * w.hook_area)
            body2 = (self.payload_mass, cwa_payload, hook[1])
        else:
            body1, body2 = (self.payload_mass, cwa_payload), None
        om, amp, ph = w.modes()
        wind = (
            _triple("wind.velocity", w.velocity),
            _triple("wind.gust", w.gust),
            w.gust_start,
            w.gust_duration,
            w.air_density,
            (om.tolist(), amp.tolist(), ph.tolist()),
        )
        knots = (self.pivot.knots(t0 - 1.0, t1 + 1.0), self.hoist.knots(t0 - 1.0, t1 + 1.0))
        spec = CraneSpec(*knots, (body1, body2), self.g, self.damping, wind)
        options = RunOptions(save_times=save, rtol=rtol, atol=atol, max_steps=MAX_STEPS)
        out = crane_simulate(spec, y0.tolist(), options)
        y, t = out["y"], out["t"]
        piv = self.pivot.position(t)
        x1, v1 = y[:, 0:3], y[:, 3:6]
        x2, v2 = (y[:, 6:9], y[:, 9:12]) if hooked else (x1, v1)
        energy = 0.5 * self.payload_mass * np.sum(v2 * v2, axis=1) + self.payload_mass * self.g * x2[:, 2]
        if hook is not None:
            energy += 0.5 * hook[0] * np.sum(v1 * v1, axis=1) + hook[0] * self.g * x1[:, 2]
        work = {k: y[:, 12 + i] for i, k in enumerate(("hoist", "pivot", "wind", "damping"))}
        rope, rope_range = self.hoist.length(t), self.hoist.length_range(t0, float(t[-1]))
        t1 = out["tension"][:, 0]
        u1 = (x1 - piv) / rope[:, None]
        power = {
            "hoist": -t1 * self.hoist.velocity(t)[:, 0],
            "pivot": -t1 * np.sum(u1 * self.pivot.velocity(t), axis=1),
        }
        return CraneRun(
            t=t,
            payload=x2,
            hook=x1,
            pivot=piv,
            payload_velocity=v2,
            hook_velocity=v1,
            sway=_angles(x1 - piv),
            rigging_sway=_angles(x2 - x1) if hooked else None,
            rope=rope,
            tension=out["tension"],
            energy=energy,
            work=work,
            power=power,
            steps=int(out["steps"]),
            rope_range=rope_range,
        )
