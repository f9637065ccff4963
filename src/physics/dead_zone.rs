//! The mesh deflection of a gear with free play: the dead zone that turns the twist δ
//! across the mesh (rad at its `to` side) into the deflection its mesh stiffness acts on.
//!
//! - **Hard contact** (ε = 0): s(δ) = δ − h beyond the play, δ + h below it, 0 inside.
//! - **Softened contact** (ε > 0): the hyperbolic smoothing of the dead zone used for
//!   gear rattle, s(δ) = ½[(δ−h) + √((δ−h)² + ε²)] + ½[(δ+h) − √((δ+h)² + ε²)]. The
//!   contact stiffness is half the mesh stiffness where the play closes and 95 % of it
//!   2ε further on; inside the play a little torque already passes, of order
//!   k·ε²/4(h−|δ|) near an edge. A tooth contact is not hard: Hertzian flattening,
//!   profile errors and the oil film make its stiffness rise over a few µrad to mrad of
//!   further twist.
//!
//! Each form is continuous with its slope (the softened one everywhere, the hard one
//! except at ±h), and odd in δ. The time domain applies the law
//! ([`crate::transient::forces`]); the linear model takes its tangent at the static
//! torque ([`contact_point`], [`crate::physics::System::new`]), so that every view of a
//! softened contact has the same stiffness about its working point.

/// The mesh deflection for twist `d` (rad) with half play `half_gap_rad` and softening
/// width `softening_rad` (both rad, ≥ 0; ε = 0 is the hard dead zone).
#[inline]
pub(crate) fn dead_zone(d: f64, half_gap_rad: f64, softening_rad: f64) -> f64 {
    if softening_rad > 0.0 {
        let e2 = softening_rad * softening_rad;
        let (above, below) = (d - half_gap_rad, d + half_gap_rad);
        0.5 * (above + (above * above + e2).sqrt()) + 0.5 * (below - (below * below + e2).sqrt())
    } else if d > half_gap_rad {
        d - half_gap_rad
    } else if d < -half_gap_rad {
        d + half_gap_rad
    } else {
        0.0
    }
}

/// The slope ds/dδ of the softened dead zone at twist `d` (ε > 0).
fn softened_slope(d: f64, half_gap_rad: f64, softening_rad: f64) -> f64 {
    let e2 = softening_rad * softening_rad;
    let (above, below) = (d - half_gap_rad, d + half_gap_rad);
    0.5 * (1.0 + above / (above * above + e2).sqrt())
        + 0.5 * (1.0 - below / (below * below + e2).sqrt())
}

