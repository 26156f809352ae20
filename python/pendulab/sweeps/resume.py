"""What a resumed sweep takes from the sweep already in ``out`` and what it refuses (``docs/sweeps.md``,
"Method", "Arithmetic"): the integrator its chunks were computed with (``method``: another is
refused; a record without one was written before methods were recorded, when sweeps ran RATTLE, and
stays without one), the RATTLE arithmetic its chunks were computed with and the version of that
arithmetic's bits (``_core.arithmetic_version``, the Rust core's ``Arithmetic::version``, bumped
whenever any bit of its results changes). The new chunks must be the same numbers, bit for bit, as
the ones there, so a resume with ``arithmetic="auto"`` adopts the recorded arithmetic, a named one
that differs is refused, and so is a recorded version other than this pendulab's (a record without a
version was written before versions were recorded: version 1). Refusals are :class:`ResumeConflict`,
whose message names the settings to change as :func:`pendulab.sweep`'s keywords or, for
``pendulab sweep``, as its options. Times in seconds.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from typing import Any

from .. import validate as limits
from .._core import InvalidInputError, arithmetic_version
from .compute import METHODS, SweepSpec, _bad, fingerprint
from .design import Design
from .sinks import recorded_sweep

FIRST_VERSION = 1
"""The version of an arithmetic recorded without one (sweeps written before versions were recorded)."""

_NO_VALUE = object()


@dataclass(frozen=True)
class Setting:
    """A setting named in a message: ``arithmetic='fused'`` for :func:`pendulab.sweep`,
    ``--arithmetic fused`` for ``pendulab sweep`` (just the name or option without a value)."""

    name: str
    value: Any = _NO_VALUE

    def spell(self, cli: bool) -> str:
        if cli:
            option = "--" + self.name.replace("_", "-")
            return option if self.value is _NO_VALUE else f"{option} {self.value}"
        return self.name if self.value is _NO_VALUE else f"{self.name}={self.value!r}"


class ResumeConflict(InvalidInputError):
    """A resume refused before any work: ``out`` records other settings than this run's. The message is
    written once, as a ``str.format`` template whose :class:`Setting` fields are spelled as
    :func:`pendulab.sweep`'s keywords in ``str(error)`` and as ``pendulab sweep``'s options in
    :meth:`for_cli` (the other fields as given)."""

    def __init__(self, template: str, **fields: Any) -> None:
        self.template, self.fields = template, fields
        super().__init__(self._render(cli=False))

    def _render(self, cli: bool) -> str:
        return self.template.format(
            **{k: v.spell(cli) if isinstance(v, Setting) else v for k, v in self.fields.items()}
        )

    def for_cli(self) -> str:
        """The message with the settings spelled as ``pendulab sweep``'s options."""
        return self._render(cli=True)


def _recorded_version(where: os.PathLike[str], recorded: Any, version: Any) -> int | None:
    """The recorded arithmetic's version as recorded (None: none recorded), checked."""
    if recorded not in ("fused", "unfused"):
        raise _bad(
            f"{where} records arithmetic {limits.show(recorded)}, not 'fused' or 'unfused': not a sweep "
            "this pendulab can continue; run it again into a new out"
        )
    if version is not None and (isinstance(version, bool) or not isinstance(version, int) or version < 1):
        raise _bad(
            f"{where} records arithmetic_version {limits.show(version)}, not a version (1, 2, …): not a "
            "sweep this pendulab can continue; run it again into a new out"
        )
    return version


def _unrecorded(
    d: Design, spec: SweepSpec, where: os.PathLike[str], old: dict[str, Any]
) -> tuple[SweepSpec, SweepSpec, str | None]:
    """A sweep written before the arithmetic was recorded: computed with "auto" on the machine that
    wrote it, so with either arithmetic at version 1. It continues with this run's arithmetic (with
    a warning) if that is at version 1 too, its record (and fingerprint) staying without one."""
    record = replace(spec, arithmetic=None, arithmetic_version=None)
    current = arithmetic_version(str(spec.arithmetic))
    if current != FIRST_VERSION and old.get("fingerprint") == fingerprint(d, record):
        raise ResumeConflict(
            "the sweep in {where} does not record the arithmetic its chunks were computed with (written "
            "before pendulab recorded it, with arithmetic='auto': 'fused' where that CPU has FMA, "
            "'unfused' elsewhere, both then of version {first}); this run's arithmetic is {mine!r}, "
            "whose bits are of version {current} now, which no chunk there has. Resume with {unfused} "
            "if the machine that wrote it had no FMA (the same numbers then), or start a new sweep: "
            "run it again into a new {out}",
            where=where,
            first=FIRST_VERSION,
            mine=spec.arithmetic,
            current=current,
            unfused=Setting("arithmetic", "unfused"),
            out=Setting("out"),
        )
    warning = (
        f"{where} does not record the arithmetic its chunks were computed with (written before "
        "pendulab recorded it, with arithmetic='auto' on the machine that wrote it: 'fused' where "
        f"that CPU has FMA, 'unfused' elsewhere); the remaining chunks use {spec.arithmetic!r}, and "
        "if that differs the chunks differ in the last bits. To be sure of one arithmetic, run the "
        "sweep again into a new out"
    )
    return spec, record, warning


