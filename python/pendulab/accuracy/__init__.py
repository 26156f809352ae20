"""Honest accuracy (above ``trajectory``, below ``simulate``): ``estimate`` computes a finished run's
global error at every sample (Richardson for fixed-step methods, a tighter companion run for DOP853,
the exact solution for the ideal pendulum), ``target`` chooses a method and its step or tolerance for
``simulate(..., accuracy=...)``. The record itself is :class:`pendulab.error_estimate.ErrorEstimate`.
"""

from ..error_estimate import ErrorEstimate
from .estimate import estimate, true_error
from .target import run_to_accuracy

__all__ = ["ErrorEstimate", "estimate", "run_to_accuracy", "true_error"]
