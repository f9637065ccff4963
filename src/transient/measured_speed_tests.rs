//! The measured trajectory against cases with exact answers: a straight ramp is
//! reproduced exactly, the angle is the speed's integral, the acceleration its
//! derivative, and a lingering run is followed.

use super::*;

/// Window centres every 0.05 s (0.1 s windows at half overlap) over `duration_s`, with
/// the speed `f(t)` rpm at each.
fn windows(duration_s: f64, f: impl Fn(f64) -> f64) -> (Vec<f64>, Vec<f64>) {
    let times: Vec<f64> = (0..)
        .map(|k| 0.05 + 0.05 * k as f64)
        .take_while(|t| *t <= duration_s - 0.05)
        .collect();
    let speeds = times.iter().map(|t| f(*t)).collect();
    (times, speeds)
}

/// A bench run that lingers: a 37 rpm/s ramp from 760 rpm that stays at 860 rpm from
/// 2.7 to 4.5 s and catches up with the ramp by 5 s (piecewise linear).
fn lingering(t: f64) -> f64 {
    let clamp01 = |x: f64| x.clamp(0.0, 1.0);
    760.0 + 37.0 * t - 66.6 * clamp01((t - 2.7) / 1.8) + 66.6 * clamp01((t - 4.5) / 0.5)
}

#[test]
fn a_straight_ramp_is_reproduced_exactly() {
    let (times, speeds) = windows(10.0, |t| 800.0 + 37.0 * t);
    let m = MeasuredSpeed::from_windows(&times, &speeds).expect("long enough");
    assert!(m.departure_from_line() < 1e-12 && !m.departs());
    let to_rad = TAU / 60.0;
    for t in [0.0, 0.05, 1.3, 4.99, 9.95, 11.0] {
        let (angle, speed, accel) = m.at(t);
        // From the first knot at 0.05 s: ω(t) = ω(0.05) + α (t − 0.05).
        let dt = t - 0.05;
        let w0 = (800.0 + 37.0 * 0.05) * to_rad;
        let alpha = 37.0 * to_rad;
        assert!((speed - (w0 + alpha * dt)).abs() < 1e-9, "speed at {t}");
        assert!((accel - alpha).abs() < 1e-9, "accel at {t}");
        assert!(
            (angle - (w0 * dt + 0.5 * alpha * dt * dt)).abs() < 1e-9,
            "angle at {t}"
        );
    }
}

#[test]
fn the_angle_is_the_integral_and_the_acceleration_the_derivative() {
    let (times, speeds) = windows(8.0, lingering);
    let m = MeasuredSpeed::from_windows(&times, &speeds).expect("long enough");
    let (t0, t1, n) = (-0.2, 8.3, 170_000);
    let h = (t1 - t0) / n as f64;
    let mut angle = m.at(t0).0;
    for i in 0..n {
        let (a, b) = (t0 + i as f64 * h, t0 + (i + 1) as f64 * h);
        // Simpson on each step: exact for the cubic pieces away from a knot.
        angle += h / 6.0 * (m.at(a).1 + 4.0 * m.at(0.5 * (a + b)).1 + m.at(b).1);
        if i % 997 == 0 {
            let d = (m.at(b + 1e-6).1 - m.at(b - 1e-6).1) / 2e-6;
            assert!((d - m.at(b).2).abs() < 1e-3 * (1.0 + d.abs()), "α at {b}");
        }
    }
    assert!(
        (angle - m.at(t1).0).abs() < 1e-9 * angle.abs(),
        "{angle} vs {}",
        m.at(t1).0
    );
}

#[test]
fn a_lingering_run_is_followed() {
    let (times, speeds) = windows(8.0, lingering);
    let m = MeasuredSpeed::from_windows(&times, &speeds).expect("long enough");
    // Half a second from every corner, each knot's line and both of a piece's knots lie on
    // one straight stretch: exact. The stall is there: 859.9 rpm at 3.6 s, where the
    // straight line between the run's ends has 893.
    for t in [1.0, 3.6, 6.0, 7.0] {
        let e = (m.speed_rpm(t) - lingering(t)).abs();
        assert!(e < 1e-9, "{t} s: {} vs {}", m.speed_rpm(t), lingering(t));
    }
    assert!((m.speed_rpm(3.6) - 859.9).abs() < 1e-9);
    // 60 rpm behind the line at the end of the plateau, on a mean of ~900 rpm.
    assert!(m.departure_from_line() > 0.03 && m.departs());
    // Through the corners a 0.5 s line rounds them: a line fitted across a corner of
    // slope change Δ over span S misses it by Δ·S/8, 170 rpm/s · 0.5 s / 8 = 10.6 rpm at
    // the catch-up's start (0 to 170 rpm/s), and the catch-up's end lies in the same
    // span: 11.2 rpm found, 12 allowed.
    for k in 0..=160 {
        let t = 0.05 * k as f64;
        let e = m.speed_rpm(t) - lingering(t);
        assert!(e.abs() < 12.0, "{t} s: {e}");
    }
    assert!((m.max_speed_rpm(0.0, 8.0) - m.speed_rpm(8.0)).abs() < 1e-9);
}

#[test]
fn too_short_or_ragged_windows_give_none() {
    let (times, speeds) = windows(0.4, |_| 1000.0);
    assert!(MeasuredSpeed::from_windows(&times, &speeds).is_none());
    assert!(MeasuredSpeed::from_windows(&[], &[]).is_none());
    let (times, speeds) = windows(5.0, |_| 1000.0);
    assert!(MeasuredSpeed::from_windows(&times, &speeds[1..]).is_none());
}
