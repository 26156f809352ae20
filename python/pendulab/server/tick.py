"""One tick of a lab session, as it runs in a worker thread (docs/web.md, "Pacing").

The WebSocket handler (:func:`pendulab.server.app.run_session`) collects the commands waiting for the
tick and hands them, with the wall-clock time elapsed, to :func:`tick_messages` in a worker thread
(``anyio.to_thread``; the core releases the GIL while it steps), then sends what it returns. So the
event loop never steps: however much work a session asks for, other sessions, the REST endpoints and
Ctrl-C are served. In one tick, within one wall-time budget (:mod:`.budget`):

1. the commands, in order (an ``error`` notice for each one refused), then the waiting steps of
   ``step`` commands; a ``status`` after them (and when a ``step`` of several ticks is done);
2. the advance to the wall clock × time scale;
3. the error estimate of those records (:mod:`.live_error`), its companion stepping in what is left
   of the budget: it never takes time from the lab's own stepping;
4. the frames (the last discontinuity's record, the ``step`` frame, the advance's records), then the
   string's ``event`` notices, and a ``status`` when ``lagging`` changed.

**No frame carries a non-finite number.** Records are checked before they are encoded: from the first
record with a NaN or ±∞ on, nothing is sent, the session pauses and an ``error`` notice names the
quantities that overflowed and the time (:func:`finite_records`). The core also refuses a state
that stops being finite (the session then pauses with "integration stopped …"); this check is the
last line, for the diagnostics computed from a finite state.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .budget import TICK_BUDGET, Budget
from .protocol import FRAME_FIELDS, CommandError, encode_records, error_notice_of, keyed_notice
from .session import Session

Message = dict[str, Any] | bytes
"""A JSON notice (dict) or a binary frame message (bytes)."""


def finite_records(session: Session, records: np.ndarray | None, out: list[Message]) -> bool:
    """Appends ``records`` (encoded) to ``out`` up to the first one holding a non-finite value; if there
    is one, pauses the session, appends an ``error`` notice naming the quantities and the time, and a
    ``status``, and returns False."""
    if records is None or len(records) == 0:
        return True
    finite = np.isfinite(records)
    good = finite.all(axis=1)
    if good.all():
        out.append(encode_records(records))
        return True
    first = int(np.argmin(good))
    if first > 0:
        out.append(encode_records(records[:first]))
    bad = [FRAME_FIELDS[i] for i in np.flatnonzero(~finite[first])]
    t = records[first, FRAME_FIELDS.index("t")]
    when = f"{t:.6g}" if np.isfinite(t) else f"≈ {session.stepper.t:.6g}"
    session.paused = True
    session.pending_steps = 0
    out.append(keyed_notice("nonfinite_motion", t=when, fields=", ".join(bad[:6])))
    out.append(session.status())
    return False


@dataclass
class Carry:
    """What a session's commands carry from tick to tick (the server keeps one per session): the
    commands not carried out yet (``left``: the budget ran out; the server puts them back at the head
    of the inbox) and the ``debt`` [s] of processor time its commands took beyond a tick's budget.
    A tick carries out at least one command, more only while the budget lasts; while in debt, it
    carries out none (stepping and frames go on) and pays off one tick's budget. So a page that
    floods ``load_scenario`` gets about its share of the room (:mod:`.room`), not a tick's worth of
    commands per tick."""

    left: list[Any] = field(default_factory=list)
    debt: float = 0.0


def first_messages(session: Session) -> list[Message]:
    """What a new connection gets first: the status and the current state's frame."""
    out: list[Message] = [session.status()]
    records = session.records()
    session.fill_errors(records, Budget())
    finite_records(session, records, out)
    return out


def tick_messages(
    session: Session,
    commands: list[Any],
    elapsed: float,
    budget_seconds: float = TICK_BUDGET,
    dropped: int = 0,
    carry: Carry | None = None,
) -> list[Message]:
    """Carries out one tick of ``session`` (the module doc): ``commands`` are parsed commands or
    :class:`CommandError` for refused messages, ``elapsed`` the wall-clock seconds since the last tick,
    ``dropped`` the messages thrown away since the last tick (throttling). Returns the messages to send,
    in order. Not thread-safe per session: one tick at a time.

    ``session.commands`` counts every message handled — applied, refused or dropped — and the status
    says it (``commands``): a page that counts what it sent knows when a status reflects all of it (the
    page's language switch reloads from the URL only then).

    With ``carry`` (the server's), the commands are carried out within the session's budget too
    (``load_scenario`` and the other commands that build a stepper cost real time): see
    :class:`Carry`."""
    budget = Budget(budget_seconds)
    out: list[Message] = []
    changed = bool(commands) or dropped > 0  # the status after them, also after refused ones
    session.commands += dropped
    records = None
    cpu = time.thread_time()
    if carry is not None and carry.debt > 0:  # paying for earlier commands: none this tick
        carry.debt = max(0.0, carry.debt - budget_seconds)
        carry.left.extend(commands)
        commands, changed = [], dropped > 0
    for i, item in enumerate(commands):
        if carry is not None and i > 0 and budget.spent():
            carry.left.extend(commands[i:])  # counted when carried out, at a later tick
            break
        session.commands += 1
        if isinstance(item, CommandError):
            out.append(error_notice_of(item))
            continue
        try:
            result = session.apply(item)
        except CommandError as e:
            out.append(error_notice_of(e))
            continue
        if result is not None:
            records = result  # only the last discontinuity matters; the status below announces it
    if carry is not None and commands:
        carry.debt += max(0.0, time.thread_time() - cpu - budget_seconds)
    was_lagging = session.lagging
    stepped = advanced = None
    try:
        stepped = session.take_pending_steps(budget)
    except CommandError as e:
        out.append(error_notice_of(e))
        changed = True
    if changed or (stepped is not None and session.pending_steps == 0):
        out.append(session.status())  # after the commands and a finished `step`: its t is the frame's
    try:
        advanced = session.advance(elapsed, budget)
    except CommandError as e:
        out.append(error_notice_of(e))
        out.append(session.status())
    how = session.error.how
    for part in (records, stepped, advanced):  # the error estimate in what is left of the budget
        session.fill_errors(part, budget)
    if session.error.how != how:
        out.append(session.status())  # the companion stopped: the status's error_estimate says why
    for part in (records, stepped, advanced):
        if not finite_records(session, part, out):
            break  # paused: nothing after the first non-finite record
    out.extend(session.take_event_notices())  # the string's leaves and snaps, after their frames
    if session.lagging != was_lagging:
        out.append(session.status())
    return out
