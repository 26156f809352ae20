"""Incremental integration for live viewing (:class:`Stepper`): ``step(n)``, ``step_to(t)``,
``set_state``, with the settings of :func:`pendulab.simulate` (time in s, x in m, v in m/s)."""

from __future__ import annotations

import numpy as np

from ._core import InvalidInputError, RunOptions
from ._core import Stepper as _Stepper
from .display import Row, html_table
from .display import number as shown
from .integrators import (
    _U64,
    DEFAULTS,
    _check_conserve,
    _method_table,
    check_arithmetic,
    check_settings,
    check_steps_on_samples,
)
from .model import Pendulum, State, check_pendulum_state
from .validate import LIMITS, flag, integer, invalid, number, planned_steps


class Stepper:
    """Incremental integration for live viewing: ``step(n)``, ``step_to(t)``, ``state``, ``t``.

    Same methods and options as :func:`simulate`; ``set_state`` replaces the state (e.g. after the
    user drags the bob).

    Parameters
    ----------
    pendulum : the :class:`Pendulum` (model and parameters, SI units; no user ``force`` callable).
    state : the start, a :class:`State` on TS² of this pendulum.
    method : a name from :func:`methods` (default ``"rattle"``).
    dt : step size [s] of a fixed-step method (default None: 1e-3 s); for the adaptive ``dop853`` its
        first step (default None: chosen automatically, as :func:`simulate` does; never 0). A given dt
        is a finite number in [1e-12, 1e6] s.
    rtol, atol : tolerances of ``dop853`` (atol in m and m/s).
    project : ``dop853`` only: project onto TS² after every step (default True).
    t0 : the start time [s] of ``state`` (default 0.0).
    conserve : ``dop853`` only: also hold E and J₃ at their initial values (as in :func:`simulate`).
    arithmetic : the RATTLE family's multiply-adds, ``"auto"``, ``"fused"`` or ``"unfused"`` (as in
        :func:`simulate`).
    steps_on_samples : a sampled pivot's fixed steps: ``dt`` [s] is the longest step and the steps land
        on every sample, each interval between samples in ⌈span/dt⌉ equal steps (default False; steps
        of dt, one that holds a sample split there). As in :func:`simulate`, whose run it reproduces
        bit for bit (``step_to`` each save time, or ``step(n)`` for ``save_every=n``); after
        ``set_state`` the steps go on landing on the samples. No effect on ``dop853``; True without
        pivot samples is an ``InvalidInputError`` (docs/integrators.md, "Sampled pivot").
    halved_steps : every fixed step (each sub-step between a sampled pivot's samples, each step
        shortened onto a ``step_to`` time) taken as two equal halves (default False; whole steps): the
        run of the error estimate's dt/2 companion on a sampled pivot, as :func:`simulate` runs it
        (``RunOptions(halved_steps=True)``). ``stats["steps"]`` counts the halves. No effect on
        ``dop853`` (docs/integrators.md, "Error estimates and asking for accuracy").

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> p = pl.Pendulum()
    >>> st = pl.Stepper(p, p.state_from_angles(theta=0.5), method='rattle', dt=1e-3)
    >>> st.step(1000)
    State(x=[-0.478686, 0, -0.877986] m, v=[-0.0781417, 0, 0.0426035] m/s; θ=28.5996°, φ=180°)
    >>> round(st.t, 12)
    1.0
    """

    def __init__(
        self,
        pendulum: Pendulum,
        state: State,
        *,
        method: str = "rattle",
        dt: float | None = None,
        rtol: float = 1e-10,
        atol: float = 1e-12,
        project: bool = True,
        t0: float = 0.0,
        conserve: bool = False,
        arithmetic: str = "auto",
        steps_on_samples: bool = False,
        halved_steps: bool = False,
    ) -> None:
        check_pendulum_state(pendulum, state)
        method, dt_checked, rtol, atol, project, conserve, t0 = check_settings(
            method=method, dt=dt, rtol=rtol, atol=atol, project=project, conserve=conserve, t0=t0
        )
        self._adaptive = bool(_method_table()[method]["adaptive"])
        if dt_checked is None:  # as pl.simulate: dop853 chooses its first step (0 to the core), else 1 ms
            dt_checked = 0.0 if self._adaptive else float(DEFAULTS["dt"])
        dt = dt_checked
        _check_conserve(pendulum, conserve)
        arithmetic = check_arithmetic(arithmetic, method, pendulum.model)
        steps_on_samples = check_steps_on_samples(steps_on_samples, pendulum)
        halved_steps = flag("halved_steps", halved_steps)
        if pendulum.force is not None:
            raise InvalidInputError(
                "the incremental Stepper does not take a user force callable; use pendulab.simulate"
            )
        self._dt = dt
        self._method = method
        self._on_samples = steps_on_samples and not self._adaptive  # dt then the longest step
        self.pendulum = pendulum
        run = RunOptions(
            t0=float(t0),
            method=method,
            dt=float(dt),
            rtol=float(rtol),
            atol=float(atol),
            project=bool(project),
            conserve=bool(conserve),
            arithmetic=arithmetic,
            steps_on_samples=steps_on_samples,
            halved_steps=halved_steps,
        )
        self._core = _Stepper(pendulum.spec, state.pair, run)

    def __repr__(self) -> str:
        theta, phi = self.state.angles_deg()
        step = f"dt={shown(self._dt)} s" + (" at most, on the samples" if self._on_samples else "")
        if self._adaptive:  # its own steps; the first one given, or chosen automatically (dt 0)
            step = f"adaptive, first step {shown(self._dt)} s" if self._dt > 0 else "adaptive"
        return (
            f"Stepper({self._method}, {step}, t={shown(self.t)} s, θ={shown(theta)}°, "
            f"φ={shown(phi)}°, steps={self._core.stats['steps']}; {self.pendulum!r})"
        )

    def _repr_html_(self) -> str:
        theta, phi = self.state.angles_deg()
        stats = self.stats
        rows: list[Row] = [
            ("method", self._method, ""),
            self._step_row(),
            ("time t", self.t, "s"),
            ("polar angle θ", theta, "°"),
            ("azimuth φ", phi, "°"),
            ("steps taken (rejected)", f"{stats['steps']} ({stats.get('rejected', 0)})", ""),
            ("model", self.pendulum.model, ""),
            ("length l", self.pendulum.length, "m"),
        ]
        return html_table("Stepper", rows)

    def _step_row(self) -> Row:
        """The step of the HTML table: dt [s], or for dop853 "adaptive" and its first step if given."""
        if not self._adaptive:
            return ("longest step dt, on the samples" if self._on_samples else "step dt", self._dt, "s")
        if self._dt > 0:
            return ("adaptive, first step", self._dt, "s")
        return ("step dt", "adaptive (first step automatic)", "")

    @property
    def t(self) -> float:
        """Current time [s]."""
        return self._core.t

    @property
    def state(self) -> State:
        """Current state."""
        return State(self._core.x, self._core.v)

    @property
    def stats(self) -> dict[str, int]:
        """Work counters: steps, rejected, rhs_evals."""
        return dict(self._core.stats)

    def step(self, n: int = 1) -> State:
        """Takes n steps and returns the new state."""
        n = integer(
            "n", n, 0, int(LIMITS["steps"]["max"]), f"an integer in [0, {LIMITS['steps']['max']:.0e}]"
        )
        self._core.step(n)
        return self.state

    def step_to(self, t: float, *, max_steps: int | None = None) -> State:
        """Advances to exactly time t [s] and returns the state there. With ``max_steps``, takes at most
        that many steps (``dop853``: accepted steps) and may stop before t (then ``self.t < t``; call
        again to go on — the same steps as one uncapped call): a bound on the work of one call.
        Without it, a fixed-step advance of more than 1e10 steps is refused (docs/limits.md)."""
        t = number("t", t, "time")
        if max_steps is not None:
            max_steps = integer("max_steps", max_steps, 0, _U64)
        elif not self._adaptive:
            planned_steps(self.t, t, self._dt, name="t")
        self._core.step_to(t, max_steps)
        return self.state

    def set_state(self, state: State) -> None:
        """Replaces the current state (must lie on TS²)."""
        if not isinstance(state, State):
            raise invalid("state", state, "a pendulab.State")
        self._core.set_state(np.ascontiguousarray(state.x), np.ascontiguousarray(state.v))