def _recorded_method(where: os.PathLike[str], recorded: Any) -> str | None:
    """The recorded method as recorded (None: none recorded, so RATTLE), checked."""
    if recorded is not None and recorded not in METHODS:
        raise _bad(
            f"{where} records method {limits.show(recorded)}, not one of {', '.join(map(repr, METHODS))}: "
            "not a sweep this pendulab can continue; run it again into a new out"
        )
    return recorded if recorded is None else str(recorded)


def resume_settings(
    d: Design, spec: SweepSpec, asked: Any, out: Any, resume: bool
) -> tuple[SweepSpec, SweepSpec, str | None]:
    """The spec the chunks run with, the spec the output records (and its fingerprint hashes), and a
    warning to give if chunks are computed (module doc). ``asked``: the ``arithmetic`` given to
    :func:`pendulab.sweep` before it was resolved. Refuses (:class:`ResumeConflict`), before any
    work, a resume of the same sweep but for its method (one recorded, or RATTLE where none is), or
    whose recorded arithmetic version is not this pendulab's, or with a named arithmetic other than
    the recorded one; a sweep that differs in other settings as well is left to
    :meth:`OutputDir.open <pendulab.sweeps.sinks.OutputDir.open>`, which names all the differences."""
    if not resume or out is None or spec.arithmetic is None:
        return spec, spec, None
    found = recorded_sweep(out)
    if found is None:
        return spec, spec, None
    where, old = found
    old_spec = old.get("spec")
    old_spec = old_spec if isinstance(old_spec, dict) else {}
    ran = _recorded_method(where, old_spec.get("method"))
    if (ran or "rattle") != spec.method:
        arith, version = old_spec.get("arithmetic"), old_spec.get("arithmetic_version")
        same = replace(spec, method=ran, arithmetic=arith, arithmetic_version=version)  # but the method
        if old.get("fingerprint") == fingerprint(d, same):
            raise ResumeConflict(
                "method = {asked!r} differs from {ran!r}, the method the sweep in {where} was computed "
                "with{how}: resume with {fix} so that the new chunks are computed as those there, or "
                "give another {out}",
                asked=spec.method,
                ran=ran or "rattle",
                where=where,
                how="" if ran is not None else " (it records none: written before sweeps recorded one)",
                fix=Setting("method", ran or "rattle"),
                out=Setting("out"),
            )
        return spec, spec, None  # a different sweep: OutputDir.open names the differences
    # a record without a method (RATTLE, as before methods were recorded) stays without one
    base = spec if ran is not None else replace(spec, method=None)
    run, record, warning = _arithmetic(d, base, asked, where, old, old_spec)
    return replace(run, method=spec.method), record, warning


def _arithmetic(
    d: Design, spec: SweepSpec, asked: Any, where: os.PathLike[str], old: dict[str, Any], old_spec: Any
) -> tuple[SweepSpec, SweepSpec, str | None]:
    """:func:`resume_settings` for the arithmetic, once the method is the recorded one."""
    if old_spec.get("arithmetic") is None:
        return _unrecorded(d, spec, where, old)
    recorded = old_spec["arithmetic"]
    version = _recorded_version(where, recorded, old_spec.get("arithmetic_version"))
    current = arithmetic_version(recorded)
    theirs = replace(spec, arithmetic=recorded, arithmetic_version=version)  # as recorded
    if old.get("fingerprint") != fingerprint(d, theirs):  # a different sweep: OutputDir.open says how
        mine = spec if asked != "auto" else replace(spec, arithmetic=recorded, arithmetic_version=current)
        if mine.arithmetic == recorded and (version or FIRST_VERSION) == current:
            mine = theirs  # not a difference worth naming
        return mine, mine, None
    if (version or FIRST_VERSION) != current:
        raise ResumeConflict(
            "the sweep in {where} was computed with the {name} arithmetic of version {old}{how}, and "
            "this pendulab's {name} arithmetic is of version {current}: its bits have changed since, "
            "and new chunks would differ from those there in the last bits. Start a new sweep: run it "
            "again into a new {out} (the one in {where} stays as it is)",
            where=where,
            name=recorded,
            old=version or FIRST_VERSION,
            how="" if version is not None else " (it records none: written before versions were recorded)",
            current=current,
            out=Setting("out"),
        )
    if asked != "auto" and recorded != spec.arithmetic:
        raise ResumeConflict(
            "arithmetic = {asked!r} differs from {recorded!r}, the arithmetic the sweep in {where} was "
            "computed with: resume with {fix} (or {auto}, which takes the recorded one) so that the new "
            "chunks match those there bit for bit, or give another {out}",
            asked=asked,
            recorded=recorded,
            where=where,
            fix=Setting("arithmetic", recorded),
            auto=Setting("arithmetic", "auto"),
            out=Setting("out"),
        )
    return replace(spec, arithmetic=recorded, arithmetic_version=current), theirs, None
