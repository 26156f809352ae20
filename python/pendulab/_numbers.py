"""Numbers in messages as a user writes them: the Python twin of the core's ``pendulab_core::error::Shown``
(docs/web.md, "Notices"). The shortest digits that read back as the same float (or ``digits`` significant
digits), in plain decimals for 1e-4 <= |x| < 1e6 (``-1``, ``0.5``, ``0.0001``), beyond that in whichever of
the plain and the exponent form is shorter, the exponent as one types it (``1e9``, ``123456789``, ``1e-9``,
``2.5e20``; not Python's ``1e+09``, ``1e-09``, ``1000000000.0``); ``nan``, ``inf``, ``-inf``.
"""

from __future__ import annotations

import math
from decimal import Decimal


def shown(x: float, digits: int | None = None) -> str:
    """``x`` as a user writes it (module doc); ``digits``: rounded to that many significant digits first."""
    x = float(x)
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    if digits is not None:
        x = float(f"{x:.{max(digits, 1) - 1}e}")
    d = Decimal(repr(x)).normalize()  # repr: the shortest digits that read back as x
    plain = format(d, "f")
    sign, ds, e = d.as_tuple()
    assert isinstance(e, int)  # finite
    mantissa = "".join(map(str, ds))
    mantissa = mantissa[0] + ("." + mantissa[1:] if len(mantissa) > 1 else "")
    exponent = f"{'-' if sign else ''}{mantissa}e{e + len(ds) - 1}"
    return plain if 1e-4 <= abs(x) < 1e6 or len(plain) <= len(exponent) else exponent
