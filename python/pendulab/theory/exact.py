"""The exact solution of the ideal spherical pendulum (docs/theory.md §4–5), from any state on TS², any g.

``pl.exact(pendulum, state)`` sets the solution up once (roots of the cubic T-4.1, the elliptic
parameter, the start's phase); afterwards a state at any time t [s], negative too, costs the same
whether t = 1 s or t = 10⁶ s (T-4.2 … T-4.4 with the argument reduced by the period). Units: SI —
t [s], x [m], v [m/s], heights [m], periods [s], angles [rad]. The motion is classified as in T-4.6:

=================== ==========================================================================
``kind``            motion
=================== ==========================================================================
``generic``         J₃ ≠ 0: z swings between z₁ and z₂ while the azimuth advances (T-4.2, T-4.4)
``conical``         J₃ ≠ 0 at constant height (z₂ − z₁ at round-off, T-6.1)
``planar``          J₃ = 0, swinging through the bottom; φ jumps by π at the pole
``planar_rotating`` J₃ = 0, going over the top
``separatrix``      J₃ = 0 at exactly the energy of the top: creeps towards it forever
``rest``            at rest at an equilibrium (or anywhere when g = 0)
``great_circle``    g = 0 (or |g| negligible: |v₀|²/(2|g|l) > 1e100): uniform motion along a great circle
=================== ==========================================================================

For g < 0 the solution is the mirror image z → −z of the one with gravity |g| (J₃ and φ unchanged).
Its states as a Trajectory, summary, notebook table, overview figure and movie:
:mod:`pendulab.theory.exact_output`.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, overload

import numpy as np
import numpy.typing as npt

from .._core import ExactSolution as _ExactSolution
from .._core import InvalidInputError
from ..display import Row, html_table, number
from ..memory import check_memory
from ..model import FloatArray, Pendulum, State, _frozen, check_pendulum_state
from ..trajectory import Trajectory
from ..validate import array, show
from . import exact_output as output

if TYPE_CHECKING:
    import os

    from ..animate import Movie, MovieSettings

BYTES_PER_TIME = 96
"""Memory [B] the exact solution needs per evaluation time: the core's x, v (3 + 3 float64), φ and
the time, and the finiteness checks' masks (checked against the available memory first)."""

KINDS = ("generic", "conical", "planar", "planar_rotating", "separatrix", "rest", "great_circle")
"""The kinds of motion (T-4.6), as ``ExactSolution.kind`` names them."""

_PHASE_KINDS = ("generic", "conical")


@dataclass(frozen=True)
class Phases:
    """The azimuthal advance per z-period and its split (T-5.1), all in rad.

    ``total`` is Δφ from T-4.5 (elliptic integrals of the third kind); ``dynamic`` = 2 T_z⟨K⟩/J₃
    (K the kinetic energy per unit mass, in the dimensionless form of §1) and ``geometric`` =
    −(area enclosed by the reduced orbit in the (z, p_z) plane)/J₃, computed independently by
    quadrature. ``sum`` = dynamic + geometric equals ``total`` to ~1e-14; ``difference`` = total − sum.
    """

    total: float
    dynamic: float
    geometric: float

    def __repr__(self) -> str:
        return (
            f"Phases(total={number(self.total, 10)} rad = dynamic {number(self.dynamic, 10)} "
            f"+ geometric {number(self.geometric, 10)} rad)"
        )

    def _repr_html_(self) -> str:
        rows: list[Row] = [
            ("Δφ per z-period (T-4.5)", self.total, "rad"),
            ("dynamic part Δφ_dyn", self.dynamic, "rad"),
            ("geometric part Δφ_geom", self.geometric, "rad"),
            ("total − (dynamic + geometric)", number(self.difference, 3), "rad"),
        ]
        return html_table("Phases of one z-period (T-5.1)", rows)

    @property
    def sum(self) -> float:
        """Δφ_dyn + Δφ_geom [rad]."""
        return self.dynamic + self.geometric

    @property
    def difference(self) -> float:
        """total − (dynamic + geometric) [rad]: zero up to rounding."""
        return self.total - self.sum


def _times(t: Any) -> tuple[FloatArray, bool]:
    """t as a contiguous float64 array and whether it was a scalar; within the time and samples limits
    of :mod:`pendulab.validate` (a clear error naming t otherwise)."""
    arr = array("t", t, "time")
    return np.ascontiguousarray(arr.reshape(-1)), arr.ndim == 0


