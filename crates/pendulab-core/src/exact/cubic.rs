//! The cubic of the exact solution (T-4.1), dimensionless (u = z/l, τ = ω₀t, g > 0):
//!
//!   (du/dτ)² = P(u) = 2(ε − u)(1 − u²) − j² = 2(u − u₁)(u − u₂)(u − u₃),  −1 ≤ u₁ ≤ u₀ ≤ u₂ ≤ 1 ≤ u₃,
//!
//! with ε = E/(m g l), j = J₃/(m l² ω₀) and u₀ the start. Everything downstream needs *differences*
//! of roots (u₂ − u₁, 1 + u₁, 1 − u₂, u₃ − u₂ …) to full relative accuracy, also where they are tiny:
//! 1 + u₁ ≈ 3e-10 when the bob skims the bottom pole, u₂ − u₁ ≈ 1e-17 on a conical orbit, u₃ − u₂
//! small near the separatrix. So each root is kept as an offset from the nearest of three centres,
//! −1, u₀ and +1, and found from the Taylor expansion of P about that centre,
//!
//!   P(c + d) = P(c) + P′(c) d + ½P″(c) d² + 2d³,
//!   about −1:  −j² + 4(κ + p₋) d − 2(3 + ε) d² + 2d³,
//!   about u₀:  u̇₀² − 2(ρ² + 2κu₀) d + (4u₀ − 2κ) d² + 2d³,
//!   about +1:  −j² + 4(p₊ − κ) d + (6 − 2ε) d² + 2d³,
//!
//! where κ = ε − u₀ = |v|²/(2gl) ≥ 0, p± = 1 ∓ u₀, ρ² = 1 − u₀² = p₊p₋, all formed without
//! cancellation from the state. About u₀ the constant term is u̇₀² itself (the identity
//! 2κρ² − j² = u̇₀², Lagrange's identity on TS²), so a start at a turning point is a root exactly
//! and a conical start keeps u₂ − u₁ at round-off instead of √(round-off).
//!
//! The constant terms are P's exact values at the centres: P(−1) = P(+1) = −j² ≤ 0 ≤ u̇₀² = P(u₀).
//! So u₁ is bracketed in [−1, u₀] and u₂ in [u₀, 1], and P is only ever taken from the expansion
//! about the nearer centre (`root_between`): from the farther one its rounding,
//! ≈ ε P″ gap², can exceed a nearly planar orbit's j² ≈ 1e-17 and flip the sign of P(±1) (such
//! starts were refused, "invalid n1"). u₃ ≥ 1 is bracketed about +1. Newton falls back to the chord
//! through the bracket, then to bisection, so that a root 1e-81 from its centre (j = 5e-41) is
//! reached in a few steps rather than 270 halvings.

/// Where a root is anchored.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Centre {
    /// u = −1 (the bottom for g > 0).
    MinusOne,
    /// u = u₀ (the start).
    Start,
    /// u = +1 (the top).
    PlusOne,
}

/// A root u = centre + offset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Root {
    /// The anchor.
    pub centre: Centre,
    /// Offset from the anchor (dimensionless).
    pub offset: f64,
}

/// Dimensionless start data, formed from the state without cancellation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StartData {
    /// u₀ = z₀/l.
    pub u0: f64,
    /// κ = |v₀|²/(2 g l) = ε − u₀.
    pub kappa: f64,
    /// p₋ = 1 + u₀.
    pub p_minus: f64,
    /// p₊ = 1 − u₀.
    pub p_plus: f64,
    /// j = J₃/(m l² ω₀).
    pub j: f64,
    /// u̇₀ = du/dτ at the start.
    pub udot: f64,
}

impl StartData {
    /// From u₀, ρ₀² = (x₀² + y₀²)/l², κ, j and u̇₀. p± come from whichever of 1 ∓ u₀ does not cancel.
    pub fn new(u0: f64, rho2: f64, kappa: f64, j: f64, udot: f64) -> Self {
        let (p_minus, p_plus) =
            if u0 < 0.0 { (rho2 / (1.0 - u0), 1.0 - u0) } else { (1.0 + u0, rho2 / (1.0 + u0)) };
        Self { u0, kappa, p_minus, p_plus, j, udot }
    }

