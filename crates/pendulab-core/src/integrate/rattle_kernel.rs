//! The arithmetic of one RATTLE step (T-2.1, T-2.2; see [`super::rattle`]), shared operation for
//! operation by the single-trajectory stepper and the ensemble kernel ([`crate::ensemble`]), so that
//! both give the same numbers bit for bit by construction. With w = v₀ + (h/2) f(t, x₀):
//!
//! ```text
//! x₁ = x₀ + h v½,  v½ = w + μ x₀,  |x₁|² = l²   ⇔   q m² + 2 b m + c = 0,  m = h μ,
//! q = |x₀|²,  b = q + h x₀·w,  c = (q − l²) + h (2 x₀·w + h |w|²).
//! ```
//!
//! The root near 0 is m = −c / (b + √(b² − q c)) = −(c / 2b) · C(z) with z = q c / (4 b²) and
//! C(z) = Σ Catₙ zⁿ = 1 + z + 2z² + 5z³ + 14z⁴ + 42z⁵ + 132z⁶ + … the Catalan series of
//! (1 − √(1 − 4z)) / (2z). For the step sizes that matter z = O((h ω)²) is tiny, and the series
//! truncated after z⁶ is exact to < 4.3·10⁻¹⁹ relative for |z| ≤ [`SERIES_LIMIT`] (tail
//! ≤ Cat₇ |z|⁷ / (1 − 4|z|)): one division (1/b) and a few multiply-adds instead of a square
//! root and a division on the step's dependency chain. Larger |z| uses the closed form.
//!
//! When the applied acceleration does not depend on position (a uniform field, possibly varying in
//! time: gravity, a moving pivot), the end-of-step kick k₁ = (h/2) f(t + h) is known before x₁, and
//! the velocity multiplier's numerator x₁·u (u = v½ + k₁) is a quadratic in μ whose coefficients are
//! computed while μ is:
//!
//! ```text
//! x₁·u = (x₀ + h w + h μ x₀)·(e + μ x₀),  e = w + k₁
//!      = (x₀·e + h w·e) + μ (b + h x₀·e) + μ² h q.
//! ```
//!
//! Updates are Kahan-compensated (the compensation folded into the increment): x₁ = x₀ + (h v½ − cₓ),
//! v₁ = v₀ + ((k₀ + k₁ − c_v) + μ x₀ − p x₁) with p = x₁·u / l².
//!
//! The multiply-adds (`fmadd`, `fmadd3`, `dot`) are, by default ([`Arithmetic::Unfused`], the
//! [`Unfused`] rounding), plain a·b + c, rounded twice — never fused — on every CPU and in
//! WebAssembly: + − × ÷ are correctly rounded everywhere, so the numbers do not depend on the
//! instruction set the hot loops were dispatched to ([`crate::isa`]), nor on the CPU, nor on the
//! engine (native or the page's wasm); the single-trajectory and ensemble paths agree bit for bit.
//! The opt-in [`Arithmetic::Fused`] ([`Fused`]) writes every one of them as `f64::mul_add`, one
//! rounding: correctly rounded everywhere too, so also the same bits on every CPU (and the fused
//! single trajectory equals the fused ensemble), but other bits than the default, and fast only where
//! the CPU has FMA (one instruction at x86-64-v3/v4 and on aarch64; an exact software routine at the
//! x86-64 baseline and in WebAssembly, 3–25× slower: docs/performance.md, "No CPU left behind").
//! The fused arithmetic also takes shorter forms that the default cannot without changing its
//! bits: the series as a polynomial in y = 4z = (q/b)(c/b), C = Σ (Catₙ/4ⁿ) yⁿ (coefficients 1, 1/4,
//! 1/8, 5/64, 7/128, 21/512, 33/1024, exact in binary) by Estrin's scheme (pairs in y, then y², then
//! y⁴: 3 multiply-adds deep instead of Horner's 6), |y| ≤ 4·[`SERIES_LIMIT`], stopped after y³ where
//! |y| ≤ [`SHORT_SERIES_LIMIT`] (truncation < 5.5·10⁻¹⁸ relative there: four fewer operations on
//! the step of almost every trajectory, the ensemble's throughput being bound by their count); the projection
//! polynomial scaled by 1/l² once, p = (a' + μ (b' + μ c'))/l²; and, in a vertical field, the step of
//! `rattle_vertical.rs` (docs/performance.md, "How fast, and why"). `tests/rattle_unfused.rs` checks the stepper and the ensemble against both
//! arithmetics written out by hand. SI units: lengths \[m\], velocities [m/s], h \[s\].

use glam::DVec3;

