"""The one validation layer: the table of limits and the checks every public entry point calls.

The table comes from the core's table of limits (``crates/pendulab-core/src/limits.rs``): the
shared model parameters length l [m], mass m [kg], gravity g [m/s²] and the bounds of everything else
a run is made of (:func:`limits`): positions [m], velocities [m/s], angles [rad], angle rates
[rad/s], times [s], step sizes [s], the planned number of steps (t_end − t₀)/dt, saved samples, bytes
of saved samples, and the size [B] and nesting of scenario and sweep files. Each model's own
parameters (:func:`pendulab.models`) come from the model registry
(``crates/pendulab-core/src/model/registry.rs``, which re-exports the shared table). The bounds are
chosen so that every derived quantity (energy m(½|v|² + g z) [J], tension m(|v|² + x·f)/l [N], J₃
[kg m²/s]) is finite and every amount of work and memory is bounded before it starts;
``docs/limits.md`` gives the reason for each.

Every check raises :class:`pendulab.InvalidInputError` (a ``ValueError``) as
``invalid <name> = <value>: <allowed>`` with the value abbreviated to at most 80 characters.

The modules: :mod:`~pendulab.validate.table` (the limits, the error), :mod:`~pendulab.validate.checks`
(numbers, arrays, steps, results), :mod:`~pendulab.validate.toml_files` (scenario and sweep files
read within limits). This package only re-exports them: ``pendulab.validate.array`` etc.
"""

from .checks import (
    FloatArray,
    array,
    choice,
    did_you_mean,
    finite,
    flag,
    integer,
    nearest,
    number,
    planned_steps,
    planned_work,
    require_finite_result,
)
from .table import (
    COMMON,
    FILE_BYTES,
    FILE_NESTING,
    LIMITS,
    LONGEST,
    LONGEST_TEXT,
    MAX_SAMPLES,
    MAX_STEPS,
    SHORTEST,
    SHORTEST_TEXT,
    SHOW_CHARS,
    abbreviate,
    invalid,
    limits,
    model_params_of,
    model_table,
    param_spec,
    show,
    spec,
)
from .toml_files import (
    check_depth,
    check_nesting,
    parse_toml,
    read_file_capped,
)

__all__ = [
    "COMMON",
    "FILE_BYTES",
    "FILE_NESTING",
    "LIMITS",
    "LONGEST",
    "LONGEST_TEXT",
    "MAX_SAMPLES",
    "MAX_STEPS",
    "SHORTEST",
    "SHORTEST_TEXT",
    "SHOW_CHARS",
    "FloatArray",
    "abbreviate",
    "array",
    "check_depth",
    "check_nesting",
    "choice",
    "did_you_mean",
    "finite",
    "flag",
    "integer",
    "invalid",
    "limits",
    "model_params_of",
    "model_table",
    "nearest",
    "number",
    "param_spec",
    "parse_toml",
    "planned_steps",
    "planned_work",
    "read_file_capped",
    "require_finite_result",
    "show",
    "spec",
]