class ExactSolution:
    """The exact motion through ``state`` at t = 0 (build it with :func:`exact`).

    Time-independent properties: ``kind``, ``turning_heights`` [m], ``modulus``, ``period_z`` [s],
    ``azimuth_advance`` [rad], ``rotation_number``; per-orbit results: :meth:`phases`,
    :meth:`constants`; at given times: :meth:`state`, :meth:`azimuth`, :meth:`trajectory`.
    """

    def __init__(self, pendulum: Pendulum, state: State) -> None:
        if not isinstance(pendulum, Pendulum):
            raise InvalidInputError(f"pendulum must be a pendulab.Pendulum, got {type(pendulum).__name__}")
        if not isinstance(state, State):
            raise InvalidInputError(
                f"state must be a pendulab.State (from Pendulum.state or state_from_angles), "
                f"got {type(state).__name__}"
            )
        check_pendulum_state(pendulum, state)  # a hand-made State of complex numbers: named, not cast
        if not pendulum.is_ideal:
            raise InvalidInputError(
                f"the exact solution exists only for the ideal pendulum, not the {pendulum.model!r} model "
                "(damping, forcing and rotating frames break integrability); simulate it instead"
            )
        self._pendulum = pendulum
        self._start = state
        try:
            self._core = _ExactSolution(pendulum.spec, state.pair)
        except InvalidInputError as e:
            raise self._refusal("", e) from None

    def _inputs(self) -> str:
        """The inputs, for messages: the pendulum and the start (values abbreviated)."""
        p, s = self._pendulum, self._start
        x, v = show(s.x.tolist()), show(s.v.tolist())
        return f"l = {p.length!r} m, g = {p.g!r} m/s^2 from x = {x} m, v = {v} m/s"

    def _refusal(self, at: str, core: Exception) -> InvalidInputError:
        """The error for an input the elliptic form cannot evaluate to its accuracy: it names the
        input (the core's internal reason goes into a note, not the message)."""
        err = InvalidInputError(
            f"no exact solution{at} for {self._inputs()} to the accuracy of docs/exact.md: the start is at "
            "a degenerate limit of the elliptic form (e.g. J3 ~ 0 at a pole, or extreme energy); simulate it "
            "instead (pl.simulate with 'rattle' or 'dop853')"
        )
        err.add_note(f"core: {core}")
        return err

    def _states(self, times: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        """The core's states at ``times``, refused (naming the input) where not finite; refused before
        anything is computed when the answer would not fit in memory (:mod:`pendulab.memory`)."""
        check_memory(
            f"the exact solution at {times.size} times",
            times.size * BYTES_PER_TIME,
            "ask for fewer times at once (in chunks)",
        )
        try:
            x, v, phi = self._core.states(times)
        except InvalidInputError as e:
            at = f" at t in [{times.min()!r}, {times.max()!r}] s" if times.size else ""
            raise self._refusal(at, e) from None
        self._finite(times, x, v)
        return x, v, phi

    def _finite(self, times: FloatArray, *arrays: Any) -> None:
        """Refuses (naming the input) where the solution is not finite, rather than returning NaN."""
        for a in arrays:
            bad = ~np.isfinite(a)
            if bad.any():
                k = int(np.flatnonzero(bad.reshape(len(times), -1).any(axis=1))[0])
                raise InvalidInputError(
                    f"the exact solution is not finite at t = {times[k]!r} s for {self._inputs()}: "
                    "this start is beyond the solution's accuracy (docs/exact.md); simulate it instead"
                )

    # --- the orbit ---

    @property
    def pendulum(self) -> Pendulum:
        """The pendulum (l [m], m [kg], g [m/s²])."""
        return self._pendulum

    @property
    def start(self) -> State:
        """The state at t = 0."""
        return self._start

    @property
    def kind(self) -> str:
        """One of :data:`KINDS` (T-4.6)."""
        return self._core.kind

    @property
    def omega0(self) -> float:
        """ω₀ = √(|g|/l) [1/s] (0 when g = 0)."""
        return self._core.omega0

    @property
    def turning_heights(self) -> tuple[float, ...]:
        """Heights [m] between which z moves, ``(z₁, z₂)`` with z₁ ≤ z₂, plus z₃ for generic and conical
        orbits: ``(z₁, z₂, z₃)``, the third root of the cubic T-4.1, outside [−l, l] (above l for
        g > 0, below −l for g < 0, mirrored). Planar swings give (−l, z₂) (g > 0), motion over the
        top (−l, l), rest (z₀, z₀), great circles (−A, A) with A the highest point reached."""
        z1, z2, z3 = self._core.turning_heights
        return (z1, z2) if z3 is None else (z1, z2, z3)

    @property
    def modulus(self) -> float | None:
        """The parameter m = k² of the Jacobi functions (dimensionless), None at rest and on great circles."""
        return self._core.modulus

    @property
    def period_z(self) -> float | None:
        """Period of z(t) [s] (T-4.3). Planar swings: the swing period 4K/ω₀ (z itself repeats after
        half of it); over the top: one revolution; great circles: 2πl/|v|; separatrix: ``inf``;
        None at rest."""
        return self._core.period_z

    @property
    def azimuth_advance(self) -> float | None:
        """Δφ [rad] per z-period (T-4.5), with the sign of J₃; None unless the kind is generic or conical."""
        return self._core.azimuth_advance

    @property
    def rotation_number(self) -> float | None:
        """W = Δφ/2π (dimensionless, T-4.5; 1/2 < |W| < 1 by Puiseux), None where Δφ is."""
        dphi = self.azimuth_advance
        return None if dphi is None else dphi / (2.0 * math.pi)

    def phases(self) -> Phases:
        """Δφ per z-period and its dynamic and geometric parts (T-5.1), in rad.

        Defined for orbits with J₃ ≠ 0 and g ≠ 0 (kinds ``generic`` and ``conical``; a conical orbit
        has geometric part 0). Any other kind raises :class:`pendulab.InvalidInputError` saying why:
        the split divides by J₃, planar motion has no azimuthal advance, and with g = 0 there is no
        potential (great circles).

        Examples
        --------
        >>> import numpy as np
        >>> import pendulab as pl
        >>> p = pl.Pendulum()
        >>> ph = pl.exact(p, p.state_from_angles(theta=np.radians(60), phi_dot=2.0)).phases()
        >>> round(ph.total, 9), round(ph.dynamic + ph.geometric, 9)
        (3.83116239, 3.83116239)
        """
        p = self._core.phases()
        if p is None and self._pendulum.g == 0.0:
            raise InvalidInputError(
                f"phases need gravity: with g = 0 m/s^2 the orbit is a {self.kind!r} (uniform motion on a "
                "great circle), with no oscillation of z about a potential minimum to split the advance over"
            )
        if p is None:
            raise InvalidInputError(
                f"phases are defined for orbits with J3 != 0 (kinds {', '.join(_PHASE_KINDS)}); "
                f"this orbit is {self.kind!r} (J3 = {self._pendulum.j3(self._start):.6g} kg m^2/s, "
                f"g = {self._pendulum.g:g} m/s^2)"
            )
        return Phases(*p)

    @property
    def weierstrass(self) -> dict[str, Any] | None:
        """The Weierstrass form of the height (T-4.7), dimensionless (u = z/l, or −z/l when g < 0;
        τ = ω₀t): ``g2`` = ε²/3 + 1 and ``g3`` = ε³/27 − ε/3 + j²/4, the invariants of
        w_τ² = 4w³ − g₂w − g₃ with u = 2w + ``shift`` (ε/3); its roots ``e`` = [e₁, e₂, e₃] (descending);
        ``omega1``, the real half-period in τ (inf on the separatrix; the z-period is 2·omega1/ω₀ [s]).
        None at rest and for g = 0 (no cubic). docs/exact.md."""
        return self._core.weierstrass()

    def height_weierstrass(self, t: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
        """z(t) [m] and ż(t) [m/s] at times ``t`` [s] through ℘ (T-4.7): a second path, independent of
        the Jacobi form of :meth:`state`, agreeing with it to 1e-13 relative (docs/exact.md). Arrays of
        the shape of ``t``. Raises InvalidInputError at rest and for g = 0, where there is no cubic."""
        tt = np.asarray(t, dtype=np.float64)
        out = self._core.heights_weierstrass(np.ascontiguousarray(tt.ravel()))
        if out is None:
            raise InvalidInputError(
                f"a {self.kind!r} motion has no Weierstrass form (no cubic: rest, or g = 0)"
            )
        return out[0].reshape(tt.shape), out[1].reshape(tt.shape)

    def constants(self) -> dict[str, float]:
        """The orbit's constants. Always ``omega0`` [1/s]; for g ≠ 0 also ``epsilon`` = E/(m|g|l) and
        ``j`` = J₃/(m l² ω₀) (dimensionless, §1) and ``m`` where defined; for generic and conical orbits
        the dimensionless roots ``u1`` ≤ ``u2`` ≤ ``u3`` of T-4.1 (u = z/l, or −z/l when g < 0),
        ``lambda``, ``n_plus``, ``n_minus``, ``K`` (T-4.2 … T-4.5)."""
        out: dict[str, float] = {"omega0": self.omega0}
        core = self._core.constants()
        if core is not None:
            return out | {k: float(v) for k, v in core.items()}
        p = self._pendulum
        if p.g != 0.0:
            out["epsilon"] = p.energy(self._start) / (p.mass * abs(p.g) * p.length)
            out["j"] = p.j3(self._start) / (p.mass * p.length**2 * self.omega0)
        if self.modulus is not None:
            out["m"] = self.modulus
        return out

    # --- states at given times ---

    @overload
    def state(self, t: float) -> State: ...
    @overload
    def state(self, t: Any) -> tuple[FloatArray, FloatArray]: ...

    def state(self, t: Any) -> State | tuple[FloatArray, FloatArray]:
        """The state at time t [s] (any finite t, negative too).

        A scalar t gives a :class:`State`; an array of times gives ``(x, v)`` with shapes
        ``t.shape + (3,)``: position [m] and velocity [m/s].
        """
        times, scalar = _times(t)
        x, v, _ = self._states(times)
        if scalar:
            return State(_frozen(x[0]), _frozen(v[0]))
        shape = (*np.shape(t), 3)
        return x.reshape(shape), v.reshape(shape)

    def azimuth(self, t: Any) -> Any:
        """The continuous azimuth φ(t) [rad] (a float for scalar t, else an array of t's shape).

        It continues across the branch cut of atan2 (no 2π jumps); for planar motion (J₃ = 0) it jumps
        by π where the bob passes through a pole, and only there. NaN at rest at a pole."""
        times, scalar = _times(t)
        _, _, phi = self._states(times)
        return float(phi[0]) if scalar else phi.reshape(np.shape(t))

    def trajectory(self, t: Any) -> Trajectory:
        """The exact states at the times t [s] (1-D, any order) as a :class:`Trajectory` with method
        ``"exact"``, so its diagnostics, summary and file writers apply."""
        return output.trajectory(self, t)

    def animate(
        self,
        path: str | os.PathLike[str],
        settings: MovieSettings | None = None,
        *,
        t: tuple[float, float] | None = None,
        **options: Any,
    ) -> Movie:
        """Writes a movie of the exact motion over ``t`` = (t_start, t_end) [s] to ``path`` (.mp4,
        .webm or .gif): every frame is :meth:`state` at its time (T-4.2 … T-4.4), nothing is
        integrated or interpolated, at any frame rate. ``t`` defaults to (0, speed · duration), or
        (0, 10 s) without a duration. The other arguments are those of
        :meth:`pendulab.Trajectory.animate` (a :class:`pendulab.animate.MovieSettings` and/or its
        fields as keywords); returns a :class:`pendulab.animate.Movie`."""
        return output.animate(self, path, settings, t, **options)

    def summary(self) -> str:
        """A few lines: kind, turning heights, z-period, Δφ and W (SI units)."""
        return output.summary(self)

    def __repr__(self) -> str:
        tz = "" if self.period_z is None else f", T_z = {number(self.period_z, 9)} s"
        return f"ExactSolution(kind={self.kind!r}{tz}, pendulum={self._pendulum!r})"

    def _repr_html_(self) -> str:
        return output.html(self)

    def default_times(self, points: int = 2000) -> FloatArray:
        """``points`` times [s] covering three z-periods (or 10/ω₀ when there is no period, 10 s when
        g = 0): what :meth:`plot` draws by default."""
        return output.default_times(self, points)

    def plot(self, path: str | os.PathLike[str] | None = None, *, t: Any = None, **kwargs: Any) -> Any:
        """The overview figure of the exact motion at the times ``t`` [s] (keyword; default
        :meth:`default_times`): the path on the sphere, z(t) between the turning heights z₁, z₂
        (dashed), and the drift of E and J₃ — which for the exact solution stays at rounding level.
        Saved atomically to ``path`` if given (first argument or keyword, as for every ``plot``
        method: ``sol.plot("x.png")``). Needs matplotlib. Returns the Figure."""
        return output.plot(self, path, t, **kwargs)


def exact(pendulum: Pendulum, state: State) -> ExactSolution:
    """The exact solution through ``state`` (on TS², at t = 0) of the ideal pendulum, any g
    (docs/theory.md §4).

    Raises :class:`pendulab.InvalidInputError` for a state off TS² or non-finite values.

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> p = pl.Pendulum()
    >>> sol = pl.exact(p, p.state_from_angles(theta=np.radians(60), phi_dot=2.0))
    >>> sol.kind
    'generic'
    >>> round(sol.period_z, 6)
    1.079669
    >>> x, v = sol.state(np.array([0.0, 1e6]))
    >>> x.shape
    (2, 3)
    """
    return ExactSolution(pendulum, state)