    /// From u₀ with p₋ = 1 + u₀ and p₊ = 1 − u₀ already formed without cancellation, κ, j and u̇₀.
    pub fn from_parts(u0: f64, p_minus: f64, p_plus: f64, kappa: f64, j: f64, udot: f64) -> Self {
        Self { u0, kappa, p_minus, p_plus, j, udot }
    }

    /// ε = E/(m g l) = κ + u₀.
    pub fn epsilon(&self) -> f64 {
        self.kappa + self.u0
    }

    /// Coefficients (P(c), P′(c), ½P″(c)) of the expansion about `c`; the cubic coefficient is 2.
    fn expansion(&self, c: Centre) -> [f64; 3] {
        let (k, u0, j2) = (self.kappa, self.u0, self.j * self.j);
        match c {
            Centre::MinusOne => [-j2, 4.0 * (k + self.p_minus), -2.0 * (3.0 + k + u0)],
            Centre::Start => [
                self.udot * self.udot,
                -2.0 * (self.p_minus * self.p_plus + 2.0 * k * u0),
                4.0 * u0 - 2.0 * k,
            ],
            Centre::PlusOne => [-j2, 4.0 * (self.p_plus - k), 6.0 - 2.0 * (k + u0)],
        }
    }

    /// P(c + d) and P′(c + d).
    fn eval(&self, c: Centre, d: f64) -> (f64, f64) {
        let [c0, c1, c2] = self.expansion(c);
        (c0 + d * (c1 + d * (c2 + 2.0 * d)), c1 + d * (2.0 * c2 + 6.0 * d))
    }

    /// Position of centre `a` minus centre `b`: 0, ±p₋, ±p₊ or ±2 (never a difference of sums,
    /// which would round p± ≈ 1e-4 to the ulp of 2).
    fn centre_gap(&self, a: Centre, b: Centre) -> f64 {
        use Centre::*;
        match (a, b) {
            (MinusOne, MinusOne) | (Start, Start) | (PlusOne, PlusOne) => 0.0,
            (Start, MinusOne) => self.p_minus,
            (MinusOne, Start) => -self.p_minus,
            (PlusOne, Start) => self.p_plus,
            (Start, PlusOne) => -self.p_plus,
            (PlusOne, MinusOne) => 2.0,
            (MinusOne, PlusOne) => -2.0,
        }
    }

    /// a − b for two roots, to full relative accuracy when both sit near the same centre.
    pub fn diff(&self, a: Root, b: Root) -> f64 {
        self.centre_gap(a.centre, b.centre) + (a.offset - b.offset)
    }

    /// 1 + u for a root u.
    pub fn one_plus(&self, r: Root) -> f64 {
        self.diff(r, Root { centre: Centre::MinusOne, offset: 0.0 })
    }

    /// 1 − u for a root u.
    pub fn one_minus(&self, r: Root) -> f64 {
        self.diff(Root { centre: Centre::PlusOne, offset: 0.0 }, r)
    }

    /// u − u₀ for a root u.
    pub fn from_start(&self, r: Root) -> f64 {
        self.diff(r, Root { centre: Centre::Start, offset: 0.0 })
    }

    /// The value of a root.
    pub fn value(&self, r: Root) -> f64 {
        match r.centre {
            Centre::MinusOne => -1.0 + r.offset,
            Centre::Start => self.u0 + r.offset,
            Centre::PlusOne => 1.0 + r.offset,
        }
    }

