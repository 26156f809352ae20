"""Which model do the data need? Fits of the same data with different unknowns (e.g. the dissipation
laws: viscous ``damping``, quadratic ``drag``, dry ``friction``) ranked by the Bayesian information
criterion BIC = −2 ln L + k ln n (Schwarz 1978), with Akaike's AIC = −2 ln L + 2k beside it (docs/fit.md,
"Which dissipation law"). A difference of more than 10 in BIC is very strong evidence for the smaller
value (Kass & Raftery 1995); a law whose addition lowers BIC by less than 2 is not needed.
Units: the criteria are dimensionless.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .._core import InvalidInputError
from ..display import Row, html_table
from .result import FitResult

#: BIC differences: below this a model is not distinguished from the best; above 10 it is ruled out.
NOT_DISTINGUISHED = 2.0
RULED_OUT = 10.0


@dataclass
class Comparison:
    """Fits ranked by BIC (best first): each fit's unknowns, k, AIC, BIC and ΔBIC to the best."""

    fits: list[FitResult]
    delta_bic: list[float]

    def table(self) -> str:
        """A plain-text table, best first, with a verdict per row."""
        lines = [f"{'unknowns':<52} {'k':>3} {'AIC':>12} {'BIC':>12} {'dBIC':>8}  verdict"]
        for res, d in zip(self.fits, self.delta_bic, strict=True):
            verdict = (
                "best"
                if d == 0.0
                else "as good (not distinguished)"
                if d < NOT_DISTINGUISHED
                else "ruled out"
                if d > RULED_OUT
                else "worse"
            )
            names = ", ".join(n for n in res.names if not n.endswith("0"))
            lines.append(
                f"{names:<52} {len(res.names):>3} {res.aic:>12.6g} {res.bic:>12.6g} {d:>8.3g}  {verdict}"
            )
        return "\n".join(lines)

    @property
    def best(self) -> FitResult:
        """The fit with the smallest BIC."""
        return self.fits[0]

    def __repr__(self) -> str:
        best = ", ".join(n for n in self.best.names if not n.endswith("0"))
        runner = f", next dBIC={self.delta_bic[1]:.3g}" if len(self.delta_bic) > 1 else ""
        return f"Comparison({len(self.fits)} fits, best: {best}{runner})"

    def _repr_html_(self) -> str:
        rows: list[Row] = []
        for res, d in zip(self.fits, self.delta_bic, strict=True):
            names = ", ".join(n for n in res.names if not n.endswith("0"))
            rows.append((names, f"BIC {res.bic:.6g}, AIC {res.aic:.6g}", f"ΔBIC {d:.3g}"))
        return html_table("Fits ranked by BIC", rows, note="ranked.table(), ranked.best")


def compare_fits(results: Sequence[FitResult]) -> Comparison:
    """Ranks fits of the SAME data (same times and kinds, σ given alike) by BIC; raises
    :class:`pendulab.InvalidInputError` for fewer than two fits or fits of different data."""
    fits = list(results)
    if len(fits) < 2 or not all(isinstance(r, FitResult) for r in fits):
        raise InvalidInputError("compare_fits needs two or more FitResult objects of the same data")
    first = fits[0]
    for r in fits[1:]:
        same = (
            len(r.t) == len(first.t)
            and np.array_equal(r.t, first.t)
            and list(r.residuals) == list(first.residuals)
            and r.sigma_estimated == first.sigma_estimated
        )
        if not same:
            raise InvalidInputError(
                "compare_fits compares fits of the same data only (same times, data kinds and sigma)"
            )
    fits.sort(key=lambda r: r.bic)
    best = fits[0].bic
    return Comparison(fits, [r.bic - best for r in fits])
