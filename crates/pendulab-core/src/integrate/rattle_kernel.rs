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
//! The fused arithmetic also takes two shorter forms that the default cannot without changing its
//! bits: the series as a polynomial in y = 4z = (q/b)(c/b), C = Σ (Catₙ/4ⁿ) yⁿ (coefficients 1, 1/4,
//! 1/8, 5/64, 7/128, 21/512, 33/1024, exact in binary) by Horner, |y| ≤ 4·[`SERIES_LIMIT`]; and the
//! projection polynomial scaled by 1/l² once, p = (a' + μ (b' + μ c'))/l². Together 4 fewer
//! products or multiply-adds per step (docs/performance.md, "How fast, and why"). `tests/rattle_unfused.rs` checks the stepper and the ensemble against both
//! arithmetics written out by hand. SI units: lengths \[m\], velocities [m/s], h \[s\].

use glam::DVec3;

/// Largest |z| for which the truncated Catalan series is used (relative truncation error
/// < 429 |z|⁷ / (1 − 4|z|) < 4.3·10⁻¹⁹).
pub const SERIES_LIMIT: f64 = 1e-3;

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
        Self { q, b, c }
    }

    /// μ = m/h [1/s] from the Catalan series, and whether the series applies (|z| ≤
    /// [`SERIES_LIMIT`] and b > 0). When it does not, the returned μ is meaningless.
    #[inline(always)]
    pub fn multiplier_series<A: MulAdd>(&self, h: f64) -> (f64, bool) {
        let ib = 1.0 / self.b;
        if A::FUSED {
            // y = 4z = (q/b)(c/b) and C as a polynomial in y with the exact binary coefficients
            // Catₙ/4ⁿ, by Horner: 5 products and 6 multiply-adds instead of 7 and 7 (module doc)
            let t = self.c * ib;
            let y = (self.q * ib) * t;
            let f = A::fmadd;
            let c56 = f(33.0 / 1024.0, y, 21.0 / 512.0);
            let c36 = f(f(c56, y, 7.0 / 128.0), y, 5.0 / 64.0);
            let series = f(f(f(c36, y, 0.125), y, 0.25), y, 1.0);
            let mu = t * (-0.5 / h) * series;
            return (mu, y.abs() <= 4.0 * SERIES_LIMIT && self.b > 0.0);
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
mod tests {
    use super::*;
    use crate::integrate::rattle::Rattle;
    use crate::model::{IdealPendulum, Model};
    use crate::state::{Params, State};

    /// Positions on the sphere and velocities over a range of speeds and step sizes, both signs of h
    /// (the compositions take negative substeps): the series and the closed form give the same μ.
    #[test]
    fn series_multiplier_agrees_with_the_closed_form() {
        let (l, g) = (1.3, 9.81);
        let mut checked = 0;
        let mut max_rel: f64 = 0.0;
        for i in 0..40 {
            let th = 0.05 + 3.0 * i as f64 / 40.0;
            let x0 = DVec3::new(th.sin() * 0.6f64.cos(), th.sin() * 0.6f64.sin(), -th.cos()) * l;
            let tangent = DVec3::Z.cross(x0).normalize();
            let along = x0.cross(tangent).normalize();
            for speed in [0.0, 0.3, 2.0, 7.0, 20.0] {
                let v0 = (tangent * 0.8 + along * 0.6) * speed;
                for h in [1e-6, -3e-5, 1e-4, 1e-3, -2e-3, 5e-3, 2e-2] {
                    let w = v0 + DVec3::new(0.0, 0.0, -g) * (0.5 * h);
                    let quad = PositionQuadratic::new::<Unfused>(x0, w, h, l * l);
                    let (series, ok) = quad.multiplier_series::<Unfused>(h);
                    let exact = quad.multiplier_exact::<Unfused>(h);
                    if ok {
                        let rel = (series - exact).abs() / exact.abs().max(1e-300);
                        max_rel = max_rel.max(rel);
                        assert!(
                            rel <= 8.0 * f64::EPSILON,
                            "th {th} speed {speed} h {h}: {series} vs {exact}"
                        );
                        checked += 1;
                    }
                    assert_eq!(
                        quad.multiplier::<Unfused>(h).to_bits(),
                        if ok { series } else { exact }.to_bits()
                    );
                }
            }
        }
        assert!(checked > 1000, "the series applied to only {checked} cases");
        eprintln!("series vs closed form: max relative difference {max_rel:.2e} over {checked} cases");
    }

    #[test]
    fn the_series_covers_the_usual_steps_and_leaves_large_ones_to_the_closed_form() {
        let p = Params::new(1.0, 1.0, 9.81).unwrap();
        let s = State::from_angles(&p, 1.0, 0.0, 0.0, 2.0).unwrap();
        let at = |h: f64| {
            let w = s.v + DVec3::new(0.0, 0.0, -9.81) * (0.5 * h);
            PositionQuadratic::new::<Unfused>(s.x, w, h, 1.0).multiplier_series::<Unfused>(h).1
        };
        assert!(at(1e-3) && at(1e-2), "rosette at dt ≤ 10 ms should use the series");
        assert!(!at(0.2), "dt = 0.2 s is outside the series' range");
        // no real root: NaN, also through `multiplier`
        let w = s.v * 1e3;
        let quad = PositionQuadratic::new::<Unfused>(s.x, w, 1.0, 1.0);
        assert!(quad.multiplier::<Unfused>(1.0).is_nan());
    }

    /// The ideal pendulum, but declaring its kick non-uniform: RATTLE takes the general path.
    #[derive(Clone, Copy)]
    struct General(IdealPendulum);
    impl Model for General {
        fn name(&self) -> &'static str {
            "general"
        }
        fn params(&self) -> &Params {
            self.0.params()
        }
        fn applied_acceleration(&self, t: f64, x: DVec3, v: DVec3) -> DVec3 {
            self.0.applied_acceleration(t, x, v)
        }
        fn potential_per_mass(&self, x: DVec3) -> f64 {
            self.0.potential_per_mass(x)
        }
        fn is_conservative(&self) -> bool {
            true
        }
        fn is_axisymmetric(&self) -> bool {
            true
        }
    }

    #[test]
    fn the_uniform_field_path_agrees_with_the_general_path_to_round_off() {
        let ideal = IdealPendulum::new(1.0, 1.0, 9.81).unwrap();
        assert!(ideal.kick_is_uniform() && !General(ideal).kick_is_uniform());
        let s0 = State::from_angles(ideal.params(), 60f64.to_radians(), 0.0, 0.0, 2.0).unwrap();
        for h in [1e-3, -1e-3, 1e-2] {
            // one step: the two paths differ only by rounding
            let (mut a, mut b) = (s0, s0);
            assert!(Rattle::default().advance(&ideal, 0.0, &mut a, h));
            assert!(Rattle::default().advance(&General(ideal), 0.0, &mut b, h));
            let scale = s0.v.length();
            assert!((a.x - b.x).length() <= 4.0 * f64::EPSILON, "h {h}: {:?} vs {:?}", a.x, b.x);
            assert!((a.v - b.v).length() <= 8.0 * f64::EPSILON * scale, "h {h}: {:?} vs {:?}", a.v, b.v);
            // and the constraint x·v = 0 holds as well on the uniform path
            assert!(a.x.dot(a.v).abs() <= 4.0 * f64::EPSILON * scale, "{}", a.x.dot(a.v));
        }
        // 10⁵ steps: round-off of both paths accumulates only in the phase, to ≪ the step error
        let (mut a, mut b) = (s0, s0);
        let (mut ra, mut rb) = (Rattle::default(), Rattle::default());
        for k in 0..100_000 {
            let t = k as f64 * 1e-3;
            assert!(ra.advance(&ideal, t, &mut a, 1e-3) && rb.advance(&General(ideal), t, &mut b, 1e-3));
        }
        assert!((a.x - b.x).length() < 1e-10, "{:?} vs {:?}", a.x, b.x);
    }
}
