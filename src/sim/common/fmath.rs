//! The simulation's transcendental functions, the same bits on every platform.
//!
//! `f32::sin`, `exp`, `powf`, `atan2` and the like call the platform's maths
//! library: glibc's on native Linux, Rust's port of musl's (the `libm` crate,
//! inside `compiler-builtins`) on wasm32. The two differ in the last bit for
//! some arguments, and a school of fish amplifies one bit into a different
//! run: the browser and `shoal-lab` then wrote different CSVs for the same
//! experiment. Every function here calls the `libm` crate instead, which is
//! plain Rust arithmetic (IEEE-754 `+ - × ÷ √`, exactly rounded everywhere), so
//! a run gives the same numbers natively and in the browser. glam is built
//! with its `libm` feature for the same reason (its rotations and angles).
//!
//! `clippy.toml` forbids the `std` versions (`disallowed-methods`) in every
//! module a run's numbers depend on; the renderer and the UI, which only draw,
//! are exempt in `lib.rs`. `sqrt`, `abs`, `floor`, `round`, `mul_add`,
//! `to_radians` and `to_degrees` are exactly rounded (or a multiplication by a
//! constant) on every platform and stay as they are. `powi` is here too
//! ([`powi`]): LLVM may call a runtime helper for it, so it is written out.
//!
//! The `f64` versions carry a `_f64` suffix.

/// Sine (radians).
#[inline]
pub fn sin(x: f32) -> f32 {
    libm::sinf(x)
}

/// Cosine (radians).
#[inline]
pub fn cos(x: f32) -> f32 {
    libm::cosf(x)
}

/// `(sin x, cos x)`, as `f32::sin_cos` returns them.
#[inline]
pub fn sin_cos(x: f32) -> (f32, f32) {
    libm::sincosf(x)
}

/// Tangent (radians).
#[inline]
pub fn tan(x: f32) -> f32 {
    libm::tanf(x)
}

/// Arcsine, in [-π/2, π/2] (NaN outside [-1, 1]: clamp first).
#[inline]
pub fn asin(x: f32) -> f32 {
    libm::asinf(x)
}

/// Arccosine, in [0, π] (NaN outside [-1, 1]: clamp first).
#[inline]
pub fn acos(x: f32) -> f32 {
    libm::acosf(x)
}

/// The angle of the point (x, y), in (-π, π]; `atan2(y, x)` is `y.atan2(x)`.
#[inline]
pub fn atan2(y: f32, x: f32) -> f32 {
    libm::atan2f(y, x)
}

/// Hyperbolic tangent.
#[inline]
pub fn tanh(x: f32) -> f32 {
    libm::tanhf(x)
}

/// eˣ.
#[inline]
pub fn exp(x: f32) -> f32 {
    libm::expf(x)
}

/// Natural logarithm.
#[inline]
pub fn ln(x: f32) -> f32 {
    libm::logf(x)
}

/// xʸ for a real exponent.
#[inline]
pub fn powf(x: f32, y: f32) -> f32 {
    libm::powf(x, y)
}

/// Cube root.
#[inline]
pub fn cbrt(x: f32) -> f32 {
    libm::cbrtf(x)
}

/// √(x² + y²) without overflow, `x.hypot(y)`.
#[inline]
pub fn hypot(x: f32, y: f32) -> f32 {
    libm::hypotf(x, y)
}

/// xⁿ for a whole exponent, by repeated squaring (the multiplications LLVM
/// itself writes for a constant exponent, in the same order), so no runtime
/// helper of the platform is called. A negative exponent gives 1 / x⁻ⁿ.
#[inline]
pub fn powi(x: f32, n: i32) -> f32 {
    let p = powi_unsigned(x, n.unsigned_abs(), |a, b| a * b, 1.0);
    if n < 0 { 1.0 / p } else { p }
}

/// Sine (radians), `f64`.
#[inline]
pub fn sin_f64(x: f64) -> f64 {
    libm::sin(x)
}

/// Cosine (radians), `f64`.
#[inline]
pub fn cos_f64(x: f64) -> f64 {
    libm::cos(x)
}