/// Where a softened contact (ε > 0) of half play `half_gap_rad` works when it passes a
/// mean deflection `s` = T/k (rad, the torque over the mesh stiffness): the twist δ with
/// s(δ) = `s`, and the slope s'(δ) there, the share of the mesh stiffness that acts on
/// small vibrations about it. `None` for a hard contact (ε = 0), whose tangent is the
/// mesh stiffness once the flanks touch.
///
/// s is strictly increasing (s' > 0 everywhere for ε > 0), so bisection on a bracket
/// that is widened until it holds `s` finds δ to the last bits in ≤ 200 halvings.
pub(crate) fn contact_point(s: f64, half_gap_rad: f64, softening_rad: f64) -> Option<(f64, f64)> {
    if softening_rad <= 0.0 || !s.is_finite() {
        return None;
    }
    let f = |d: f64| dead_zone(d, half_gap_rad, softening_rad) - s;
    let mut width = half_gap_rad + softening_rad + s.abs();
    let (mut lo, mut hi) = (s - width, s + width);
    while f(lo) > 0.0 || f(hi) < 0.0 {
        width *= 2.0;
        (lo, hi) = (s - width, s + width);
        if !width.is_finite() {
            return None;
        }
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if f(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let d = 0.5 * (lo + hi);
    Some((d, softened_slope(d, half_gap_rad, softening_rad)))
}

#[cfg(test)]
mod tests {
    use super::{contact_point, dead_zone};

    const H: f64 = 1e-3;
    const EPS: f64 = 2e-4;

    /// The slope of `dead_zone` at `d`, by a central difference of step 1e-9 rad (its
    /// truncation error ~ (1e-9/ε)² ≤ 1e-8 for ε ≥ 1e-5).
    fn slope(d: f64, e: f64) -> f64 {
        (dead_zone(d + 1e-9, H, e) - dead_zone(d - 1e-9, H, e)) / 2e-9
    }

    #[test]
    fn the_hard_dead_zone_is_exact() {
        assert_eq!(dead_zone(0.5 * H, H, 0.0), 0.0);
        assert_eq!(dead_zone(-H, H, 0.0), 0.0);
        assert_eq!(dead_zone(3.0 * H, H, 0.0), 2.0 * H);
        assert_eq!(dead_zone(-3.0 * H, H, 0.0), -2.0 * H);
    }

    #[test]
    fn the_softened_dead_zone_is_odd_and_tends_to_the_hard_one() {
        for d in [0.0, 0.3 * H, H, 1.7 * H, 10.0 * H] {
            assert_eq!(dead_zone(-d, H, EPS), -dead_zone(d, H, EPS));
        }
        // Far from the play the gap to the hard law is the two hyperbolas' distance to
        // their asymptotes, ε²/4x − ε⁴/16x³ at the near edge (x = δ − h) less the same
        // at the far one (δ + h); the series' next terms are ~(ε/x)⁴ = 6e-6 of it.
        let far = H + 20.0 * EPS;
        let gap = dead_zone(far, H, EPS) - dead_zone(far, H, 0.0);
        let tail = |x: f64| EPS.powi(2) / (4.0 * x) - EPS.powi(4) / (16.0 * x.powi(3));
        let expected = tail(far - H) - tail(far + H);
        assert!(
            (gap - expected).abs() < 1e-4 * expected,
            "{gap} against {expected}"
        );
    }

    #[test]
    fn the_contact_stiffness_is_half_at_the_play_and_95_percent_two_widths_on() {
        // ½(1 + x/√(x² + ε²)) at x = 0 and x = 2ε; with ε = h/100 the far edge adds
        // ½(1 − 2h/√(4h² + ε²)) ≈ (ε/2h)²/4 = 6e-6.
        let eps = 1e-2 * H;
        assert!((slope(H, eps) - 0.5).abs() < 1e-5);
        let at_two = 0.5 * (1.0 + 2.0 / 5f64.sqrt());
        assert!((slope(H + 2.0 * eps, eps) - at_two).abs() < 1e-5);
        assert!(at_two > 0.947 && at_two < 0.948);
        // and with no play the law is the straight line (h = 0: the two halves cancel).
        assert!((dead_zone(3e-4, 0.0, EPS) - 3e-4).abs() < 1e-15);
    }

    #[test]
    fn the_contact_point_inverts_the_law_and_gives_its_slope() {
        assert_eq!(contact_point(1e-4, H, 0.0), None);
        for s in [-3.0 * H, -1e-5, 0.0, 1e-6, 1e-4, 2.0 * H] {
            let (d, slope) = contact_point(s, H, EPS).unwrap();
            assert!((dead_zone(d, H, EPS) - s).abs() < 1e-15, "s = {s}");
            let numeric = (dead_zone(d + 1e-9, H, EPS) - dead_zone(d - 1e-9, H, EPS)) / 2e-9;
            assert!((slope - numeric).abs() < 1e-6, "{slope} against {numeric}");
        }
        // Far into contact the tangent is the mesh stiffness (to ε²/4x² ≈ 6e-4 at x = 20ε),
        // and a light torque works on the soft edge: s = ε/10 sits 1.788ε short of the
        // play's edge (the far edge's pull included), where 6.73 % of it acts (computed
        // apart, in double precision, by bisection and the slope's formula).
        assert!(contact_point(20.0 * EPS, H, EPS).unwrap().1 > 0.999);
        let (d, light) = contact_point(0.1 * EPS, H, EPS).unwrap();
        assert!(((d - H) / EPS + 1.787_866).abs() < 1e-5, "{d}");
        assert!((light - 0.067_288).abs() < 1e-5, "{light}");
    }
}