/// Largest |z| for which the truncated Catalan series is used (relative truncation error
/// < 429 |z|⁷ / (1 − 4|z|) < 4.3·10⁻¹⁹).
pub const SERIES_LIMIT: f64 = 1e-3;

/// Largest |y| = 4|z| for which the fused arithmetic stops the series after y³ (relative truncation
/// error < (Cat₄/4⁴) |y|⁴ / (1 − |y|) < 5.5·10⁻¹⁸, a twentieth of the rounding of μ itself; module
/// doc). |y| ≈ (h |v| / l)²: every step with h |v| ≤ l / 100.
pub const SHORT_SERIES_LIMIT: f64 = 1e-4;

/// How many terms of the series [`PositionQuadratic::multiplier_series_with`] computes (fused
/// arithmetic; the unfused one has one form): the ensemble's tiles try the short form first, for
/// every lane at once, and take the full one only when some lane needs it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesTerms {
    /// Up to y³, applying where |y| ≤ [`SHORT_SERIES_LIMIT`].
    Short,
    /// Up to y³ where |y| ≤ [`SHORT_SERIES_LIMIT`], up to y⁶ elsewhere, applying where
    /// |y| ≤ 4·[`SERIES_LIMIT`].
    Full,
}

/// How the RATTLE kernel rounds its multiply-adds a·b + c (module doc): `Unfused` (the default; two
/// roundings, the same bits on every CPU and in WebAssembly, fast everywhere) or `Fused` (opt-in; one
/// rounding, `f64::mul_add`: the same bits everywhere too, but other bits than `Unfused`, and fast
/// only on CPUs with FMA).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Arithmetic {
    /// a·b + c with two roundings (default).
    #[default]
    Unfused,
    /// a·b + c with one rounding (`f64::mul_add`).
    Fused,
}

impl Arithmetic {
    /// Both, in display order.
    pub const ALL: [Arithmetic; 2] = [Arithmetic::Unfused, Arithmetic::Fused];

    /// The name: `"unfused"` or `"fused"`.
    pub fn name(self) -> &'static str {
        match self {
            Arithmetic::Unfused => "unfused",
            Arithmetic::Fused => "fused",
        }
    }

    /// The version of this arithmetic's numbers: two runs with the same arithmetic and version give
    /// the same bits (on every CPU), so a record of results that are to be continued later (a sweep's
    /// manifest, `python/pendulab/sweeps/resume.py`) keeps the name and this version, and refuses to
    /// add results of another version. Bump it whenever any bit of this arithmetic's results changes
    /// (another order or form of its operations, series, compensations; a change that leaves every bit
    /// as it was needs none), and update `tests/arithmetic_version.rs`, which pins the bits of each
    /// version. History: unfused 1; fused 1. (Stopping the fused series after y³ where
    /// |y| ≤ [`SHORT_SERIES_LIMIT`], 2026-11-27, changed no bit: the terms dropped, < 5.5·10⁻¹⁸ of
    /// the series' value, are below half its ulp, so the full series' last multiply-add had rounded
    /// them away; the same results as the first builds that recorded the arithmetic in sweeps.)
    pub const fn version(self) -> u32 {
        match self {
            Arithmetic::Unfused => 1,
            Arithmetic::Fused => 1,
        }
    }

    /// Looks an arithmetic up by its name (`"unfused"`, `"fused"`).
    pub fn from_name(name: &str) -> crate::error::Result<Self> {
        Self::ALL
            .iter()
            .copied()
            .find(|a| a.name() == name)
            .ok_or_else(|| crate::error::Error::UnknownArithmetic { name: name.to_string() })
    }
}

/// The rounding of a·b + c the kernel functions are compiled with ([`Unfused`] or [`Fused`]).
pub trait MulAdd: Copy {
    /// True for [`Fused`]: the kernel then also uses its shorter forms of the series and the
    /// projection polynomial (module doc, "The fused arithmetic"), which the unfused default cannot
    /// take without changing its bits.
    const FUSED: bool;
    /// a·b + c.
    fn fmadd(a: f64, b: f64, c: f64) -> f64;
}

/// a·b + c unfused (two roundings: the product, then the sum) on every CPU and in WebAssembly, so
/// the same bits everywhere and no software fma on CPUs without FMA (module doc).
#[derive(Debug, Clone, Copy, Default)]
pub struct Unfused;

/// a·b + c fused (`f64::mul_add`, one rounding): one instruction where the CPU has FMA, an exact
/// software routine elsewhere (module doc).
#[derive(Debug, Clone, Copy, Default)]
pub struct Fused;

