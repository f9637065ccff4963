//! Runs the truth for one recording: settles at the start speed, then samples the
//! stations' angle and speed on the DAQ's grid (issue 14, item 5: a run-up starts settled).

use crate::draw::Case;
use crate::driveline::Driveline;
use crate::integrate::Rk4;
use crate::plant::{Band, Plant, Profile};
use std::f64::consts::TAU;

/// The RK4 step: at most 1/40 of the shortest natural period (rubbers counted 4× stiffer
/// to cover friction and amplitude stiffening), at most 0.5/λ_max of the fastest Maxwell
/// branch or Dahl friction state (`plant.rs`, `DAHL_RATE_MARGIN`), and an integer
/// fraction of the sample interval.
pub fn step_s(truth: &Driveline, plant: &Plant, sample_s: f64) -> f64 {
    let mut stiff = truth.clone();
    for c in &mut stiff.connections {
        if let crate::driveline::Kind::Rubber { stiffness, .. } = &mut c.kind {
            *stiffness *= 4.0;
        }
    }
    let f_max = stiff.modes().freq_hz.last().copied().unwrap_or(100.0);
    let h = (1.0 / (40.0 * f_max)).min(0.5 / plant.fastest_rate.max(1e-9));
    sample_s / (sample_s / h).ceil()
}

/// Puts the static twist of the mean engine torque into `y` (load node held).
fn static_twist(d: &Driveline, t_mean: f64, y: &mut [f64]) {
    for (a, x) in y.iter_mut().zip(d.static_angles(t_mean)) {
        *a += x;
    }
}

/// Simulates `plant` over `settle + duration` and calls `each(t_rec, y)` at every sample
/// from the end of settling on (t_rec from 0).
pub fn run(truth: &Driveline, plant: &Plant, rate_hz: f64, mut each: impl FnMut(f64, &[f64])) {
    let sample_s = 1.0 / rate_hz;
    let h = step_s(truth, plant, sample_s);
    let per = (sample_s / h).round() as usize;
    let mut y = plant.initial_state();
    static_twist(truth, plant.mean_torque(), &mut y);
    let mut rk = Rk4::new(y.len());
    let settle_steps = (plant.profile.settle_s / sample_s).round() as usize * per;
    let mut t = 0.0;
    for i in 0..settle_steps {
        rk.step(plant, t, h, &mut y);
        t = (i + 1) as f64 * h;
    }
    let n_samples = (plant.profile.duration_s * rate_hz).round() as usize;
    let t0 = t;
    for s in 0..n_samples {
        each(s as f64 * sample_s, &y);
        for k in 0..per {
            rk.step(plant, t, h, &mut y);
            t = t0 + (s * per + k + 1) as f64 * h;
        }
    }
}

/// The band over which the rubber laws of `case` are fitted, Hz: the model file's, the
/// same for every recording (`fitpoints.rs`), so that for the `none` control the bench
/// integrates the model file's law as every analysis of the model file represents it.
pub fn band(case: &Case) -> Band {
    let (lo, hi) = crate::fitpoints::speed_range_rpm(&case.campaign);
    crate::fitpoints::model_band(lo, hi)
}

/// The plant of one recording of `case`.
pub fn plant_for(case: &Case, rec: &crate::campaign::Recording) -> Plant {
    let w1 = TAU * case.modes_hz.first().copied().unwrap_or(10.0);
    let settle = (4.0 / (case.zeta1 * w1)).clamp(1.0, 8.0);
    let profile = Profile {
        settle_s: settle,
        from_rpm: rec.from_rpm,
        to_rpm: rec.to_rpm,
        duration_s: rec.duration_s,
        wobble: case.campaign.wobble,
        wobble_period_s: case.campaign.wobble_period_s,
        wobble_phase: (rec.from_rpm * 0.37).rem_euclid(TAU),
    };
    Plant::new(&case.truth, &case.effect, rec.load, profile, band(case))
}