    /// Bracketed Newton (Newton with bisection fallback) for f(d) = 0 with d in [lo, hi].
    fn solve_with(f: impl Fn(f64) -> (f64, f64), lo: f64, hi: f64, guess: f64) -> f64 {
        let (flo, _) = f(lo);
        let (fhi, _) = f(hi);
        if flo == 0.0 {
            return lo;
        }
        if fhi == 0.0 {
            return hi;
        }
        if flo.signum() == fhi.signum() {
            // Round-off at a (near-)double root: the end with the smaller residual is the root.
            return if flo.abs() <= fhi.abs() { lo } else { hi };
        }
        // orient so that f(a) < 0 < f(b)
        let (mut a, mut b, mut fa, mut fb) = if flo < 0.0 { (lo, hi, flo, fhi) } else { (hi, lo, fhi, flo) };
        let mut d = if guess > lo.min(hi) && guess < lo.max(hi) { guess } else { 0.5 * (lo + hi) };
        let mut secant_last = false;
        for _ in 0..200 {
            let (fd, df) = f(d);
            if fd == 0.0 {
                return d;
            }
            if fd < 0.0 {
                (a, fa) = (d, fd);
            } else {
                (b, fb) = (d, fd);
            }
            let inside = |t: f64| (t - a) * (t - b) < 0.0;
            let newton = d - fd / df;
            // Newton when it stays in the bracket; else the chord through the bracket's ends (a root
            // 1e-81 from the end of a bracket 0.07 wide is 270 halvings away, but one chord from a
            // near-linear P); bisection after a chord, so that a bent P cannot stall the chord.
            let chord = a - fa * (b - a) / (fb - fa);
            let next = if df != 0.0 && inside(newton) {
                secant_last = false;
                newton
            } else if !secant_last && inside(chord) {
                secant_last = true;
                chord
            } else {
                secant_last = false;
                0.5 * (a + b)
            };
            if next == d || (a - b).abs() <= 2.0 * f64::EPSILON * d.abs().max(f64::MIN_POSITIVE) {
                return next;
            }
            d = next;
        }
        d
    }

    /// Bracketed Newton for P(c + d) = 0 with d in [lo, hi], P expanded about `c`.
    fn solve(&self, c: Centre, lo: f64, hi: f64, guess: f64) -> f64 {
        Self::solve_with(|d| self.eval(c, d), lo, hi, guess)
    }

    /// The root of P between the centres `near` and `far` (|gap| = |far − near| apart, `gap` signed
    /// as far − near), where P(near) and P(far) — the exact constant terms −j² and u̇₀² of their
    /// expansions — have opposite signs (or one is zero). The sign of P at the middle decides in
    /// which half the root lies, and it is then found by Newton on the expansion about the centre
    /// of that half: no value of P is ever taken from an expansion about the farther centre, whose
    /// rounding (≈ ε·P″·gap²) can exceed a P(±1) = −j² of 1e-17 and flip its sign (near-planar
    /// starts were refused that way). Returns the root anchored at the nearer centre.
    fn root_between(&self, near: Centre, far: Centre, gap: f64) -> Root {
        let half = 0.5 * gap;
        let f_near = self.expansion(near)[0];
        let f_half = self.eval(near, half).0;
        if f_half == 0.0 {
            return Root { centre: near, offset: half };
        }
        if f_near == 0.0 || f_half.signum() != f_near.signum() {
            let (lo, hi) = if half < 0.0 { (half, 0.0) } else { (0.0, half) };
            Root { centre: near, offset: self.solve(near, lo, hi, 0.5 * half) }
        } else {
            let (lo, hi) = if half < 0.0 { (0.0, -half) } else { (-half, 0.0) };
            Root { centre: far, offset: self.solve(far, lo, hi, -0.5 * half) }
        }
    }

