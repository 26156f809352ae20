"""The output spacing of the crane's Python calls (:meth:`pendulab.crane.Crane.simulate`,
:func:`pendulab.crane.residual_grid`): the keyword ``output_spacing`` [s], the time between saved samples
(the crane's DOP853 chooses its own steps). ``dt`` is its older name, still taken with a
DeprecationWarning, as a crane file's ``[simulation] dt`` is still read (docs/cranes.md)."""

from __future__ import annotations

import warnings

from .._core import InvalidInputError

OLD_NAME = "dt"


def spacing(where: str, output_spacing: float | None, dt: float | None, default: float) -> tuple[str, float]:
    """(the name the spacing was given by, the spacing [s]) of the call ``where`` (e.g.
    ``"Crane.simulate"``): ``output_spacing``, else the older ``dt`` (a DeprecationWarning naming
    ``output_spacing``, pointing at the caller of ``where``), else ``default``. Both given is an
    ``InvalidInputError`` naming both values. ``None`` is "not given"."""
    if dt is None:
        return "output_spacing", default if output_spacing is None else output_spacing
    if output_spacing is not None:
        raise InvalidInputError(
            f"{where}: output_spacing = {output_spacing!r} and dt = {dt!r} both given: dt is the older "
            "name of output_spacing (the time between saved samples in s, not an integrator step); "
            "give output_spacing only"
        )
    warnings.warn(
        f"{where}(dt=...) is deprecated: dt is the older name of output_spacing (the time between saved "
        f"samples in s, not an integrator step); write output_spacing={dt!r}",
        DeprecationWarning,
        stacklevel=3,
    )
    return OLD_NAME, dt
