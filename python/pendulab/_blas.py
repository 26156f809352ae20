"""One BLAS thread for the work of a fit (``pendulab.fit`` and what calls it).

A fit's linear algebra is small — Jacobians of N samples × k ≤ 20 unknowns, their SVD and
least-squares steps — and runs between model runs on one core. OpenBLAS (NumPy's and SciPy's) starts
a thread per core for each call even so; on a machine whose cores are busy (a classroom server, a
sweep of fits, any shared machine) those threads wait to be scheduled and spin while they wait:
`bench/fit_jacobian.py`'s 14 000-sample fit took 7.1 s of CPU with NumPy's default threads and
4.2–4.7 s with one, at load 10 on 2 cores, and each 20-lag autocorrelation took 0.3 s instead of
0.2 ms (docs/fit.md, "Speed"). :func:`one_blas_thread` limits BLAS to one thread for the duration of
a call with threadpoolctl (the ``io`` extra), and does nothing when threadpoolctl is not installed.
No units.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import ParamSpec, TypeVar

P = ParamSpec("P")
R = TypeVar("R")


@contextmanager
def blas_threads(limit: int = 1) -> Iterator[None]:
    """BLAS limited to ``limit`` threads inside the ``with`` block (threadpoolctl), then restored."""
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # pragma: no cover - threadpoolctl is in the io, tour and dev extras
        yield
        return
    with threadpool_limits(limits=limit, user_api="blas"):
        yield


def one_blas_thread(fn: Callable[P, R]) -> Callable[P, R]:
    """``fn`` run with one BLAS thread (:func:`blas_threads`); its signature and doc are kept."""

    @functools.wraps(fn)
    def wrapper(*args: P.args, **kwargs: P.kwargs) -> R:
        with blas_threads(1):
            return fn(*args, **kwargs)

    return wrapper
