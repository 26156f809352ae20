"""Figure helpers shared by every plot: matplotlib imported on demand, a Figure with an Agg canvas (no
pyplot, no global backend), and atomic saving in the format of the suffix (.png, .svg, .pdf)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np

from ._core import InvalidInputError
from .io import atomic_path

FORMATS = (".png", ".svg", ".pdf")


def require_matplotlib() -> Any:
    """Imports matplotlib or raises an ImportError saying how to install it."""
    try:
        import matplotlib
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError(
            "plotting needs matplotlib (>= 3.8): pip install 'pendulab[plot]' or pip install matplotlib"
        ) from e
    return matplotlib


def new_figure(**kwargs: Any) -> Any:
    """A Figure with an Agg canvas (no pyplot, no global backend)."""
    require_matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(**kwargs)
    FigureCanvasAgg(fig)
    return fig


def save_figure(fig: Any, path: str | os.PathLike[str], dpi: int = 150) -> Path:
    """Renders ``fig`` to ``path`` atomically; the format comes from the suffix (.png, .svg, .pdf)."""
    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in FORMATS:
        raise InvalidInputError(
            f"unknown image suffix {suffix!r} in {str(path)!r}; use one of {', '.join(FORMATS)}"
        )
    # mplot3d projects NaN-padded face arrays with np.dot, which can raise spurious floating-point
    # warnings depending on the BLAS; they say nothing about the figure.
    with atomic_path(target) as tmp, np.errstate(over="ignore", invalid="ignore"):
        fig.savefig(tmp, format=suffix[1:], dpi=dpi)
    return target
