"""The ``[initial]`` table of a scenario file: the start either as angles — θ (polar angle from the
downward vertical) and φ (azimuth atan2(y, x)) in rad, or as ``theta_deg``/``phi_deg`` in degrees,
with rates θ̇, φ̇ [rad/s] — or as a Cartesian position x [m] and velocity v [m/s] of the bob, which
``project = true`` moves onto TS² (the constraint |x| = l, x·v = 0 of docs/theory.md §1, T-1.1; the core
checks it when the scenario is built, :mod:`pendulab.scenario.build`). The validator refuses a mix of
the two forms, a key given in rad and in degrees, and a missing polar angle.
"""

from __future__ import annotations

from pydantic import Field, model_validator

from .table_base import _DEG, _VEC3, _lim, _Position, _Section, _show, _Velocity

_ANGLE_KEYS = ("theta", "theta_deg", "phi", "phi_deg", "theta_dot", "phi_dot")
_CARTESIAN_KEYS = ("x", "v", "project")


class InitialSection(_Section):
    """``[initial]``: the start, either as angles or as Cartesian position and velocity."""

    theta: float | None = Field(
        None, description="polar angle from the downward vertical in rad, in [-1e6, 1e6]", **_lim("angle")
    )
    theta_deg: float | None = Field(
        None, description="polar angle from the downward vertical in degrees, in [-1e6, 1e6]", **_lim("angle")
    )
    phi: float | None = Field(
        None, description="azimuth atan2(y, x) in rad, in [-1e6, 1e6] (default 0)", **_lim("angle")
    )
    phi_deg: float | None = Field(
        None, description="azimuth atan2(y, x) in degrees, in [-1e6, 1e6] (default 0)", **_lim("angle")
    )
    theta_dot: float | None = Field(
        None, description="polar angular rate in rad/s, in [-1e9, 1e9] (default 0)", **_lim("angle_rate")
    )
    phi_dot: float | None = Field(
        None, description="azimuthal angular rate in rad/s, in [-1e9, 1e9] (default 0)", **_lim("angle_rate")
    )
    x: list[_Position] | None = Field(
        None, description="position of the bob in m, 3 numbers in [-1e9, 1e9]", **_VEC3
    )
    v: list[_Velocity] | None = Field(
        None, description="velocity of the bob in m/s, 3 numbers in [-1e7, 1e7]", **_VEC3
    )
    project: bool | None = Field(
        None, description="true or false: move a Cartesian start onto TS² (default false: refuse it)"
    )

    @model_validator(mode="after")
    def _one_form(self) -> InitialSection:
        given = {k for k in (*_ANGLE_KEYS, *_CARTESIAN_KEYS) if getattr(self, k) is not None}
        for rad, deg in (("theta", "theta_deg"), ("phi", "phi_deg")):
            if rad in given and deg in given:
                raise ValueError(
                    f"give either {rad} (rad) or {deg} (degrees), not both: "
                    f"{rad} = {getattr(self, rad)!r}, {deg} = {getattr(self, deg)!r}"
                )
        angles = sorted(given & set(_ANGLE_KEYS))
        cartesian = sorted(given & set(_CARTESIAN_KEYS))
        if angles and cartesian == ["project"]:
            raise ValueError(
                f"project = {_show(self.project)} applies only to a Cartesian start (x, v); "
                "a start given by angles is always on TS²"
            )
        if angles and cartesian:
            raise ValueError(
                "give the start either as angles (theta_deg or theta, phi_deg or phi, theta_dot, phi_dot) "
                f"or as Cartesian x and v, not both: got {', '.join(angles)} and {', '.join(cartesian)}"
            )
        if cartesian:
            missing = [k for k in ("x", "v") if k not in given]
            if missing:
                raise ValueError(
                    f"{' and '.join(missing)} missing: a Cartesian start needs both x (3 numbers, m) "
                    "and v (3 numbers, m/s)"
                )
        elif "theta" not in given and "theta_deg" not in given:
            raise ValueError(
                "no initial polar angle: give theta_deg (degrees) or theta (rad), "
                "or a Cartesian start x = [..] (m) and v = [..] (m/s)"
            )
        return self

    @property
    def cartesian(self) -> bool:
        """True for a start given as x and v."""
        return self.x is not None

    def angles(self) -> tuple[float, float, float, float]:
        """(θ [rad], φ [rad], θ̇ [rad/s], φ̇ [rad/s]) of an angle start; degrees converted as deg·π/180."""
        theta = self.theta if self.theta is not None else float(self.theta_deg or 0.0) * _DEG
        phi = self.phi if self.phi is not None else float(self.phi_deg or 0.0) * _DEG
        return theta, phi, self.theta_dot or 0.0, self.phi_dot or 0.0
