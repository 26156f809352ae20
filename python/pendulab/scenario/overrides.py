"""Run overrides: the settings of a scenario's ``[simulation]`` replaced for one run, named once for
:meth:`Scenario.with_overrides`, :meth:`Scenario.run` and ``pendulab run`` (its ``--method``,
``--dt``, ``--t-end``, ``--save-every``, ``--rtol``, ``--atol``). SI units: dt, t_end [s]; rtol
relative, atol [m and m/s]. A field left None keeps the file's value; the result is validated like
a file (docs/scenarios.md)."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class RunOverrides:
    """``method`` (a name of ``pendulab.methods()``), ``dt`` [s], ``t_end`` [s], ``save_every``
    (replaces a ``save_at`` list of the file), ``rtol``, ``atol`` [m and m/s]; None keeps the file's."""

    method: str | None = None
    dt: float | None = None
    t_end: float | None = None
    save_every: int | None = None
    rtol: float | None = None
    atol: float | None = None

    def given(self) -> dict[str, Any]:
        """The fields that replace the file's values, in field order."""
        return {
            f.name: getattr(self, f.name)
            for f in dataclasses.fields(self)
            if getattr(self, f.name) is not None
        }


def run_overrides(overrides: RunOverrides | None, fields: dict[str, Any]) -> RunOverrides:
    """``overrides`` (default: none) with the keywords ``fields`` put in; a keyword that is not a
    setting of ``[simulation]`` one may override is a TypeError naming the ones there are."""
    names = {f.name for f in dataclasses.fields(RunOverrides)}
    unknown = sorted(set(fields) - names)
    if unknown:
        raise TypeError(f"unknown run override(s) {unknown}; the overrides are {sorted(names)}")
    if overrides is not None and not isinstance(overrides, RunOverrides):
        raise TypeError(f"overrides = {overrides!r} must be a pendulab.scenario.RunOverrides")
    return dataclasses.replace(overrides or RunOverrides(), **fields)
