"""The one progress bar every long run uses: tqdm's notebook widget where Jupyter's ipywidgets are
installed, its text bar everywhere else (``tqdm.auto`` alone warns "IProgress not found" in a notebook
without ipywidgets, on every run)."""

from __future__ import annotations

import importlib.util
from typing import Any

from tqdm.std import tqdm as _text_bar

tqdm: type[_text_bar[Any]]
if importlib.util.find_spec("ipywidgets") is not None:  # pragma: no cover - depends on the environment
    from tqdm.auto import tqdm
else:
    tqdm = _text_bar


def seconds_bar(seconds: float, desc: str) -> _text_bar[Any]:
    """A bar counting ``seconds`` [s] of simulated time: n and total in s (3 digits, SI prefixes), the
    rate in simulated s per s of wall time."""
    return tqdm(total=seconds, unit="s", unit_scale=True, desc=desc, leave=False)


__all__ = ["seconds_bar", "tqdm"]
