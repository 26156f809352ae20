"""``Crane.simulate`` and ``crane.residual_grid`` take the time between saved samples as
``output_spacing`` [s] (it was ``dt``, read as the integrator's step: the crane's DOP853 chooses its own
steps), as a crane file's ``[simulation] output_spacing``, and ``GridResult`` says it as
``output_spacing`` (``sample_spacing`` deprecated); ``Path.pivot_samples`` and ``Path.knots`` take
``spacing``. ``dt=`` is still taken: the same run bit for bit, with a DeprecationWarning naming the new
name at the caller's line; both given is refused naming both values; a bad spacing is named as
written. docs/cranes.md "The crane model"."""

from __future__ import annotations

import warnings
from typing import Any

import numpy as np
import pytest

from pendulab import InvalidInputError, crane

DEPRECATED = (
    r"\(dt=\.\.\.\) is deprecated: dt is the older name of output_spacing .*; write output_spacing=0\.1"
)


def _crane() -> crane.Crane:
    path = crane.move(distance=1.0, v_max=0.5, a_max=0.5, t_start=0.2)
    return crane.Crane(rope=6.0, pivot=path, payload_mass=500.0, hook_mass=50.0, rigging=1.5)


def _same_run(a: crane.CraneRun, b: crane.CraneRun) -> None:
    for name in ("t", "payload", "hook", "pivot", "payload_velocity", "hook_velocity", "sway", "tension"):
        x, y = getattr(a, name), getattr(b, name)
        assert x.shape == y.shape and x.tobytes() == y.tobytes(), name
    assert a.energy.tobytes() == b.energy.tobytes() and a.steps == b.steps
    assert all(a.work[k].tobytes() == b.work[k].tobytes() for k in a.work)


def _new_keyword_only() -> Any:
    return warnings.catch_warnings(action="error")


def test_simulate_takes_output_spacing_and_dt_gives_the_same_run_bit_for_bit_with_a_warning() -> None:
    c = _crane()
    with _new_keyword_only():
        new = c.simulate(t_end=4.0, sway=(0.05, 0.3), output_spacing=0.1)
        positional = c.simulate(4.0, (0.05, 0.3), None, 0.1)  # the old place of dt among the arguments
        default = c.simulate(t_end=1.0)
    assert new.t.size == 41 and np.allclose(np.diff(new.t), 0.1)
    assert np.allclose(np.diff(default.t), 0.02) and default.t.size == 51  # the default kept, 0.02 s
    _same_run(new, positional)
    with pytest.warns(DeprecationWarning, match="Crane.simulate" + DEPRECATED) as caught:
        old = c.simulate(t_end=4.0, sway=(0.05, 0.3), dt=0.1)
    assert len(caught) == 1 and caught[0].filename == __file__  # points at the caller's line
    _same_run(new, old)


def test_residual_grid_takes_output_spacing_and_dt_gives_the_same_grid_bit_for_bit_with_a_warning() -> None:
    shapers = [None, crane.shaper("zv", omega=1.2)]
    args: Any = ([4.0, 7.0], [2.0, 5.0], shapers)
    with _new_keyword_only():
        new = crane.residual_grid(*args, settle=3.0, output_spacing=0.1)
        positional = crane.residual_grid(*args, 5.0, 0.5, 0.5, None, 100.0, 2.0, 9.81, 3.0, 0.1)
        default = crane.residual_grid(*args, settle=3.0)
    assert new.output_spacing == 0.1 and default.output_spacing == 0.05
    assert new.sway.tobytes() == positional.sway.tobytes() and np.all(new.sway > 0)
    assert not np.array_equal(new.sway, default.sway)  # the spacing does reach the runs
    with pytest.warns(DeprecationWarning, match="residual_grid" + DEPRECATED) as caught:
        old = crane.residual_grid(*args, settle=3.0, dt=0.1)
    assert len(caught) == 1 and caught[0].filename == __file__
    assert old.sway.tobytes() == new.sway.tobytes() and old.output_spacing == 0.1


