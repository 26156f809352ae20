"""Identifying a real pendulum from measurements: ``pl.fit`` and its ``FitResult`` (docs/fit.md).
``data`` the data kinds and their predictions, ``problem`` the unknowns and the forward model,
``start`` starting values from the data, ``identify`` what the data determine, ``estimator`` the
least-squares fit (its steps: ``multistart`` the search from several starts, ``inference`` the
statistics at the optimum), ``result`` the result (``report`` its text and figure). SI units
throughout."""

from .compare import Comparison, compare_fits
from .data import KINDS
from .estimator import fit
from .result import FitResult

__all__ = ["KINDS", "Comparison", "FitResult", "compare_fits", "fit"]
