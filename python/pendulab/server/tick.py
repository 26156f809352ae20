"""One tick of a lab session, as the room's ticker runs it in a worker thread (docs/web.md, "Pacing").

The tick itself is the core's (``LiveSession.tick``, ``crates/pendulab-core/src/live/session.rs``; the
interpreter lock is released while it steps), so the event loop never steps: however much work a
session asks for, other sessions, the REST endpoints and Ctrl-C are served. In one tick, within one
wall-time budget [s]:

1. the commands, in order (an ``error`` notice for each one refused), then the waiting steps of
   ``step`` commands; a ``status`` after them (and when a ``step`` of several ticks is done);
2. the advance to the wall clock × time scale;
3. the error estimate of those records, its companion stepping in what is left of the budget: it
   never takes time from the lab's own stepping;
4. the frames (the last discontinuity's record, the ``step`` frame, the advance's records), then the
   string's ``event`` notices, and a ``status`` when ``lagging`` changed.

**No frame carries a non-finite number.** From the first record with a NaN or ±∞ on, nothing is
sent, the session pauses and an ``error`` notice names the quantities that overflowed and the time.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from .session import TICK_BUDGET, Message, Session

__all__ = ["Carry", "Message", "first_messages", "tick_messages"]


@dataclass
class Carry:
    """What a session's commands carry from tick to tick (the server keeps one per session): the
    commands not carried out yet (``left``: the budget ran out; the server puts them back at the head
    of the inbox) and the ``debt`` [s] of wall time its commands took beyond a tick's budget.
    A tick carries out at least one command, more only while the budget lasts; while in debt, it
    carries out none (stepping and frames go on) and pays off one tick's budget. So a page that
    floods ``load_scenario`` gets about its share of the room (:mod:`.room`), not a tick's worth of
    commands per tick."""

    left: list[Any] = field(default_factory=list)
    debt: float = 0.0


def first_messages(session: Session) -> list[Message]:
    """What a new connection gets first: the status and the current state's frame."""
    return session.first_messages()


def tick_messages(
    session: Session,
    commands: list[Any],
    elapsed: float,
    budget_seconds: float = TICK_BUDGET,
    dropped: int = 0,
    carry: Carry | None = None,
) -> list[Message]:
    """Carries out one tick of ``session`` (the module doc): ``commands`` are parsed commands or
    :class:`~.protocol.CommandError` for refused messages, ``elapsed`` the wall-clock seconds since the
    last tick, ``dropped`` the messages thrown away since the last tick (throttling). Returns the
    messages to send, in order. Not thread-safe per session: one tick at a time.

    ``session.commands`` counts every message handled — applied, refused or dropped — and the status
    says it (``commands``): a page that counts what it sent knows when a status reflects all of it (the
    page's language switch reloads from the URL only then).

    With ``carry`` (the server's), the commands are carried out within the session's budget too
    (``load_scenario`` and the other commands that build a stepper cost real time): see
    :class:`Carry`."""
    out, left, debt = session.tick(
        commands, elapsed, budget_seconds, dropped, None if carry is None else carry.debt
    )
    if carry is not None:
        carry.debt = float(debt or 0.0)
        carry.left.extend(left)  # counted when carried out, at a later tick
    return out
