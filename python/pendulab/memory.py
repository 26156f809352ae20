"""Memory checked before a large allocation (docs/limits.md, "Memory").

A call that allocates memory in proportion to its input — the exact solution at 10⁸ times
(:meth:`pendulab.ExactSolution.state`), an ensemble of 10⁷ starts (:func:`pendulab.simulate_ensemble`)
— is inside the documented size limits on a large machine and far beyond a small one. When the
allocation fails inside the Rust core, the process aborts (Rust's allocator does not raise), so the
need is estimated first and refused with :class:`pendulab.InvalidInputError` when it exceeds
:data:`USABLE_FRACTION` of what this process can still get (:func:`available_bytes`): the smallest of
the memory the operating system reports available (``MemAvailable``), the room left under the
process's address-space limit (``ulimit -v``, RLIMIT_AS) and under its cgroup's memory limit
(containers). All sizes in bytes.

Asking the operating system reads four files (about 0.5 ms), more than a short run costs, and a fit
or a sweep runs thousands. So a reading is kept for :data:`FRESH_FOR` seconds and reused for a need
below 1/:data:`SMALL_SHARE` of it, and for the cap on saved samples; a larger need, or one that would
be refused, always reads afresh.
"""

from __future__ import annotations

import os
import resource
import time
from pathlib import Path

from ._core import InvalidInputError

USABLE_FRACTION = 0.8
"""The share of the available memory one call may plan to fill."""
FRESH_FOR = 0.5
"""How long a reading of the available memory is reused [s] (module doc)."""
SMALL_SHARE = 64
"""A need below 1/SMALL_SHARE of a recent reading is checked against it without asking again."""
_recent: tuple[float, int | None] | None = None


def _meminfo(key: str) -> int | None:
    try:
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith(key + ":"):
                return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return None


def _own_status(key: str) -> int | None:
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith(key + ":"):
                return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return None


def _cgroup_room() -> int | None:
    """memory.max − memory.current of this process's cgroup (v2), or None without a limit."""
    try:
        rel = Path("/proc/self/cgroup").read_text().strip().split("\n")[0].split(":")[-1]
        base = Path("/sys/fs/cgroup") / rel.lstrip("/")
        top = (base / "memory.max").read_text().strip()
        if top == "max":
            return None
        return int(top) - int((base / "memory.current").read_text().strip())
    except (OSError, ValueError, IndexError):
        return None


def available_bytes() -> int | None:
    """The memory this process can still allocate, as well as it can be told (module doc); None when
    nothing is known (then nothing is refused)."""
    known: list[int] = []
    avail = _meminfo("MemAvailable")
    if avail is None:
        try:
            avail = os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
        except (ValueError, OSError, AttributeError):
            avail = None
    if avail is not None:
        known.append(avail)
    for limit, used in ((resource.RLIMIT_AS, "VmSize"), (resource.RLIMIT_DATA, "VmData")):
        soft = resource.getrlimit(limit)[0]
        if soft != resource.RLIM_INFINITY:
            known.append(soft - (_own_status(used) or 0))
    room = _cgroup_room()
    if room is not None:
        known.append(room)
    have = max(0, min(known)) if known else None
    global _recent
    _recent = (time.monotonic(), have)
    return have


def recent_available_bytes() -> int | None:
    """:func:`available_bytes` as read within the last :data:`FRESH_FOR` seconds, else afresh."""
    if _recent is not None and time.monotonic() - _recent[0] < FRESH_FOR:
        return _recent[1]
    return available_bytes()


def check_memory(what: str, need: float, hint: str) -> None:
    """Raises :class:`pendulab.InvalidInputError` when ``need`` bytes for ``what`` exceed
    :data:`USABLE_FRACTION` of :func:`available_bytes`; ``hint`` says how to ask for less. A need
    below 1/:data:`SMALL_SHARE` of a recent reading is passed on it (module doc)."""
    recent = recent_available_bytes()
    if recent is None or need * SMALL_SHARE <= recent:
        return
    have = available_bytes()
    if have is None or need <= USABLE_FRACTION * have:
        return
    raise InvalidInputError(
        f"{what} needs about {need / 2**30:.3g} GiB of memory, more than this process can get "
        f"({have / 2**30:.3g} GiB available; at most {USABLE_FRACTION:.0%} of it is used); {hint}"
    )


SAMPLE_BYTES = 7 * 8
"""Bytes of one saved sample of a run (t, x, v as float64; the core's ``BYTES_PER_SAMPLE``)."""
SAMPLE_COPIES = 3
"""Copies of a run's samples alive at the peak: the chunks taken from the core, their concatenation,
and the core's own buffer growing by doubling."""
DEFAULT_SAVED_BYTES = 4 * 2**30
"""The core's default cap on the memory of saved samples [bytes] (``max_saved_bytes``)."""


def saved_bytes_cap(given: int | None) -> int | None:
    """The cap on a run's saved samples [bytes] to hand to the core: ``given`` (``max_saved_bytes``)
    when the caller set one, else the smaller of the core's default (4 GiB) and what this process can
    still get (:data:`USABLE_FRACTION` of :func:`available_bytes`, over :data:`SAMPLE_COPIES`), so
    that a run keeping more samples than fit (an adaptive run with ``save_every=1`` over a long time,
    10⁷ ``save_at`` times under a memory limit) is refused by the core with its error naming the
    limit instead of aborting the process when an allocation fails. None: the core's default."""
    if given is not None:
        return given
    have = recent_available_bytes()
    if have is None:
        return None
    return max(SAMPLE_BYTES, min(DEFAULT_SAVED_BYTES, int(USABLE_FRACTION * have / SAMPLE_COPIES)))