@pytest.mark.parametrize("call", ["Crane.simulate", "residual_grid"])
def test_output_spacing_and_dt_together_are_refused_naming_both(call: str) -> None:
    def run(**kw: float) -> Any:
        if call == "Crane.simulate":
            return _crane().simulate(t_end=2.0, **kw)
        return crane.residual_grid([4.0], [2.0], [None], settle=3.0, **kw)

    both = rf"{call}: output_spacing = 0\.1 and dt = 0\.2 both given: dt is the older name of output_spacing"
    with _new_keyword_only(), pytest.raises(InvalidInputError, match=both):
        run(output_spacing=0.1, dt=0.2)
    with (
        _new_keyword_only(),
        pytest.raises(InvalidInputError, match=r"output_spacing = 0\.1 and dt = 0\.1 both"),
    ):
        run(output_spacing=0.1, dt=0.1)  # equal values too: one name only


def test_a_bad_spacing_is_named_as_written() -> None:
    c = _crane()
    with pytest.raises(InvalidInputError, match=r"^invalid output_spacing = 0\.0: a finite number > 0 s$"):
        c.simulate(t_end=2.0, output_spacing=0.0)
    with (
        pytest.warns(DeprecationWarning),
        pytest.raises(InvalidInputError, match=r"^invalid dt = -1\.0: a finite number > 0 s$"),
    ):
        c.simulate(t_end=2.0, dt=-1.0)
    with pytest.raises(InvalidInputError, match=r"raise output_spacing or shorten t_end"):
        c.simulate(t_end=1e4, output_spacing=1e-2)
    with pytest.raises(
        InvalidInputError,
        match=r"^invalid output_spacing = 5\.0: a finite number > 0 s, at most settle = 3\.0",
    ):
        crane.residual_grid([4.0], [2.0], [None], settle=3.0, output_spacing=5.0)
    with (
        pytest.warns(DeprecationWarning),
        pytest.raises(InvalidInputError, match=r"^invalid dt = 5\.0: .* at most settle"),
    ):
        crane.residual_grid([4.0], [2.0], [None], settle=3.0, dt=5.0)


def test_pivot_samples_takes_spacing_and_dt_gives_the_same_samples_with_a_warning() -> None:
    """``Path.pivot_samples``' spacing of the returned samples is ``spacing`` (it was ``dt``), by the same
    mechanism (crane/_spacing.py): dt= warns at the caller's line and gives the same samples."""
    path = crane.move(distance=1.0, v_max=0.5, a_max=0.5, t_start=0.2)
    with _new_keyword_only():
        t, p = path.pivot_samples(3.0, spacing=0.25)
        positional = path.pivot_samples(3.0, 0.25)  # the old place of dt among the arguments
        default, _ = path.pivot_samples(1.0)
    assert t.size == 13 and np.allclose(np.diff(t), 0.25) and p.shape == (13, 3)
    assert default.size == 101  # the default kept, 0.01 s
    assert positional[0].tobytes() == t.tobytes() and positional[1].tobytes() == p.tobytes()
    warned = r"Path\.pivot_samples\(dt=\.\.\.\) is deprecated: dt is the older name of spacing \(the time "
    with pytest.warns(DeprecationWarning, match=warned + r".*\); write spacing=0\.25$") as caught:
        old = path.pivot_samples(3.0, dt=0.25)
    assert len(caught) == 1 and caught[0].filename == __file__
    assert old[0].tobytes() == t.tobytes() and old[1].tobytes() == p.tobytes()
    both = r"^Path\.pivot_samples: spacing = 0\.25 and dt = 0\.5 both given: dt is the older name of spacing"
    with _new_keyword_only(), pytest.raises(InvalidInputError, match=both):
        path.pivot_samples(3.0, spacing=0.25, dt=0.5)
    with pytest.raises(InvalidInputError, match=r"^invalid spacing = '0\.25': a finite number > 0 s$"):
        path.pivot_samples(3.0, spacing="0.25")


def test_grid_result_says_output_spacing_and_sample_spacing_is_deprecated() -> None:
    """One number, one name: ``GridResult.output_spacing`` as ``residual_grid``'s keyword; the older
    ``sample_spacing`` still reads it, with a DeprecationWarning at the caller's line."""
    res = crane.residual_grid([4.0], [2.0], [None], settle=3.0, output_spacing=0.25)
    assert res.output_spacing == 0.25 and "sample_spacing" not in crane.GridResult.__dataclass_fields__
    warned = r"^GridResult\.sample_spacing is deprecated: it is the older name of output_spacing .*"
    with pytest.warns(DeprecationWarning, match=warned) as caught:
        old = res.sample_spacing
    assert str(caught[0].message).endswith("; read output_spacing")
    assert old == 0.25 and len(caught) == 1 and caught[0].filename == __file__


