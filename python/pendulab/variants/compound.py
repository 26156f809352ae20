"""A physical (compound) pendulum — a rigid body swinging about a fixed horizontal axis — as the point
pendulum it moves like (docs/theory.md T-7.7): its equivalent length

l_eq = I_O/(M h),  I_O = Σ (I_c,i + m_i d_i²),  M = Σ m_i,  M h = Σ m_i d_i,

[m] from its parts' masses m_i [kg], the distances d_i [m] of their centres of mass from the axis
(along the line through the body's centre of mass) and their moments of inertia I_c,i [kg m²] about
their own centres (parallel to the axis). Planar swings of the body, I_O θ̈ = −M g h sin θ − τ(θ̇), are
those of the point pendulum of length l_eq with every torque divided by I_O: a dry pivot friction τ_f
[N m] is ``friction`` ε_f = τ_f/I_O [rad/s²] and a viscous pivot torque −b θ̇ [N m s] is ``damping``
c = b/I_O [1/s] (T-7.1, T-7.6). What an angle recording measures is l_eq (with g): a fitted length is
this body's l_eq, and with the geometry known except one distance, :meth:`CompoundPendulum.solve_distance`
gives that distance.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from .._core import InvalidInputError
from ..model import Pendulum


@dataclass(frozen=True)
class Part:
    """One rigid part: mass m [kg], distance d [m] of its centre of mass from the axis (negative on
    the far side of the axis), moment of inertia I_c [kg m²] about its centre of mass."""

    mass: float
    distance: float
    inertia: float = 0.0

    def __post_init__(self) -> None:
        for name, value, ok in (
            ("mass", self.mass, self.mass > 0.0),
            ("distance", self.distance, True),
            ("inertia", self.inertia, self.inertia >= 0.0),
        ):
            if not (math.isfinite(value) and ok):
                allowed = {"mass": "> 0 kg", "distance": "a finite number of m", "inertia": ">= 0 kg m²"}[
                    name
                ]
                raise InvalidInputError(f"part {name} = {value!r}: {allowed}")

    @classmethod
    def rod(cls, mass: float, length: float, start: float = 0.0) -> Part:
        """A thin uniform rod [kg, m] along the swing's radius from ``start`` [m] (0: at the axis) to
        start + length: I_c = m L²/12."""
        if not (math.isfinite(length) and length > 0.0):
            raise InvalidInputError(f"rod length = {length!r}: > 0 m")
        return cls(mass, start + length / 2.0, mass * length**2 / 12.0)

    @classmethod
    def sphere(cls, mass: float, radius: float, distance: float) -> Part:
        """A solid uniform sphere (a bob) [kg, m] with its centre at ``distance`` [m]: I_c = 2 m R²/5."""
        if not (math.isfinite(radius) and radius >= 0.0):
            raise InvalidInputError(f"sphere radius = {radius!r}: >= 0 m")
        return cls(mass, distance, 0.4 * mass * radius**2)

    @classmethod
    def disk(cls, mass: float, radius: float, distance: float) -> Part:
        """A thin uniform disk [kg, m] swinging in its own plane, centre at ``distance`` [m]:
        I_c = m R²/2."""
        if not (math.isfinite(radius) and radius >= 0.0):
            raise InvalidInputError(f"disk radius = {radius!r}: >= 0 m")
        return cls(mass, distance, 0.5 * mass * radius**2)


@dataclass(frozen=True)
class CompoundPendulum:
    """A rigid body of :class:`Part` s swinging about a fixed axis (module doc, T-7.7), e.g.
    ``pl.CompoundPendulum((pl.Part.rod(0.4, 0.6), pl.Part.sphere(1.5, 0.04, 0.55)))``."""

    parts: tuple[Part, ...]

    def __post_init__(self) -> None:
        if not self.parts:
            raise InvalidInputError("a compound pendulum needs at least one part")
        if not self.mass * self.centre > 0.0:
            raise InvalidInputError(
                f"the centre of mass is at h = {self.centre!r} m from the axis: it must hang below it (h > 0)"
            )

    @property
    def mass(self) -> float:
        """Total mass M [kg]."""
        return sum(p.mass for p in self.parts)

    @property
    def centre(self) -> float:
        """Distance h of the centre of mass from the axis [m]."""
        return sum(p.mass * p.distance for p in self.parts) / self.mass

    @property
    def inertia(self) -> float:
        """Moment of inertia about the axis I_O = Σ (I_c + m d²) [kg m²]."""
        return sum(p.inertia + p.mass * p.distance**2 for p in self.parts)

    @property
    def equivalent_length(self) -> float:
        """l_eq = I_O/(M h) [m]: the point pendulum with the same motion."""
        return self.inertia / (self.mass * self.centre)

    @property
    def formula(self) -> str:
        """The equivalent length as the report prints it, with the numbers."""
        return (
            f"l_eq = I_O/(M h) = {self.inertia:.6g} kg m² / ({self.mass:.6g} kg × {self.centre:.6g} m) "
            f"= {self.equivalent_length:.6g} m"
        )

    def period(self, g: float = 9.81) -> float:
        """Small-swing period 2π √(l_eq/g) [s] for g [m/s²] > 0."""
        return 2.0 * math.pi * math.sqrt(self.equivalent_length / g)

    def pendulum(
        self, g: float = 9.81, friction_torque: float = 0.0, damping_torque: float = 0.0
    ) -> Pendulum:
        """The equivalent point pendulum (length l_eq, mass M) for g [m/s²], a dry pivot friction torque
        τ_f [N m] (→ ``friction`` = τ_f/I_O) and a viscous pivot torque coefficient b [N m s]
        (→ ``damping`` = b/I_O)."""
        extra = {}
        if friction_torque:
            extra["friction"] = friction_torque / self.inertia
        if damping_torque:
            extra["damping"] = damping_torque / self.inertia
        # **extra holds only the model's own float parameters by name (never model/force/pivot_samples)
        return Pendulum(self.equivalent_length, g, self.mass, **extra)  # type: ignore[arg-type]

    def solve_distance(self, index: int, equivalent_length: float) -> CompoundPendulum:
        """The same body with part ``index`` moved along the radius so that its equivalent length is
        ``equivalent_length`` [m] (e.g. a fitted length → where the bob is). l_eq(d) has its minimum at
        d* where d(l_eq)/dd = 0; of the two solutions the one on the side of the given position is
        returned, or an error when the length is shorter than any position gives."""
        if not 0 <= index < len(self.parts):
            raise InvalidInputError(f"part index = {index!r}: 0 ... {len(self.parts) - 1}")
        part = self.parts[index]
        rest = [p for i, p in enumerate(self.parts) if i != index]
        # l_eq (M h) = I_O is a quadratic in d: m d² − l m d + (I_r + I_c − l S_r) = 0, S_r = Σ_rest m d
        i_rest = sum(p.inertia + p.mass * p.distance**2 for p in rest)
        s_rest = sum(p.mass * p.distance for p in rest)
        m, lq = part.mass, equivalent_length
        disc = (lq * m) ** 2 - 4.0 * m * (i_rest + part.inertia - lq * s_rest)
        if not (math.isfinite(lq) and lq > 0.0) or disc < 0.0:
            raise InvalidInputError(
                f"equivalent length = {lq!r} m: no position of part {index} gives it "
                f"(at {part.distance:g} m it is {self.equivalent_length:.6g} m)"
            )
        roots = ((lq * m - math.sqrt(disc)) / (2 * m), (lq * m + math.sqrt(disc)) / (2 * m))
        d = min(roots, key=lambda r: abs(r - part.distance))
        parts = list(self.parts)
        parts[index] = replace(part, distance=d)
        return CompoundPendulum(tuple(parts))
