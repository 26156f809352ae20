"""The energy–momentum map (J₃, E) of the spherical pendulum and its rotation number (T-6.4, T-4.5).

Every motion has two conserved quantities, the energy E [J] and the vertical angular momentum
J₃ [kg m²/s] (T-2.6); the map sends a state to (J₃, E). Its image is bounded by the conical
orbits (T-6.1) and has the stable bottom (0, −mgl) as its vertex; inside lies the line J₃ = 0 of
planar motions with the unstable top (0, +mgl), a focus–focus value. On each orbit the rotation
number W = Δφ/2π (T-4.5, dimensionless) is defined for J₃ ≠ 0, with 1/2 < |W| < 1 (Puiseux).
Carried continuously once around the top, W comes back changed by exactly ±1: Hamiltonian
monodromy (Duistermaat 1980; Cushman & Bates 1997).

The core works in the dimensionless ε = E/(m g l), j = J₃/(m l² ω₀) of §1; this module converts
to SI: E = ε m g l, J₃ = j m l² ω₀. For g < 0 the motion is the mirror image z → −z of gravity
|g|, which leaves E, J₃ and Δφ unchanged, so the map is the same as for |g| (the "top" is then the
equilibrium at z = −l). For g = 0 there is no potential and no such map (an error).
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .. import io
from .._core import InvalidInputError, conical_curve, rotation_numbers
from .._core import monodromy as _monodromy
from ..display import html_table, number
from ..model import FloatArray, Pendulum
from ..validate import MAX_SAMPLES, finite, integer, invalid

MAX_GRID_POINTS = 4_000_000
"""Largest number of grid points :func:`em_map` evaluates (~10 s)."""

DEFAULT_EPS_RANGE = (-1.1, 2.5)
"""Default energy range, in units of m|g|l."""

DEFAULT_J_RANGE = (-2.4, 2.4)
"""Default J₃ range, in units of m l² ω₀ (the boundary reaches j = ±2.28 at ε = 2.5)."""


def _check_range(name: str, r: Any, unit: str) -> tuple[float, float]:
    allowed = f"two finite numbers (min, max) with min < max, in {unit}"
    if isinstance(r, str | bytes) or not hasattr(r, "__len__") or len(r) != 2:
        raise invalid(name, r, allowed)
    lo, hi = finite(f"{name}[0]", r[0], allowed), finite(f"{name}[1]", r[1], allowed)
    if not lo < hi:
        raise InvalidInputError(f"{name} = ({lo!r}, {hi!r}) must be finite with min < max, in {unit}")
    return lo, hi


def _check_grid(grid: Any) -> tuple[int, int]:
    try:
        nj, ne = grid
    except (TypeError, ValueError, RecursionError):
        raise invalid("grid", grid, "two integers (n_J3, n_E)") from None
    for name, n in (("n_J3", nj), ("n_E", ne)):
        if isinstance(n, bool) or not isinstance(n, int | np.integer) or not 2 <= n <= MAX_GRID_POINTS:
            raise invalid(f"grid {name}", n, f"an integer in [2, {MAX_GRID_POINTS}]")
    if nj * ne > MAX_GRID_POINTS:
        raise InvalidInputError(
            f"grid = {nj}x{ne} = {nj * ne} points exceeds the limit of {MAX_GRID_POINTS}; use a coarser grid"
        )
    return int(nj), int(ne)


def _continued(w: FloatArray) -> FloatArray:
    """W along a closed loop made continuous by integer shifts (W jumps by ±1 where the loop crosses
    J₃ = 0, where Δφ changes sign; the shift that keeps it continuous is the monodromy's)."""
    out = np.array(w, dtype=np.float64)
    shift = 0.0
    for k in range(1, len(out)):
        shift += round(out[k - 1] - (w[k] + shift))
        out[k] = w[k] + shift
    return out


@dataclass(frozen=True)
class EMMap:
    """The energy–momentum image on a grid (build it with :func:`em_map`).

    ``J3`` (n_J3,) [kg m²/s] and ``E`` (n_E,) [J] are the axes; ``W`` (n_E, n_J3) the rotation number
    (dimensionless; NaN outside the image and on J₃ = 0). ``boundary`` = (J₃ [kg m²/s], E [J]) along the
    conical family, both branches through the vertex (0, −mgl). ``critical_values``: ``bottom``
    (0, −m|g|l) and ``top`` (0, +m|g|l) as (J₃, E). ``energy_unit`` = m|g|l [J] and ``momentum_unit`` =
    m l² ω₀ [kg m²/s] convert to the dimensionless ε, j of the core.
    """

    pendulum: Pendulum
    J3: FloatArray
    E: FloatArray
    W: FloatArray
    boundary: tuple[FloatArray, FloatArray]
    energy_unit: float
    momentum_unit: float
    critical_values: dict[str, tuple[float, float]] = field(default_factory=dict)

    def _summary(self) -> list[tuple[str, Any, str]]:
        return [
            ("grid (n_J3 × n_E)", f"{len(self.J3)} × {len(self.E)}", ""),
            ("J₃ from … to", f"{number(self.J3[0])} … {number(self.J3[-1])}", "kg m²/s"),
            ("E from … to", f"{number(self.E[0])} … {number(self.E[-1])}", "J"),
            ("points in the image", int(np.isfinite(self.W).sum()), ""),
            ("m|g|l, m l² ω₀", f"{number(self.energy_unit)}, {number(self.momentum_unit)}", "J, kg m²/s"),
        ]

    def __repr__(self) -> str:
        return (
            f"EMMap({len(self.J3)} x {len(self.E)} grid, J3 = {number(self.J3[0])} … {number(self.J3[-1])} "
            f"kg m²/s, E = {number(self.E[0])} … {number(self.E[-1])} J, pendulum={self.pendulum!r})"
        )

    def _repr_html_(self) -> str:
        return html_table("Energy–momentum map (rotation number W)", self._summary())

    def monodromy(self, radius: float = 0.5, n: int = 720) -> float:
        """The change of W carried once around the top on the circle (j, ε) = (r sin α, 1 + r cos α),
        α from 0 to 2π in ``n`` steps, r = ``radius`` in the dimensionless units (of m l² ω₀ in J₃, of
        m|g|l in E): ±1 to rounding (T-6.4). A circle that leaves the image is an error."""
        radius = finite("radius", radius, "a finite radius > 0 (dimensionless)")
        return float(_monodromy(radius, integer("n", n, 3, MAX_SAMPLES)))

    def loop(self, radius: float = 0.5, n: int = 720) -> tuple[FloatArray, FloatArray, FloatArray]:
        """The monodromy loop (see :meth:`monodromy`) as (J₃ [kg m²/s], E [J], W continued), starting just
        right of J₃ = 0 above the top; W(end) − W(start) = :meth:`monodromy`."""
        radius = finite("radius", radius, "a finite radius > 0 (dimensionless)")
        n = integer("n", n, 3, MAX_SAMPLES)
        alpha = math.pi / n + 2.0 * math.pi * np.arange(n + 1) / n
        j, eps = radius * np.sin(alpha), 1.0 + radius * np.cos(alpha)
        w = rotation_numbers(np.ascontiguousarray(eps), np.ascontiguousarray(j))
        if np.any(np.isnan(w)):
            raise InvalidInputError(
                f"the loop of radius {radius!r} around the top leaves the image of the energy-momentum map"
            )
        return j * self.momentum_unit, eps * self.energy_unit, _continued(w)

    def metadata(self) -> dict[str, Any]:
        """Parameters, units and the critical values (what the data files carry)."""
        return {
            "software": "pendulab",
            "what": "energy-momentum map: rotation number W = dphi/2pi per z-period (T-4.5, T-6.4)",
            "pendulum": self.pendulum.params(),
            "units": {"E": "J", "J3": "kg m^2/s", "W": "1"},
            "energy_unit_mgl": self.energy_unit,
            "momentum_unit_ml2w0": self.momentum_unit,
            "critical_values": {k: list(v) for k, v in self.critical_values.items()},
        }

    def to_xarray(self) -> Any:
        """An ``xarray.Dataset``: W on dims (E, J3), the boundary on dim ``b``, units as attributes."""
        xr = io._require("xarray")
        jb, eb = self.boundary
        return xr.Dataset(
            {
                "W": (("E", "J3"), self.W, {"units": "1", "long_name": "rotation number dphi/2pi"}),
                "boundary_J3": ("b", jb, {"units": "kg m^2/s", "long_name": "conical boundary, J3"}),
                "boundary_E": ("b", eb, {"units": "J", "long_name": "conical boundary, E"}),
            },
            coords={"E": ("E", self.E, {"units": "J"}), "J3": ("J3", self.J3, {"units": "kg m^2/s"})},
            attrs={"pendulab": json.dumps(self.metadata(), sort_keys=True)},
        )

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Writes the grid atomically: ``.nc`` (NetCDF via xarray, scipy engine) or ``.csv`` (one row per
        grid point: E [J], J3 [kg m²/s], W; a ``#`` metadata line first).
        Images: :func:`pendulab.plot.plot_em_map`."""
        target = Path(path)
        suffix = target.suffix.lower()
        if suffix == ".nc":
            io._require("scipy")
            ds = self.to_xarray()
            with io.atomic_path(target) as tmp:
                ds.to_netcdf(tmp, engine="scipy")
        elif suffix == ".csv":
            ee, jj = np.meshgrid(self.E, self.J3, indexing="ij")
            columns = {"E": ("J", ee.ravel()), "J3": ("kg m^2/s", jj.ravel()), "W": ("1", self.W.ravel())}
            io.write_columns_csv(target, "em-map", self.metadata(), columns)
        else:
            raise InvalidInputError(
                f"unknown suffix {suffix!r} in {str(path)!r} for the energy-momentum map data; "
                "use .nc or .csv (or .png with pendulab.plot.plot_em_map)"
            )
        return target


def conical_boundary(pendulum: Pendulum, n: int = 801) -> tuple[FloatArray, FloatArray]:
    """The conical family bounding the image, as (J₃ [kg m²/s], E [J]) with J₃ from negative to positive
    through the vertex (0, −m|g|l); heights u = z/l ∈ (−1, 0) spaced to resolve both ends."""
    eu, mu = _units(pendulum)
    s = np.linspace(0.0, 1.0, n)[1:-1]
    u = -(np.cos(0.5 * math.pi * s) ** 2)  # from near −1 (the vertex) to near 0 (far out)
    j, eps = conical_curve(np.ascontiguousarray(u))
    jj = np.concatenate([-j[::-1], [0.0], j])
    ee = np.concatenate([eps[::-1], [-1.0], eps])
    return jj * mu, ee * eu


def _units(pendulum: Pendulum) -> tuple[float, float]:
    if not isinstance(pendulum, Pendulum):
        raise InvalidInputError(f"pendulum must be a pendulab.Pendulum, got {type(pendulum).__name__}")
    if pendulum.g == 0.0:
        raise InvalidInputError(
            "the energy-momentum map needs gravity: g = 0 m/s^2 has no potential (every orbit is a great "
            "circle); give g > 0 (or g < 0, the mirror image)"
        )
    p = pendulum
    return p.mass * abs(p.g) * p.length, p.mass * p.length**2 * p.omega0


def em_map(
    pendulum: Pendulum,
    j_range: tuple[float, float] | None = None,
    e_range: tuple[float, float] | None = None,
    grid: tuple[int, int] = (400, 400),
) -> EMMap:
    """The rotation number W(E, J₃) on a grid of ``grid = (n_J3, n_E)`` points over ``j_range``
    [kg m²/s] × ``e_range`` [J]. Defaults: j ∈ [−2.4, 2.4] m l² ω₀ and ε ∈ [−1.1, 2.5] m|g|l, which hold
    the bottom, the top and the monodromy loop. Grid points within 1e-12 (relative to the J₃ range) of
    J₃ = 0 are put on it. g < 0 is mapped as its mirror image (module docstring); g = 0, models other
    than the ideal pendulum, bad ranges and grids raise :class:`pendulab.InvalidInputError`.

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> emm = pl.em_map(pl.Pendulum(), grid=(100, 100))
    >>> emm.W.shape
    (100, 100)
    >>> round(emm.monodromy())
    -1
    """
    eu, mu = _units(pendulum)
    if not pendulum.is_ideal:
        raise InvalidInputError(
            f"the energy–momentum map is that of the ideal pendulum, not the {pendulum.model!r} model"
        )
    jr = (
        _check_range("j_range", j_range, "kg m^2/s")
        if j_range is not None
        else tuple(mu * v for v in DEFAULT_J_RANGE)
    )
    er = (
        _check_range("e_range", e_range, "J")
        if e_range is not None
        else tuple(eu * v for v in DEFAULT_EPS_RANGE)
    )
    nj, ne = _check_grid(grid)
    j3 = np.linspace(jr[0], jr[1], nj)
    j3[np.abs(j3) <= 1e-12 * (jr[1] - jr[0])] = 0.0  # rounding of linspace: put such points on J₃ = 0
    e = np.linspace(er[0], er[1], ne)
    ee, jj = np.meshgrid(e / eu, j3 / mu, indexing="ij")
    w = rotation_numbers(np.ascontiguousarray(ee.ravel()), np.ascontiguousarray(jj.ravel()))
    return EMMap(
        pendulum=pendulum,
        J3=j3,
        E=e,
        W=w.reshape(ne, nj),
        boundary=conical_boundary(pendulum),
        energy_unit=eu,
        momentum_unit=mu,
        critical_values={"bottom": (0.0, -eu), "top": (0.0, eu)},
    )
