"""Floating-point operations and memory traffic of Pendulab's hot kernels, counted by hand from the
source (bench/roofline/run.py puts them on the roofline).

How: every line of a kernel's hot path is read once and its operations tallied in the tables below, one
row per function with the file it is in. A fused multiply-add (C's contracted a·b + c) counts 2 flop;
the RATTLE kernel's ``fmadd`` is an unfused a·b + c since 2026-11-26 (issue 29 item 4), a multiplication
and an addition, 2 flop as well, so its rows list no FMAs;
an addition, subtraction, multiplication, division or square root 1; sign changes, abs, min/max,
comparisons and selects 0 (no arithmetic; they use other execution ports). Loop-invariant work that
the compiler hoists out of the step loop (h/2, −0.5/h, 1/l²) is not counted. A dot product
``rattle_kernel::dot`` is 3 mul + 2 add = 5 flop; an unfused glam ``a.dot(b)`` or ``length_squared``
3 mul + 2 add = 5 flop. "Executed" counts what the machine does (recomputed values included);
the figures are per unit of work (one trajectory-step, one step, one state).

Bytes are the traffic between the kernel's registers and memory per unit of work, counted from the
data structures (8 B per float64): the register-blocked ensemble loads and stores a tile once per
chunk of up to 1024 steps, so its traffic per step is tiny and it is compute-bound by construction;
the C RK4 ensemble keeps its stage arrays in L1 and moves them every stage. Register spills the
compiler adds are not counted (they stay in L1). SI units do not enter: these are counts.
"""

from __future__ import annotations

from dataclasses import dataclass

# (function, file, mul/add/sub/div/sqrt count, fma count, times per unit of work)
Row = tuple[str, str, int, int, int]

RATTLE_STEP: list[Row] = [
    ("kick (0, 0, −g)·h/2 and w = v₀ + k₀", "integrate/rattle.rs", 6, 0, 1),
    ("PositionQuadratic::new: |x₀|², x₀·w, |w|² (3 dots), b, c", "integrate/rattle_kernel.rs", 23, 0, 1),
    ("multiplier_series: 1/b, z, z², Catalan polynomial, μ", "integrate/rattle_kernel.rs", 21, 0, 1),
    ("v½ = x₀ μ + w (fmadd3)", "integrate/rattle_kernel.rs", 6, 0, 1),
    ("advance_position: h v½ − cₓ, x₀ + y, Kahan (x₁ − x₀) − y", "integrate/rattle_kernel.rs", 15, 0, 1),
    ("kick k₁ = (0, 0, −g)·h/2 (uniform field)", "integrate/rattle.rs", 3, 0, 1),
    ("ProjectionPolynomial::new: e = w + k₁, x₀·e, w·e, a, b, c", "integrate/rattle_kernel.rs", 21, 0, 1),
    ("ProjectionPolynomial::at: a + μ(b + μ c)", "integrate/rattle_kernel.rs", 4, 0, 1),
    (
        "advance_velocity: k₀ + k₁, − c_v, + μ x₀, − p x₁, v₀ + y, Kahan",
        "integrate/rattle_kernel.rs",
        15,
        6,
        1,
    ),
]
"""One RATTLE step of one trajectory, ideal pendulum (`Rattle::advance`, the uniform-field path)."""

ENSEMBLE_STEP: list[Row] = [
    ("kick (0, 0, −g·h/2): one mul (the zeros are +0 exactly), w = v₀ + k", "ensemble/block.rs", 4, 0, 1),
    ("PositionQuadratic::new: |x₀|², x₀·w, |w|² (3 dots), b, c", "integrate/rattle_kernel.rs", 23, 0, 1),
    ("multiplier_series: 1/b, z, z², Catalan polynomial, μ", "integrate/rattle_kernel.rs", 21, 0, 1),
    ("ProjectionPolynomial::new (k₁ = k₀) and at(μ)", "integrate/rattle_kernel.rs", 25, 0, 1),
    ("v½ = x₀ μ + w, advance_position", "integrate/rattle_kernel.rs", 21, 0, 1),
    (
        "advance_velocity: k + k (one add: 0 + 0 folds), − c_v, + μ x₀, − p x₁, v₀ + y, Kahan",
        "integrate/rattle_kernel.rs",
        13,
        6,
        1,
    ),
]
"""One trajectory-step of the ensemble block (`ensemble/block.rs` `Tile::rattle`, undamped, no
summary): the same operations as `RATTLE_STEP` for each lane, with k₁ = k₀ computed once."""

RK4_C_STEP: list[Row] = [
    (
        "rhs_block: |v|² (1 mul, 2 fma), g z − |v|² (fma), ·1/l², λx, λy, λz − g (fma)",
        "bench/peers/rk4.c",
        4,
        4,
        4,
    ),
    ("stage states t = s + a·k (gcc fuses)", "bench/peers/rk4.c", 0, 6, 3),
    ("s += h/6 (k1 + 2 k2 + 2 k3 + k4): 3 fma + 1 add per component", "bench/peers/rk4.c", 1, 3, 6),
]
"""One trajectory-step of the C RK4 ensemble (bench/peers/rk4.c, the peers benchmark's baseline),
as gcc -O3 -march=native contracts it (a·b + c fused)."""

