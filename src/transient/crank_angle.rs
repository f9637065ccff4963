//! Angle arithmetic of the engine's right-hand side ([`super::forces`]), which runs six
//! or more times per step for every cylinder: the crank angle wrapped to the working
//! cycle, and the sine and cosine of the crank angle.
//!
//! Written here rather than taken from `libm`: between evaluations the crank angle moves
//! little, and the series of that small move, with multiplications only and short
//! dependency chains, is cheaper than a general `sincos` with its argument reduction. (A
//! table of π/8 steps for the mean crank angle within the cycle was tried too: no faster
//! than `libm`'s `sincos` on the cng-genset run-up, 289 against 290 ms, so not kept.)

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

/// The sine and cosine of the crank angle, from the last one worked out exactly: a
/// Dormand–Prince step evaluates the right-hand side six times within a few hundredths
/// of a radian of crank angle, so each evaluation adds its small offset from that anchor
/// by the angle-addition formulas ([`series_sin_cos`]) instead of calling `sincos` (13 %
/// of a thermal-drift diagnosis's time, `perf`, 2026-12-02). A fresh anchor is taken
/// when the angle is 0.25 rad or more away (the cycle's wrap included). The result is the
/// library's within a few ulp, and a run's is reproducible: the anchor is scratch of that
/// run alone ([`super::forces::Scratch`]).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct CrankAnchor {
    /// The anchor's angle, rad, with its sine and cosine; `None` before the first.
    at: Option<(f64, f64, f64)>,
}

impl CrankAnchor {
    /// Sine and cosine of `angle`, rad.
    #[inline]
    pub(super) fn sin_cos(&mut self, angle: f64) -> (f64, f64) {
        if let Some((a, s_a, c_a)) = self.at {
            let d = angle - a;
            if d.abs() < 0.25 {
                let (s_d, c_d) = series_sin_cos(d);
                return (s_a * c_d + c_a * s_d, c_a * c_d - s_a * s_d);
            }
        }
        let (s, c) = angle.sin_cos();
        self.at = Some((angle, s, c));
        (s, c)
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

    /// Angles walked in small and large steps, across the anchor's reach and back: within
    /// 4e-16 of the library (its own rounding and the series' truncation, 2e-17).
    #[test]
    fn the_anchor_matches_the_library() {
        let mut anchor = CrankAnchor::default();
        let mut angle: f64 = 0.0;
        for i in 0..20_000 {
            angle += if i % 97 == 0 { 1.3 } else { 0.0123 };
            if angle > 12.0 {
                angle -= 12.5;
            }
            let (s, c) = anchor.sin_cos(angle);
            assert!(
                (s - angle.sin()).abs() < 4e-16 && (c - angle.cos()).abs() < 4e-16,
                "{angle}"
            );
        }
    }

    #[test]
    fn wrap_takes_angles_into_the_cycle() {
        assert!((wrap(-0.5, 4.0) - 3.5).abs() < 1e-15 && (wrap(4.5, 4.0) - 0.5).abs() < 1e-15);
        assert!((wrap(-9.0, 4.0) - 3.0).abs() < 1e-15 && (wrap(13.0, 4.0) - 1.0).abs() < 1e-15);
    }
}
