//! Double-double arithmetic: a value is the unevaluated sum `hi + lo` of two `f64` with
//! |lo| ≤ ulp(hi)/2, about 106 significant bits.
//!
//! Built on the error-free transformations
//! - TwoSum (Knuth, TAOCP vol. 2, §4.2.2): a + b = s + e exactly, s = fl(a + b);
//! - FastTwoSum (Dekker 1971), the same for |a| ≥ |b|;
//! - TwoProduct (Dekker 1971) with Veltkamp's splitting a = a_hi + a_lo into 26-bit halves:
//!   a·b = p + e exactly, p = fl(a·b), valid while |a|, |b| < 2⁹⁹⁶ (no overflow in the split).
//!
//! The elliptic module needs it only for the quarter period K(m) (arithmetic-geometric mean,
//! DLMF 19.8.1), so that the Jacobi functions can subtract multiples of 2K from large
//! arguments without losing the digits that a 53-bit K would lose (see `jacobi.rs`).
//! Division and square root take one Newton correction each; all results are accurate to a
//! few units of 2⁻¹⁰⁴ relative.

/// A double-double number `hi + lo`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Dd {
    /// Leading part, the `f64` nearest to the value.
    pub hi: f64,
    /// Trailing part.
    pub lo: f64,
}

/// π/2 as a double-double.
pub(crate) const FRAC_PI_2: Dd = Dd { hi: std::f64::consts::FRAC_PI_2, lo: 6.123233995736766e-17 };

/// Knuth's TwoSum: `a + b` exactly as `s + e`.
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    let bb = s - a;
    Dd { hi: s, lo: (a - (s - bb)) + (b - bb) }
}

/// Dekker's FastTwoSum, valid when |a| ≥ |b| (or a = 0).
#[inline]
fn fast_two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    Dd { hi: s, lo: b - (s - a) }
}

/// Veltkamp's split of `a` into two halves of at most 26 significant bits each.
#[inline]
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a; // 2^27 + 1
    let hi = c - (c - a);
    (hi, a - hi)
}

/// Dekker's TwoProduct: `a·b` exactly as `p + e` (for |a|, |b| < 2⁹⁹⁶).
#[inline]
pub(crate) fn two_prod(a: f64, b: f64) -> Dd {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    Dd { hi: p, lo: ((ah * bh - p) + ah * bl + al * bh) + al * bl }
}

impl Dd {
    /// One as a double-double.
    pub(crate) const ONE: Dd = Dd { hi: 1.0, lo: 0.0 };

    /// Sum (the accurate variant: both trailing parts enter with their own TwoSum).
    #[inline]
    pub(crate) fn add(self, o: Dd) -> Dd {
        let s = two_sum(self.hi, o.hi);
        let t = two_sum(self.lo, o.lo);
        let r = fast_two_sum(s.hi, s.lo + t.hi);
        fast_two_sum(r.hi, r.lo + t.lo)
    }

    /// Difference.
    #[inline]
    pub(crate) fn sub(self, o: Dd) -> Dd {
        self.add(Dd { hi: -o.hi, lo: -o.lo })
    }

    /// Product.
    #[inline]
    pub(crate) fn mul(self, o: Dd) -> Dd {
        let p = two_prod(self.hi, o.hi);
        fast_two_sum(p.hi, p.lo + (self.hi * o.lo + self.lo * o.hi))
    }

    /// Product with an `f64`.
    #[inline]
    fn mul_f64(self, b: f64) -> Dd {
        let p = two_prod(self.hi, b);
        fast_two_sum(p.hi, p.lo + self.lo * b)
    }

    /// Product with a power of two (exact).
    #[inline]
    pub(crate) fn scale(self, f: f64) -> Dd {
        Dd { hi: self.hi * f, lo: self.lo * f }
    }

    /// Quotient: three f64 quotient digits, each from the exact remainder.
    pub(crate) fn div(self, o: Dd) -> Dd {
        let q1 = self.hi / o.hi;
        let r = self.sub(o.mul_f64(q1));
        let q2 = r.hi / o.hi;
        let r = r.sub(o.mul_f64(q2));
        let q3 = r.hi / o.hi;
        fast_two_sum(q1, q2).add(Dd { hi: q3, lo: 0.0 })
    }

    /// Square root of a non-negative value: s = √hi corrected by (x − s²)/(2s).
    pub(crate) fn sqrt(self) -> Dd {
        if self.hi <= 0.0 {
            return Dd { hi: 0.0, lo: 0.0 };
        }
        let s = self.hi.sqrt();
        let p = two_prod(s, s);
        fast_two_sum(s, ((self.hi - p.hi) - p.lo + self.lo) / (2.0 * s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_sum_and_two_prod_are_exact() {
        let s = two_sum(1.0, 1e-20);
        assert_eq!((s.hi, s.lo), (1.0, 1e-20));
        let a = 1.0 + f64::EPSILON;
        let p = two_prod(a, a); // (1 + ε)² = 1 + 2ε + ε²
        assert_eq!((p.hi, p.lo), (1.0 + 2.0 * f64::EPSILON, f64::EPSILON * f64::EPSILON));
    }

    #[test]
    fn sqrt_and_div_reach_double_double_accuracy() {
        // √2 = 1.41421356237309504880168872420969807857 (to 39 digits)
        let r = Dd { hi: 2.0, lo: 0.0 }.sqrt();
        assert_eq!(r.hi, std::f64::consts::SQRT_2);
        assert!((r.lo - (-9.667293313452913e-17)).abs() < 1e-31);
        // 1/3 = 0.3333… : hi = fl(1/3), lo = (1 − 3 hi)/3
        let q = Dd::ONE.div(Dd { hi: 3.0, lo: 0.0 });
        assert_eq!(q.hi, 1.0 / 3.0);
        assert!((q.lo - 1.850371707708594e-17).abs() < 1e-32);
        // (π/2)·(2/π) = 1 to ~1e-32
        let one = FRAC_PI_2.mul(Dd::ONE.div(FRAC_PI_2));
        assert!(((one.hi - 1.0) + one.lo).abs() < 1e-31);
    }
}
