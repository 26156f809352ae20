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

from ..figure import FORMATS, new_figure, require_matplotlib, save_figure
from .em_map import plot_em_map
from .phases import plot_phases
from .reduced import plot_reduced
from .trajectory import plot_trajectory

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