impl MulAdd for Unfused {
    const FUSED: bool = false;
    #[inline(always)]
    fn fmadd(a: f64, b: f64, c: f64) -> f64 {
        a * b + c
    }
}

impl MulAdd for Fused {
    const FUSED: bool = true;
    #[inline(always)]
    fn fmadd(a: f64, b: f64, c: f64) -> f64 {
        a.mul_add(b, c)
    }
}

/// a·b + c with the rounding `A`.
#[inline(always)]
pub fn fmadd<A: MulAdd>(a: f64, b: f64, c: f64) -> f64 {
    A::fmadd(a, b, c)
}

/// a·s + c componentwise.
#[inline(always)]
pub fn fmadd3<A: MulAdd>(a: DVec3, s: f64, c: DVec3) -> DVec3 {
    DVec3::new(fmadd::<A>(a.x, s, c.x), fmadd::<A>(a.y, s, c.y), fmadd::<A>(a.z, s, c.z))
}

/// The dot product as a_z b_z + (a_y b_y + a_x b_x).
#[inline(always)]
pub fn dot<A: MulAdd>(a: DVec3, b: DVec3) -> f64 {
    fmadd::<A>(a.z, b.z, fmadd::<A>(a.y, b.y, a.x * b.x))
}

/// The position quadratic q m² + 2 b m + c = 0 of one step, m = h μ.
#[derive(Debug, Clone, Copy)]
pub struct PositionQuadratic {
    /// |x₀|² \[m²\].
    pub q: f64,
    /// x₀·(x₀ + h w) \[m²\].
    pub b: f64,
    /// |x₀ + h w|² − l² \[m²\], expanded so that l² cancels exactly.
    pub c: f64,
    /// x₀·w \[m²/s\], of which b and c are made (the vertical-field step, `rattle_vertical.rs`,
    /// reuses it).
    pub xw: f64,
    /// |w|² \[m²/s²\], of which c is made (reused like `xw`).
    pub ww: f64,
}

impl PositionQuadratic {
    /// The quadratic for position `x0` \[m\], w = v₀ + k₀ [m/s], step `h` \[s\] and l² = `l2` \[m²\].
    #[inline(always)]
    pub fn new<A: MulAdd>(x0: DVec3, w: DVec3, h: f64, l2: f64) -> Self {
        let q = dot::<A>(x0, x0);
        let xw = dot::<A>(x0, w);
        let ww = dot::<A>(w, w);
        let b = fmadd::<A>(h, xw, q);
        let c = fmadd::<A>(h, fmadd::<A>(h, ww, xw + xw), q - l2);
        Self { q, b, c, xw, ww }
    }

    /// μ = m/h [1/s] from the Catalan series, and whether the series applies (|z| ≤
    /// [`SERIES_LIMIT`] and b > 0). When it does not, the returned μ is meaningless.
    #[inline(always)]
    pub fn multiplier_series<A: MulAdd>(&self, h: f64) -> (f64, bool) {
        self.multiplier_series_with::<A>(h, SeriesTerms::Full)
    }

    /// [`PositionQuadratic::multiplier_series`] computed with the `terms` given: with the fused
    /// arithmetic, `Short` computes the series only up to y³ and says it applies only where
    /// |y| ≤ [`SHORT_SERIES_LIMIT`] (and b > 0); where it applies, μ has the same bits as with `Full`
    /// (which takes the same short polynomial there). The unfused arithmetic has one form.
    #[inline(always)]
    pub fn multiplier_series_with<A: MulAdd>(&self, h: f64, terms: SeriesTerms) -> (f64, bool) {
        let ib = 1.0 / self.b;
        if A::FUSED {
            // y = 4z = (q/b)(c/b) and C as a polynomial in y with the exact binary coefficients
            // Catₙ/4ⁿ by Estrin's scheme, 3 multiply-adds deep (Horner: 6); up to y³ (4 products and
            // multiply-adds) where |y| ≤ SHORT_SERIES_LIMIT, up to y⁶ (4 more) elsewhere (module doc)
            let t = self.c * ib;
            let y = (self.q * ib) * t;
            let f = A::fmadd;
            let (y2, p01, p23) = (y * y, f(0.25, y, 1.0), f(5.0 / 64.0, y, 0.125));
            let p03 = f(p23, y2, p01);
            let short = y.abs() <= SHORT_SERIES_LIMIT;
            let (series, in_range) = match terms {
                SeriesTerms::Short => (p03, short),
                SeriesTerms::Full => {
                    let p45 = f(21.0 / 512.0, y, 7.0 / 128.0);
                    let p46 = f(33.0 / 1024.0, y2, p45);
                    let full = f(p46, y2 * y2, p03);
                    (if short { p03 } else { full }, y.abs() <= 4.0 * SERIES_LIMIT)
                }
            };
            let mu = t * (-0.5 / h) * series;
            return (mu, in_range && self.b > 0.0);
        }
        let z = 0.25 * self.q * self.c * (ib * ib);
        let z2 = z * z;
        let low = fmadd::<A>(z2, fmadd::<A>(5.0, z, 2.0), 1.0 + z);
        let high = fmadd::<A>(z2, 132.0, fmadd::<A>(42.0, z, 14.0));
        let series = fmadd::<A>(z2 * z2, high, low);
        let mu = self.c * (ib * (-0.5 / h)) * series;
        (mu, z.abs() <= SERIES_LIMIT && self.b > 0.0)
    }

