"""The spacing keywords of the crane's Python calls: ``output_spacing`` [s] of
:meth:`pendulab.crane.Crane.simulate` and :func:`pendulab.crane.residual_grid`, the time between saved
samples (the crane's DOP853 chooses its own steps), and ``spacing`` [s] of
:meth:`pendulab.crane.Path.pivot_samples`, the time between the returned samples, and of
:meth:`pendulab.crane.Path.knots`, the most time between two knots. ``dt`` is their
older name, still taken with a DeprecationWarning, as a crane file's ``[simulation] dt`` is still read
(docs/cranes.md)."""

from __future__ import annotations

from .._core import InvalidInputError
from .._warn import warn_user
from ..validate import show

OLD_NAME = "dt"
SAVED = "the time between saved samples in s, not an integrator step"
"""What ``output_spacing`` is, in the messages."""


def spacing(
    where: str,
    output_spacing: object,
    dt: object,
    default: float,
    new: str = "output_spacing",
    what: str = SAVED,
    old: str = OLD_NAME,
) -> tuple[str, object]:
    """(the name the spacing was given by, the spacing as given) of the call ``where`` (e.g.
    ``"Crane.simulate"``): ``output_spacing`` (the keyword ``new``, which is ``what``), else the older
    ``dt`` (by the keyword ``old``: a DeprecationWarning naming ``new``, at the first caller outside
    pendulab however many of its frames lie between: :func:`pendulab._warn.warn_user`), else
    ``default``. Both given is an ``InvalidInputError`` naming both values. ``None`` is "not given";
    the caller checks the value (:mod:`pendulab.crane._checks`), naming it by the returned name."""
    if dt is None:
        return new, default if output_spacing is None else output_spacing
    if output_spacing is not None:
        raise InvalidInputError(
            f"{where}: {new} = {show(output_spacing)} and {old} = {show(dt)} both given: {old} is the older "
            f"name of {new} ({what}); give {new} only"
        )
    text = f"{where}({old}=...) is deprecated: {old} is the older name of {new} ({what})"
    warn_user(f"{text}; write {new}={show(dt)}", DeprecationWarning)
    return old, dt
