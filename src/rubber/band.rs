//! The band over which a model's rubber law is fitted: the frequencies its excitation
//! orders span over its speed range (`spec/model-format.md`, `kind = "rubber"`).
//!
//! The band belongs to the model, not to a run: every view of one model (modes, response,
//! the time domain at any speed) then reads the same chain. It runs from a quarter of the
//! lowest order at the lowest speed (the slow wobble and run-up content below it) to
//! 1.5 × the highest order at the highest speed (seed 000 measured α_f to 300 Hz; the
//! band may reach beyond, where the law is held at its end value).

use crate::model::Model;

/// Speed range used when a model's `[operation]` gives none, rpm: from idle of a large
/// engine to the top of a fast one.
pub const DEFAULT_SPEED_RANGE_RPM: [f64; 2] = [100.0, 3000.0];

/// Lowest band edge, Hz: below it an arm's relaxation is slower than any run settles.
const MIN_BAND_HZ: f64 = 0.1;

/// The speed range the law is fitted for, rpm of the reference node: `[operation]
/// speed_range_rpm`, widened to take in `operating_range_rpm` and every named regime;
/// [`DEFAULT_SPEED_RANGE_RPM`] when none is given.
pub fn law_speed_range_rpm(model: &Model) -> [f64; 2] {
    let op = &model.operation;
    let mut range: Option<[f64; 2]> = op.speed_range_rpm;
    let mut widen = |lo: f64, hi: f64| {
        range = Some(match range {
            None => [lo, hi],
            Some([a, b]) => [a.min(lo), b.max(hi)],
        });
    };
    if let Some([lo, hi]) = op.operating_range_rpm {
        widen(lo, hi);
    }
    for r in &op.regimes {
        widen(r.speed_rpm, r.speed_rpm);
    }
    match range {
        Some([lo, hi]) if lo > 0.0 && hi >= lo => [lo, hi],
        Some([_, hi]) if hi > 0.0 => [hi.min(DEFAULT_SPEED_RANGE_RPM[0]), hi],
        _ => DEFAULT_SPEED_RANGE_RPM,
    }
}

/// The band the model's orders excite over [`law_speed_range_rpm`], Hz: `[¼·q_min·n_min,
/// 1.5·q_max·n_max]/60` over the engine's orders and any prescribed harmonics.
pub fn law_band_hz(model: &Model) -> [f64; 2] {
    let [lo_rpm, hi_rpm] = law_speed_range_rpm(model);
    let orders = model
        .orders()
        .into_iter()
        .chain(model.harmonics.iter().map(|h| h.order))
        .filter(|q| q.is_finite() && *q > 0.0);
    let (q_min, q_max) = orders.fold((f64::INFINITY, 0.0_f64), |(a, b), q| (a.min(q), b.max(q)));
    let (q_min, q_max) = if q_max > 0.0 {
        (q_min, q_max)
    } else {
        (0.5, 12.0)
    };
    let lo = (0.25 * q_min * lo_rpm / 60.0).max(MIN_BAND_HZ);
    let hi = (1.5 * q_max * hi_rpm / 60.0).max(4.0 * lo);
    [lo, hi]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::parse_model;

    const BASE: &str = r#"format = 1
name = "band"
[[inertia]]
name = "a"
inertia = 1.0
[[inertia]]
name = "b"
inertia = 1.0
[[connection]]
name = "s"
kind = "shaft"
from = "a"
to = "b"
stiffness = 1.0e4
"#;

    #[test]
    fn the_band_spans_the_orders_over_the_speed_range() {
        let text =
            format!("{BASE}\n[operation]\nspeed_range_rpm = [600, 2400]\norders = [0.5, 1, 6]\n");
        let model = parse_model(&text, "b.toml").unwrap();
        assert_eq!(law_speed_range_rpm(&model), [600.0, 2400.0]);
        // ¼·0.5·600/60 = 1.25 Hz; 1.5·6·2400/60 = 360 Hz.
        let [lo, hi] = law_band_hz(&model);
        assert!(
            (lo - 1.25).abs() < 1e-12 && (hi - 360.0).abs() < 1e-12,
            "{lo} {hi}"
        );
    }

    #[test]
    fn regimes_widen_the_range_and_a_bare_model_takes_the_default() {
        let text = format!(
            "{BASE}\n[operation]\nspeed_range_rpm = [600, 2400]\nregimes = [{{ label = \"A\", speed_rpm = 3000 }}]\n"
        );
        let model = parse_model(&text, "b.toml").unwrap();
        assert_eq!(law_speed_range_rpm(&model), [600.0, 3000.0]);
        let bare = parse_model(BASE, "b.toml").unwrap();
        assert_eq!(law_speed_range_rpm(&bare), DEFAULT_SPEED_RANGE_RPM);
        // Default orders 0.5 … 12: ¼·0.5·100/60 and 1.5·12·3000/60.
        let [lo, hi] = law_band_hz(&bare);
        assert!((lo - 0.2083333333333333).abs() < 1e-12 && (hi - 900.0).abs() < 1e-12);
    }
}
