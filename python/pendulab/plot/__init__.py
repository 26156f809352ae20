"""Figures (matplotlib, imported only when a figure is made; ``pip install 'pendulab[plot]'``).

- :func:`plot_em_map`: the energy–momentum map, W as colour, the conical boundary, the critical line
  J₃ = 0 with the bottom and the top, and the monodromy loop around the top with its W values.
- :func:`plot_reduced`: Holm's Figure 2 — the surface C = 0 of the orbit's J₃, the plane H = const
  and the orbit on their intersection, in (σ₁, σ₂, σ₃) space.
- :func:`plot_trajectory`: the path on the sphere in 3-D and/or seen from above (the rosette), with
  the turning heights z₁, z₂ of the exact solution as horizontal circles.
- :func:`plot_phases`: the split Δφ = Δφ_dyn + Δφ_geom (T-5.1) as bars with their values, for one
  orbit or several side by side; for one orbit also the reduced orbit in the (z, p_z) plane with
  its enclosed area A shaded (Δφ_geom = −A/J).

Each returns a ``matplotlib.figure.Figure`` (shown inline by notebooks) built without pyplot, so no
global backend is touched; files are rendered with the Agg canvas and written atomically (temporary
file + rename), in the format of the suffix (.png, .svg, .pdf). Axes carry SI units.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np

from ..io import atomic_path

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
    from .. import _core

    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in FORMATS:
        raise _core.InvalidInputError(
            f"unknown image suffix {suffix!r} in {str(path)!r}; use one of {', '.join(FORMATS)}"
        )
    # mplot3d projects NaN-padded face arrays with np.dot, which can raise spurious floating-point
    # warnings depending on the BLAS; they say nothing about the figure.
    with atomic_path(target) as tmp, np.errstate(over="ignore", invalid="ignore"):
        fig.savefig(tmp, format=suffix[1:], dpi=dpi)
    return target


from .em_map import plot_em_map  # noqa: E402
from .phases import plot_phases  # noqa: E402
from .reduced import plot_reduced  # noqa: E402
from .trajectory import plot_trajectory  # noqa: E402

__all__ = [
    "FORMATS",
    "new_figure",
    "plot_em_map",
    "plot_phases",
    "plot_reduced",
    "plot_trajectory",
    "require_matplotlib",
    "save_figure",
]
