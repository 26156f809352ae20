"""Movies of the pendulum: MP4, WebM and GIF, drawn with Pillow and encoded by ffmpeg (imageio-ffmpeg).

Users call ``Trajectory.animate``, ``ExactSolution.animate`` and ``EnsembleResult.animate`` (or
``pendulab animate`` on the command line); they build a :class:`Motion` and call :func:`render`.

- :mod:`.clock` — which simulated time each frame shows; the limits on the work
- :mod:`.motion` — what moves: states at any time (exact, or Hermite-interpolated samples)
- :mod:`.canvas` — colours, fonts, the 3-D camera, 2-D axes
- :mod:`.scene` — the states on the movie's grid and the panel interface
- :mod:`.panel_3d`, :mod:`.panels_2d`, :mod:`.panel_reduced` — the panels; :mod:`.layout` places them
- :mod:`.encode` — MP4/WebM through ffmpeg, GIF through Pillow
- :mod:`.movie` — the driver: checks, frames, progress, Ctrl-C, atomic write
"""

from .clock import MAX_FRAMES, MAX_POSITIONS, Clock
from .encode import FORMATS
from .layout import PANELS
from .motion import Motion, from_function, from_samples
from .movie import Movie, MovieSettings, frames, render

__all__ = [
    "FORMATS",
    "MAX_FRAMES",
    "MAX_POSITIONS",
    "PANELS",
    "Clock",
    "Motion",
    "Movie",
    "MovieSettings",
    "frames",
    "from_function",
    "from_samples",
    "render",
]
