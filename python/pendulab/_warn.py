"""Warnings reported at the user's line: :func:`warn_user` names the first frame outside the pendulab
package, however many of pendulab's own frames (wrappers such as ``_blas.one_blas_thread``, helpers)
lie between it and the ``warn`` call, so no fixed ``stacklevel`` has to be counted by hand. Python 3.12's
``skip_file_prefixes`` does the same, but the package supports 3.11. No units.
"""

from __future__ import annotations

import os
import sys
import warnings

_PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__)) + os.sep


def _inside(filename: str) -> bool:
    return os.path.abspath(filename).startswith(_PACKAGE_DIR)


def warn_user(message: str, category: type[Warning] = UserWarning) -> None:
    """``warnings.warn(message, category)`` reported at the first calling frame outside pendulab (the
    outermost frame if every frame is pendulab's own, e.g. in the lab's server)."""
    frame = sys._getframe(1)  # the caller of warn_user: stacklevel 2
    level = 2
    while frame.f_back is not None and _inside(frame.f_code.co_filename):
        frame = frame.f_back
        level += 1
    warnings.warn(message, category, stacklevel=level)
