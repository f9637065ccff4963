//! Angle arithmetic of the engine's right-hand side ([`super::forces`]), which runs six
//! or more times per step for every cylinder: the crank angle wrapped to the working
//! cycle, and the sine and cosine of a vibration angle.
//!
//! Written here rather than taken from `libm`: the vibration angle is small, and its
//! series, with multiplications only and short dependency chains, is cheaper than a
//! general `sincos` with its argument reduction. (A table of π/8 steps for the mean crank
//! angle within the cycle was tried too: no faster than `libm`'s `sincos` on the
//! cng-genset run-up, 289 against 290 ms, so not kept.)

/// `x` wrapped into `[0, cycle)` when it is within one cycle of it (the usual case).
#[inline]
pub(super) fn wrap(x: f64, cycle: f64) -> f64 {
    if x < 0.0 {
        if x + cycle >= 0.0 {
            x + cycle
        } else {
            x.rem_euclid(cycle)
        }
    } else if x >= cycle {
        if x - cycle < cycle {
            x - cycle
        } else {
            x.rem_euclid(cycle)
        }
    } else {
        x
    }
}

/// Sine and cosine of a vibration angle, rad: their Taylor series for |x| < 0.25
/// ([`series_sin_cos`]), the library's beyond.
#[inline]
pub(super) fn small_sin_cos(x: f64) -> (f64, f64) {
    if x.abs() < 0.25 {
        series_sin_cos(x)
    } else {
        x.sin_cos()
    }
}

/// Their Taylor series through x¹¹ and x¹² (truncation below 2e-17 relative for |x| <
/// 0.25). The coefficients are the reciprocal factorials, multiplied in: the nested form
/// took 11 divisions per cylinder and evaluation (with the right-hand side's other
/// divisions gone too, the cng-genset run-up went from 371 to 303 ms).
#[inline(always)]
fn series_sin_cos(x: f64) -> (f64, f64) {
    const S: [f64; 5] = [
        -1.0 / 6.0,
        1.0 / 120.0,
        -1.0 / 5040.0,
        1.0 / 362_880.0,
        -1.0 / 39_916_800.0,
    ];
    const C: [f64; 6] = [
        -1.0 / 2.0,
        1.0 / 24.0,
        -1.0 / 720.0,
        1.0 / 40_320.0,
        -1.0 / 3_628_800.0,
        1.0 / 479_001_600.0,
    ];
    // Estrin's scheme: short dependency chains (the cylinders' calls overlap).
    let x2 = x * x;
    let x4 = x2 * x2;
    let x8 = x4 * x4;
    let s = (S[0] + S[1] * x2) + x4 * (S[2] + S[3] * x2) + x8 * S[4];
    let c = (C[0] + C[1] * x2) + x4 * (C[2] + C[3] * x2) + x8 * (C[4] + C[5] * x2);
    (x + x * x2 * s, 1.0 + x2 * c)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The series alone over ±0.3 rad (beyond its 0.25): within 2e-16 of the library.
    #[test]
    fn the_series_matches_the_library() {
        for i in -1000..=1000 {
            let x = 0.3 * i as f64 / 1000.0;
            let (s, c) = series_sin_cos(x);
            assert!(
                (s - x.sin()).abs() < 2e-16 && (c - x.cos()).abs() < 2e-16,
                "{x}"
            );
        }
    }

    #[test]
    fn wrap_takes_angles_into_the_cycle() {
        assert!((wrap(-0.5, 4.0) - 3.5).abs() < 1e-15 && (wrap(4.5, 4.0) - 0.5).abs() < 1e-15);
        assert!((wrap(-9.0, 4.0) - 3.0).abs() < 1e-15 && (wrap(13.0, 4.0) - 1.0).abs() < 1e-15);
    }
}
