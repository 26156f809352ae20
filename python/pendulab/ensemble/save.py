"""What an ensemble run keeps: ``pl.Save.final() | pl.Save.every(1000) | pl.Save.summary()``.

Memory is bounded by what is saved, never by trajectories × steps:

* :meth:`Save.final` — the start and the final state of each trajectory (always kept);
* :meth:`Save.every` — also every n-th step: (N, steps // n + 2, 3) arrays of x [m] and v [m/s];
* :meth:`Save.summary` — per-trajectory extremes tracked at every step: z_min, z_max [m], E/m and
  J₃/m ranges, energy and J₃ drift, max sway [rad] (``EnsembleResult.summary``).

Parts combine with ``|``; two different ``every`` intervals are an error.
"""

from __future__ import annotations

from dataclasses import dataclass

from .._core import InvalidInputError


@dataclass(frozen=True)
class Save:
    """A saving rule for :func:`pendulab.simulate_ensemble` (build it with the class methods)."""

    every_n: int | None = None
    """Keep every n-th step (None: the start and the final state only)."""
    with_summary: bool = False
    """Track the per-trajectory summary."""

    @classmethod
    def final(cls) -> Save:
        """The start and the final state only (what every rule keeps)."""
        return cls()

    @classmethod
    def every(cls, n: int) -> Save:
        """Also every ``n``-th step (n ≥ 1, an integer)."""
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise InvalidInputError(f"Save.every({n!r}): n must be an integer >= 1 (steps)")
        return cls(every_n=n)

    @classmethod
    def summary(cls) -> Save:
        """Per-trajectory extremes and drifts, tracked at every step."""
        return cls(with_summary=True)

    def __or__(self, other: Save) -> Save:
        if not isinstance(other, Save):
            return NotImplemented
        a, b = self.every_n, other.every_n
        if a is not None and b is not None and a != b:
            raise InvalidInputError(f"Save.every({a}) | Save.every({b}): give one interval")
        return Save(a if a is not None else b, self.with_summary or other.with_summary)

    def __repr__(self) -> str:
        parts = ["Save.final()"]
        if self.every_n is not None:
            parts.append(f"Save.every({self.every_n})")
        if self.with_summary:
            parts.append("Save.summary()")
        return " | ".join(parts)