    /// μ = m/h [1/s] in closed form, −c / (h (b + √(b² − q c))); NaN when there is no real root near
    /// 0 (b ≤ 0 or a negative discriminant: h far too large for the motion).
    #[inline(always)]
    pub fn multiplier_exact<A: MulAdd>(&self, h: f64) -> f64 {
        let disc = fmadd::<A>(-self.q, self.c, self.b * self.b);
        if disc.is_nan() || disc < 0.0 || self.b <= 0.0 {
            return f64::NAN;
        }
        -self.c / (h * (self.b + disc.sqrt()))
    }

    /// μ [1/s]: the series where it applies, else the closed form (NaN when there is no root).
    #[inline(always)]
    pub fn multiplier<A: MulAdd>(&self, h: f64) -> f64 {
        let (mu, ok) = self.multiplier_series::<A>(h);
        if ok {
            mu
        } else {
            self.multiplier_exact::<A>(h)
        }
    }
}

/// p(μ) = x₁·u / l² = a + μ (b + μ c) for a uniform field (see the module doc); with the fused
/// arithmetic the coefficients are kept unscaled and p = (a' + μ (b' + μ c')) / l², one product by
/// 1/l² instead of three.
#[derive(Debug, Clone, Copy)]
pub struct ProjectionPolynomial {
    a: f64,
    b: f64,
    c: f64,
    inv_l2: f64,
}

impl ProjectionPolynomial {
    /// Coefficients from x₀ \[m\], w [m/s], the end kick k₁ [m/s], the quadratic, h \[s\] and 1/l².
    #[inline(always)]
    pub fn new<A: MulAdd>(
        x0: DVec3,
        w: DVec3,
        kick1: DVec3,
        quad: &PositionQuadratic,
        h: f64,
        inv_l2: f64,
    ) -> Self {
        let e = w + kick1;
        let xe = dot::<A>(x0, e);
        let (a, b) = (fmadd::<A>(h, dot::<A>(w, e), xe), fmadd::<A>(h, xe, quad.b));
        if A::FUSED {
            Self { a, b, c: h * quad.q, inv_l2 }
        } else {
            Self { a: a * inv_l2, b: b * inv_l2, c: h * quad.q * inv_l2, inv_l2 }
        }
    }

    /// p [1/s] at the multiplier μ.
    #[inline(always)]
    pub fn at<A: MulAdd>(&self, mu: f64) -> f64 {
        let p = fmadd::<A>(mu, fmadd::<A>(mu, self.c, self.b), self.a);
        if A::FUSED {
            p * self.inv_l2
        } else {
            p
        }
    }
}

/// x₁ = x₀ + h v½ \[m\], Kahan-compensated with the running compensation `comp`.
#[inline(always)]
pub fn advance_position<A: MulAdd>(x0: DVec3, v_half: DVec3, h: f64, comp: &mut DVec3) -> DVec3 {
    let y = fmadd3::<A>(v_half, h, -*comp);
    let x1 = x0 + y;
    *comp = (x1 - x0) - y;
    x1
}

/// v₁ = v₀ + (k₀ + k₁) + μ x₀ − p x₁ [m/s], Kahan-compensated with the running compensation `comp`.
#[inline(always)]
pub fn advance_velocity<A: MulAdd>(
    v0: DVec3,
    kicks: DVec3,
    x0: DVec3,
    mu: f64,
    x1: DVec3,
    p: f64,
    comp: &mut DVec3,
) -> DVec3 {
    let y = fmadd3::<A>(x1, -p, fmadd3::<A>(x0, mu, kicks - *comp));
    let v1 = v0 + y;
    *comp = (v1 - v0) - y;
    v1
}

#[cfg(test)]
#[path = "rattle_kernel_tests.rs"]
mod tests;