    /// Roots when the start is a turning point (u̇₀ = 0): P(u₀ + d) = d (P′(u₀) + ½P″(u₀) d + 2d²), so
    /// u₀ is a root exactly and the others solve the quadratic (stable form). Roots nearer ±1 than
    /// u₀ are then found again on the expansion about ±1 ([`refine`](Self::refine)), which keeps 1 ± u
    /// relatively accurate.
    fn roots_at_turning_point(&self) -> [Root; 3] {
        let [_, c1, c2] = self.expansion(Centre::Start);
        let disc = (c2 * c2 - 8.0 * c1).max(0.0);
        let q = -0.5 * (c2 + disc.sqrt().copysign(c2));
        let (da, db) = if q == 0.0 { (0.0, 0.0) } else { (q / 2.0, c1 / q) };
        let mut d = [0.0, da, db];
        d.sort_by(f64::total_cmp);
        let (pm, pp) = (self.p_minus, self.p_plus);
        d.map(|di| {
            let to_bottom = pm + di; // u − (−1)
            let to_top = pp - di; // 1 − u
            if di != 0.0 && to_bottom.abs() < di.abs() {
                Root { centre: Centre::MinusOne, offset: self.refine(Centre::MinusOne, to_bottom, 0.5 * pm) }
            } else if di != 0.0 && to_top.abs() < di.abs() {
                Root { centre: Centre::PlusOne, offset: self.refine(Centre::PlusOne, -to_top, -0.5 * pp) }
            } else {
                Root { centre: Centre::Start, offset: di }
            }
        })
    }

    /// The root near the pole `c` (±1) from the estimate `d`: bracketed between the pole, where
    /// P = −j² < 0 exactly, and a point where P > 0 on the estimate's side — `half` (half-way to
    /// u₀, signed) for a root between the pole and u₀, else 2d, 4d, … beyond the pole (u₃);
    /// [`polish`](Self::polish) when no such bracket holds (j = 0, or round-off).
    fn refine(&self, c: Centre, d: f64, half: f64) -> f64 {
        let mut end = half;
        if d * half < 0.0 && c == Centre::PlusOne {
            end = 2.0 * d;
            while self.eval(c, end).0 <= 0.0 && end.abs() < 1e300 {
                end *= 2.0;
            }
        }
        let (lo, hi) = if end < 0.0 { (end, 0.0) } else { (0.0, end) };
        if self.j != 0.0 && self.eval(c, end).0 > 0.0 {
            self.solve(c, lo, hi, d)
        } else {
            self.polish(c, d)
        }
    }

    /// A few Newton steps on the expansion about `c` from `d`, kept while the residual falls.
    fn polish(&self, c: Centre, mut d: f64) -> f64 {
        let mut best = self.eval(c, d).0.abs();
        for _ in 0..8 {
            let (f, df) = self.eval(c, d);
            if f == 0.0 || df == 0.0 {
                break;
            }
            let next = d - f / df;
            let r = self.eval(c, next).0.abs();
            if r.is_nan() || r >= best {
                break;
            }
            best = r;
            d = next;
        }
        d
    }

    /// The three roots u₁ ≤ u₂ ≤ u₃ of P (requires g > 0 form; any j, any start on TS²).
    pub fn roots(&self) -> [Root; 3] {
        let (pm, pp) = (self.p_minus, self.p_plus);
        if self.j == 0.0 {
            // Planar: P = 2(ε − u)(1 − u²), roots −1, +1 and ε = 1 + (κ − p₊).
            let eps_from_top = Root { centre: Centre::PlusOne, offset: self.kappa - pp };
            let top = Root { centre: Centre::PlusOne, offset: 0.0 };
            let bottom = Root { centre: Centre::MinusOne, offset: 0.0 };
            return if eps_from_top.offset < 0.0 {
                [bottom, eps_from_top, top]
            } else {
                [bottom, top, eps_from_top]
            };
        }
        if self.udot == 0.0 {
            return self.roots_at_turning_point();
        }
        // u₁ in [−1, u₀] where P(−1) = −j² < 0 < u̇₀² = P(u₀); u₂ in [u₀, 1] likewise.
        let u1 = self.root_between(Centre::Start, Centre::MinusOne, -pm);
        let u2 = self.root_between(Centre::Start, Centre::PlusOne, pp);
        // u₃ ≥ 1: expand the bracket until P > 0.
        let mut hi = 1.0;
        while self.eval(Centre::PlusOne, hi).0 <= 0.0 && hi < 1e300 {
            hi *= 2.0;
        }
        let u3 = Root { centre: Centre::PlusOne, offset: self.solve(Centre::PlusOne, 0.0, hi, 0.5 * hi) };
        [u1, u2, u3]
    }
}
