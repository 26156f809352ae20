"""The ``[simulation]`` table of a scenario file: the time span t0 … t_end [s], the integrator
(``pendulab methods``), its step dt [s] (fixed-step methods; the first step of adaptive ones) or
tolerances rtol [1] and atol [m, m/s] (adaptive ones), and what to save: every n-th step
(``save_every``) or the states at given times ``save_at`` [s]. The validators refuse an unknown
method (with the closest name), t_end ≤ t0, more than the allowed number of steps, both save_every and
save_at, and save_at times out of order or outside [t0, t_end]; the resolved step and tolerances are
what the core receives.
"""

from __future__ import annotations

from pydantic import Field, field_validator, model_validator

from ..integrators import DEFAULTS, _method_table, method_names, unknown_method
from ..validate import LIMITS, MAX_SAMPLES, MAX_STEPS
from .table_base import _lim, _Section, _Time

_U64_LIMIT = 2**63  # save_every must fit the core's unsigned 64-bit counter


class SimulationSection(_Section):
    """``[simulation]``: time span, integrator, step size or tolerances, and what to save."""

    t_end: float = Field(description="end time in s, a number > t0 in [-1e12, 1e12]", **_lim("time"))
    t0: float = Field(
        0.0, description="start time in s, a number in [-1e12, 1e12] (default 0)", **_lim("time")
    )
    method: str = Field(
        str(DEFAULTS["method"]), description="an integrator name (see `pendulab methods`), default 'rattle'"
    )
    dt: float | None = Field(
        None,
        description="step size in s, a number in [1e-12, 1e6] (default 1e-3 s; adaptive methods: the first "
        "step); (t_end - t0)/dt at most 1e10 steps",
        **_lim("dt"),
    )
    rtol: float | None = Field(
        None,
        ge=1e-15,
        le=1,
        description="relative tolerance of adaptive methods, a number in [1e-15, 1] (default 1e-10)",
    )
    atol: float | None = Field(
        None,
        ge=0,
        description="absolute tolerance of adaptive methods in m and m/s, finite and >= 0 (default 1e-12)",
    )
    save_every: int | None = Field(
        None,
        ge=1,
        lt=_U64_LIMIT,
        description="an integer >= 1: keep every n-th step plus the first and last state (default 1)",
    )
    save_at: list[_Time] | None = Field(
        None,
        min_length=1,
        max_length=MAX_SAMPLES,
        description="a non-empty array of strictly increasing times in s within [t0, t_end]",
    )

    @field_validator("method")
    @classmethod
    def _known_method(cls, name: str) -> str:
        if name not in method_names():
            raise ValueError(unknown_method(name))
        return name

    @model_validator(mode="after")
    def _consistent(self) -> SimulationSection:
        if not self.t_end > self.t0:
            raise ValueError(f"t_end = {self.t_end!r} s must be after t0 = {self.t0!r} s")
        if not self.is_adaptive() and not (self.t_end - self.t0) / self.resolved_dt() <= MAX_STEPS:
            raise ValueError(
                f"(t_end - t0)/dt = {(self.t_end - self.t0) / self.resolved_dt():.3g} steps "
                f"(t_end = {self.t_end!r} s, t0 = {self.t0!r} s, dt = {self.resolved_dt()!r} s); "
                f"{LIMITS['steps']['allowed']}"
            )
        if self.save_every is not None and self.save_at is not None:
            raise ValueError(
                f"give either save_every (= {self.save_every!r}) or save_at (= {self.save_at!r}), not both"
            )
        if self.save_at is not None:
            for a, b in zip(self.save_at, self.save_at[1:], strict=False):
                if not b > a:
                    raise ValueError(
                        f"save_at times must be strictly increasing, but {a!r} s is followed by {b!r} s"
                    )
            outside = [t for t in self.save_at if not self.t0 <= t <= self.t_end]
            if outside:
                raise ValueError(
                    f"save_at time {outside[0]!r} s is outside [t0, t_end] = [{self.t0!r}, {self.t_end!r}] s"
                )
        return self

    def is_adaptive(self) -> bool:
        """True when the method chooses its own steps (dop853)."""
        return bool(_method_table()[self.method]["adaptive"])

    def resolved_dt(self) -> float:
        """The step size handed to the core [s]: ``dt``, else 1e-3 s (0 = automatic for adaptive methods)."""
        if self.dt is not None:
            return self.dt
        return 0.0 if self.is_adaptive() else float(DEFAULTS["dt"])

    def resolved_tolerances(self) -> tuple[float, float]:
        """(rtol, atol) handed to the core: the given values, else the defaults 1e-10 and 1e-12."""
        rtol = self.rtol if self.rtol is not None else float(DEFAULTS["rtol"])
        atol = self.atol if self.atol is not None else float(DEFAULTS["atol"])
        return rtol, atol