# DOP853 (integrate/dop853.rs) on the ideal pendulum's T-2.4, projection on:
_RHS_FLOP = 5 + 5 + 1 + 1 + 3 + 3  # |v|², x·f, +, ·1/l², x λ (3 mul), f + (3 add)
_STAGE_AXPYS = sum(range(1, 12))  # stage i adds k₀ … k_{i−1}, zeros of A included: 66 axpys
DOP853_STEP: list[Row] = [
    (
        "attempt: stage sums y₀ + Σ h a_ij k_j (h·a_ij, 6 mul, 6 add)",
        "integrate/dop853.rs",
        13,
        0,
        _STAGE_AXPYS,
    ),
    ("rhs: ẋ = v, v̇ = f + λ x with λ = −(|v|² + x·f)/l²", "model/mod.rs", _RHS_FLOP, 0, 12),
    ("attempt: incr, e5, e3 = Σ b_i k_i (3 axpys of 12 flop per stage)", "integrate/dop853.rs", 36, 0, 12),
    (
        "attempt: y₁ = y₀ + h incr; error weights; two scaled norms; err",
        "integrate/dop853.rs",
        12 + 12 + 34 + 6,
        0,
        1,
    ),
    ("accept: project_onto_tangent_bundle (|x|, l/r, x·v/l², v − …)", "state.rs", 23, 0, 1),
]
"""One accepted DOP853 step (12 evaluations: 11 stages + the next step's first, FSAL), without the
step-size controller's few scalar operations and without rejected steps (the benchmark reports
evaluations per accepted step; the flop rate is scaled by evaluations/12)."""


def flops(rows: list[Row]) -> int:
    """Executed flop per unit of work (FMA = 2)."""
    return sum((plain + 2 * fma) * times for _, _, plain, fma, times in rows)


def fmas(rows: list[Row]) -> int:
    """Fused multiply-adds per unit of work."""
    return sum(fma * times for _, _, _, fma, times in rows)


@dataclass(frozen=True)
class Kernel:
    """A kernel on the roofline: its name, unit of work, flop and bytes per unit, and how counted."""

    key: str
    name: str
    unit: str
    flop: float
    bytes: float
    how: str


# bytes per unit: the ensemble moves x, v, cₓ, c_v (12 float64 in, 12 out) and l², 1/l², g, decay
# (4 in) once per chunk of 1024 steps; the single RATTLE step reads and writes the state and its two
# compensations (12 + 12 float64); the C RK4 ensemble reads 6 and writes 6 per rhs (4 rhs), reads 12 and
# writes 6 per stage state (3), reads 30 and writes 6 for the update: 138 float64; DOP853 reads a k
# vector (6 float64) per stage-sum axpy (66) and once more for the three final sums (12), and writes
# the 12 k vectors: 66·6 + 12·6 + 12·6 float64.
FUSED_FEWER_FLOP = 6 + 2 + 2 + (2 + 3 + 3 + 3 + 2)
"""Flop the fused arithmetic's ensemble step (``arithmetic="fused"``, ``integrate/rattle_kernel.rs`` and
``integrate/rattle_vertical.rs``) does not do: the Catalan series in y = 4z by Estrin's scheme, stopped
after y³ where |y| ≤ 10⁻⁴ (every step of the benchmarks: 3 FMA and y² = 7 flop instead of 13; up to y⁶
it is 6 FMA, y² and y⁴, 14 flop), y and μ from c/b and q/b (5 products instead of 7), the
projection polynomial scaled by 1/l² once (2 products fewer), and the vertical field's form: w without
the kick's two zero components (2 additions), e = w + k₁ not formed (3), x₀·e and w·e as one
multiply-add each from x₀·w and |w|² (a dot product of 5 flop → 2, twice), Δv without the kicks' two
zero components (2 subtractions)."""

KERNELS = [
    Kernel(
        "ensemble",
        "RATTLE ensemble (`ensemble/block.rs`)",
        "trajectory-step",
        flops(ENSEMBLE_STEP),
        28 * 8 / 1024,
        "ENSEMBLE_STEP",
    ),
    Kernel(
        "rattle",
        "RATTLE, one trajectory (`Stepper::step_n`)",
        "step",
        flops(RATTLE_STEP),
        24 * 8,
        "RATTLE_STEP",
    ),
    Kernel(
        "rk4_c",
        "C RK4 ensemble (bench/peers/rk4.c)",
        "trajectory-step",
        flops(RK4_C_STEP),
        138 * 8,
        "RK4_C_STEP",
    ),
    Kernel(
        "dop853",
        "DOP853, one trajectory (`Stepper::step_n`)",
        "accepted step",
        flops(DOP853_STEP),
        (_STAGE_AXPYS * 6 + 12 * 6 + 12 * 6) * 8,
        "DOP853_STEP",
    ),
]
"""The kernels with counted flops. The exact solution's state is not among them: its cost is a few
calls of the C library's sin/cos/atan2 and iterations of Newton and Carlson's duplication whose count
depends on the orbit, so bench/roofline/run.py reports its rate in states/s without a flop figure."""


if __name__ == "__main__":
    for k in KERNELS:
        print(
            f"{k.name:50s} {k.flop:7.0f} flop/{k.unit}, {k.bytes:8.2f} B, intensity {k.flop / k.bytes:8.1f}"
        )