/// `atan2(y, x)`, `f64`.
#[inline]
pub fn atan2_f64(y: f64, x: f64) -> f64 {
    libm::atan2(y, x)
}

/// √(x² + y²), `f64`.
#[inline]
pub fn hypot_f64(x: f64, y: f64) -> f64 {
    libm::hypot(x, y)
}

/// Decimal logarithm, `f64`.
#[inline]
pub fn log10_f64(x: f64) -> f64 {
    libm::log10(x)
}

/// xⁿ for a whole exponent, `f64` (see [`powi`]).
#[inline]
pub fn powi_f64(x: f64, n: i32) -> f64 {
    let p = powi_unsigned(x, n.unsigned_abs(), |a, b| a * b, 1.0);
    if n < 0 { 1.0 / p } else { p }
}

/// Repeated squaring: the running square is multiplied into the result for
/// every set bit of `n`, lowest first (LLVM's expansion of `powi`).
#[inline]
fn powi_unsigned<T: Copy>(x: T, mut n: u32, mul: impl Fn(T, T) -> T, one: T) -> T {
    let mut result: Option<T> = None;
    let mut square = x;
    while n > 0 {
        if n & 1 == 1 {
            result = Some(match result {
                Some(r) => mul(r, square),
                None => square,
            });
        }
        n >>= 1;
        if n > 0 {
            square = mul(square, square);
        }
    }
    result.unwrap_or(one)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_functions_agree_with_the_platform_to_within_one_unit_in_the_last_place() {
        #![allow(clippy::disallowed_methods)] // comparing with std on purpose
        let ulp = |a: f32, b: f32| (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs();
        for k in -400..=400 {
            let x = k as f32 * 0.0173;
            assert!(ulp(sin(x), x.sin()) <= 1, "sin {x}");
            assert!(ulp(cos(x), x.cos()) <= 1, "cos {x}");
            assert_eq!(sin_cos(x), (sin(x), cos(x)), "sin_cos {x}");
            assert!(ulp(atan2(x, 0.7), x.atan2(0.7)) <= 1, "atan2 {x}");
            assert!(ulp(exp(x * 0.1), (x * 0.1).exp()) <= 1, "exp {x}");
            assert!(ulp(cbrt(x), x.cbrt()) <= 1, "cbrt {x}");
            assert!(ulp(hypot(x, 1.3), x.hypot(1.3)) <= 1, "hypot {x}");
            let y = (k as f32 * 0.0025).clamp(-1.0, 1.0);
            assert!(ulp(asin(y), y.asin()) <= 1, "asin {y}");
            assert!(ulp(acos(y), y.acos()) <= 1, "acos {y}");
            if x > 0.0 {
                assert!(ulp(ln(x), x.ln()) <= 1, "ln {x}");
                assert!(ulp(powf(x, 0.8), x.powf(0.8)) <= 1, "powf {x}");
            }
        }
        assert!((log10_f64(1000.0) - 3.0).abs() < 1e-15);
        assert!((hypot_f64(3.0, 4.0) - 5.0).abs() < 1e-15);
    }

    #[test]
    fn powi_is_the_product_of_its_factors() {
        #![allow(clippy::disallowed_methods)] // comparing with std on purpose
        for &x in &[0.0f32, 1.0, -1.5, 0.9983, 3.25, 1e-3] {
            for n in -8..=64 {
                let expected = x.powi(n);
                let got = powi(x, n);
                assert!(
                    got == expected || (got - expected).abs() <= expected.abs() * 1e-6,
                    "{x}^{n}: {got} vs {expected}"
                );
                let (got64, expected64) = (powi_f64(f64::from(x), n), f64::from(x).powi(n));
                assert!(
                    got64 == expected64 || (got64 - expected64).abs() <= expected64.abs() * 1e-12,
                    "{x}^{n} (f64)"
                );
            }
        }
        assert_eq!(powi(1.5, 2), 1.5 * 1.5);
        assert_eq!(powi(1.5, 3), 1.5 * 1.5 * 1.5);
        assert_eq!(powi(2.0, -2), 0.25);
        assert_eq!(powi(7.0, 0), 1.0);
    }
}