def test_grid_result_takes_sample_spacing_as_a_deprecated_keyword() -> None:
    """``GridResult(..., sample_spacing=...)`` (the field's older name) was a TypeError once the field
    became ``output_spacing``: it builds the same result, with a DeprecationWarning at the caller's line;
    both names given is refused naming both values; positions and the default are unchanged."""
    cells: Any = (np.ones((1, 1, 1)), np.array([4.0]), np.array([2.0]), ("unshaped",))
    with _new_keyword_only():
        new = crane.GridResult(*cells, output_spacing=0.25)
        positional = crane.GridResult(*cells, True, 0.25, 1e-6, 1e-7)
        default = crane.GridResult(*cells)
    assert new.output_spacing == 0.25 and default.output_spacing == 0.05 and not new.interrupted
    assert (positional.interrupted, positional.output_spacing, positional.rtol, positional.atol) == (
        True,
        0.25,
        1e-6,
        1e-7,
    )
    warned = r"^GridResult\(sample_spacing=\.\.\.\) is deprecated: sample_spacing is the older name of "
    with pytest.warns(
        DeprecationWarning, match=warned + r"output_spacing .*; write output_spacing=0\.25$"
    ) as w:
        old = crane.GridResult(*cells, sample_spacing=0.25)
    assert len(w) == 1 and w[0].filename == __file__
    assert old == new and old.output_spacing == 0.25
    both = r"^GridResult: output_spacing = 0\.25 and sample_spacing = 0\.5 both given: sample_spacing is"
    with _new_keyword_only(), pytest.raises(InvalidInputError, match=both):
        crane.GridResult(*cells, output_spacing=0.25, sample_spacing=0.5)


@pytest.mark.parametrize("kind", ["move", "sampled"])
def test_knots_take_spacing_and_dt_gives_the_same_knots_with_a_warning(kind: str) -> None:
    """``Path.knots``' most time between two knots is ``spacing`` (it was ``dt``), by the same mechanism;
    a measured path's ``knots`` (an override) warns at the caller's line too."""
    path: crane.Path = crane.move(distance=1.0, v_max=0.5, a_max=0.5, t_start=0.2)
    if kind == "sampled":
        ts = np.linspace(0.0, 4.0, 9)
        path = crane.Sampled(ts, np.stack([ts**2, ts, 0 * ts], axis=1))
    with _new_keyword_only():
        new = path.knots(0.0, 3.0, spacing=0.25)
        positional = path.knots(0.0, 3.0, 0.25)  # the old place of dt among the arguments
        default = path.knots(0.0, 3.0)
    assert new[0][0] == 0.0 and new[0][-1] == 3.0 and np.diff(new[0]).max() <= 0.25 + 1e-15
    assert np.diff(default[0]).max() <= 0.05 + 1e-15 < np.diff(new[0]).max()  # the default kept, 0.05 s
    assert all(a.tobytes() == b.tobytes() for a, b in zip(new, positional, strict=True))
    warned = r"^Path\.knots\(dt=\.\.\.\) is deprecated: dt is the older name of spacing \(the most time "
    with pytest.warns(DeprecationWarning, match=warned + r".*\); write spacing=0\.25$") as caught:
        old = path.knots(0.0, 3.0, dt=0.25)
    assert len(caught) == 1 and caught[0].filename == __file__
    assert all(a.tobytes() == b.tobytes() for a, b in zip(new, old, strict=True))
    both = r"^Path\.knots: spacing = 0\.25 and dt = 0\.5 both given: dt is the older name of spacing"
    with _new_keyword_only(), pytest.raises(InvalidInputError, match=both):
        path.knots(0.0, 3.0, spacing=0.25, dt=0.5)
    with pytest.raises(InvalidInputError, match=r"^invalid spacing = 0\.0: a finite number > 0 s$"):
        path.knots(0.0, 3.0, spacing=0.0)
    with (
        pytest.warns(DeprecationWarning),
        pytest.raises(InvalidInputError, match=r"^invalid dt = -1\.0: a finite number > 0 s$"),
    ):
        path.knots(0.0, 3.0, dt=-1.0)
