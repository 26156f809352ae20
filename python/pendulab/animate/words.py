"""Words for movie titles: an integrator's or model's code name (``"rattle"``, ``"damped"``) as a person
reads it (``"RATTLE (symplectic, order 2)"``, ``"damped pendulum"``), from the integrator registry
(:func:`pendulab.methods`: order, symplectic) and a short table of model names. No units involved."""

from __future__ import annotations

from ..integrators import _method_table

_METHOD_NAMES = {
    "rattle": "RATTLE",
    "rattle4": "RATTLE, 4th-order composition",
    "rattle6": "RATTLE, 6th-order composition",
    "rattle8": "RATTLE, 8th-order composition",
    "dop853": "Dormand–Prince 8(5,3), adaptive",
    "rkmk4": "Runge–Kutta–Munthe-Kaas on the sphere",
    "rk4": "classic Runge–Kutta 4, Cartesian",
    "rk4_angles": "classic Runge–Kutta 4 in angles",
    "exact": "exact solution",
    "stormer_verlet": "Störmer–Verlet (symplectic, order 2)",
    "triple_jump": "Störmer–Verlet, triple jump (symplectic, order 4)",
}

_MODEL_NAMES = {
    "ideal": "ideal pendulum",
    "damped": "damped pendulum",
    "rotating": "pendulum on the turning Earth",
    "slewing": "slewing crane",
    "vibrating": "vibrating pivot",
    "sampled_pivot": "moving pivot",
    "string": "pendulum on a string",
    "spring": "swinging spring",
}


def method_words(name: str) -> str:
    """``"rattle"`` → ``"RATTLE (symplectic, order 2)"``; an unknown name is returned as it is.

    Examples
    --------
    >>> method_words("rattle")
    'RATTLE (symplectic, order 2)'
    >>> method_words("dop853")
    'Dormand–Prince 8(5,3), adaptive (order 8)'
    """
    info = _method_table().get(name)
    if info is None:
        return _METHOD_NAMES.get(name, name)
    kind = "symplectic, " if info["symplectic"] else ""
    return f"{_METHOD_NAMES.get(name, name)} ({kind}order {info['order']})"


def model_words(model: str) -> str:
    """``"damped"`` → ``"damped pendulum"``; an unknown name is returned as it is."""
    return _MODEL_NAMES.get(model, model)
