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

__all__ = ["tqdm"]
