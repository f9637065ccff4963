//! Sizes the effects whose visible size depends on the response: the thermal drift
//! (needs the rubber's loss power) and the Dahl friction (needs the twist amplitude).
//! A one-second pre-run of the truth without the effect measures them, so the effect is
//! sized for visibility in the campaign (issue 14: no invisible, no huge effects).

use crate::draw::Case;
use crate::effects::{Effect, HystereticLaw, Softening, Thermal};
use crate::rng::Rng;
use crate::sim;

/// Completes the sizes of `case.effect` that need a pre-run.
pub fn size_effect(case: &mut Case, rng: &mut Rng) {
    match case.effect.clone() {
        Effect::ThermalDrift { conn, law } => {
            let Some(long) = case
                .campaign
                .recordings
                .iter()
                .position(|r| r.stem == "long-run")
            else {
                return;
            };
            let loss_w = heat_run(case, conn, long);
            let rec = case.campaign.recordings[long].clone();
            let drop = rng.range(0.03, 0.08);
            let dt_k = match law.softening {
                Softening::Exponential { beta_per_k } => -(1.0 - drop).ln() / beta_per_k,
                Softening::Linear { beta_per_k } => drop / beta_per_k,
            };
            let tau = rec.duration_s * rng.range(1.0, 3.0);
            let p = loss_w.max(1e-6);
            let g = p * (1.0 - (-rec.duration_s / tau).exp()) / dt_k;
            let thermal = Thermal {
                capacity_j_per_k: g * tau,
                conductance_w_per_k: g,
                softening: law.softening,
            };
            case.params
                .push(("stiffness_drop_over_long_run".into(), drop));
            case.params.push(("time_constant_s".into(), tau));
            case.params.push(("capacity_j_per_k".into(), g * tau));
            case.effect = Effect::ThermalDrift { conn, law: thermal };
        }
        Effect::Hysteretic {
            conn,
            law: HystereticLaw::Dahl {
                sigma_nm_per_rad, ..
            },
        } => {
            let rec = case.campaign.recordings[case.campaign.recordings.len() / 2].clone();
            let PreRun {
                twist_amplitude_rad: amp,
                twist_rate_rad_s,
                ..
            } = pre_run(case, conn, &rec);
            let (k, psi) = match case.truth.connections[conn].kind {
                crate::driveline::Kind::Rubber { stiffness, psi } => (stiffness, psi),
                _ => (1.0, 1.0),
            };
            // Coulomb loss 4·F_c·A per cycle = ψ·½kA² (DIN 740's relative damping).
            // The sliding torque is floored at 1 % of the spring's torque at that
            // amplitude (an unsized or vanishing Coulomb term would make the state's
            // relaxation rate σ·|Δθ̇|/F_c unbounded: seed 16 diverged at t = 0).
            let f_c = (psi * k * amp / 8.0).max(0.01 * k * amp).max(1e-3);
            case.params.push(("friction_nm".into(), f_c));
            case.effect = Effect::Hysteretic {
                conn,
                law: HystereticLaw::Dahl {
                    f_c_nm: f_c,
                    sigma_nm_per_rad,
                    twist_rate_rad_s,
                },
            };
        }
        _ => {}
    }
}

/// The heat run: a test engineer who looks for a coupling's thermal drift runs the long
/// run where the coupling works hardest, so the long run moves to the speed of the
/// full-load regime where connection `conn` loses most (a pre-run of each), and returns
/// that loss, W. The heat balance sized on it then warms no steady regime more than the
/// long run. Sized on a long run drawn anywhere in the range, as before 2026-12-03, a
/// regime at a resonance lost up to 300 times the long run's power into a capacity sized
/// for the long run: development seed 2116's `regime-b` would have risen 970 K in its
/// 14 s (467 W into 3.7 J/K), seed 2127's `regime-a` 360 K, a coupling far past any
/// rubber's service temperature, while the long run drifted too little to be seen.
fn heat_run(case: &mut Case, conn: usize, long: usize) -> f64 {
    let hottest = case
        .campaign
        .recordings
        .iter()
        .filter(|r| !r.run_up && r.stem != "long-run" && r.load == 1.0)
        .map(|r| (r.from_rpm, pre_run(case, conn, r).loss_w))
        .max_by(|a, b| a.1.total_cmp(&b.1));
    match hottest {
        Some((speed_rpm, loss_w)) => {
            let rec = &mut case.campaign.recordings[long];
            rec.from_rpm = speed_rpm;
            rec.to_rpm = speed_rpm;
            loss_w
        }
        None => pre_run(case, conn, &case.campaign.recordings[long]).loss_w,
    }
}

/// What the pre-run without the effect measures at one connection.
struct PreRun {
    /// Mean rubber loss power, W.
    loss_w: f64,
    /// Twist amplitude, rad (√2·RMS about the mean).
    twist_amplitude_rad: f64,
    /// Twist rate amplitude, rad/s (√2·RMS).
    twist_rate_rad_s: f64,
}

/// Loss power, twist amplitude and twist rate amplitude of connection `conn` over a 1 s
/// run without the effect.
fn pre_run(case: &Case, conn: usize, rec: &crate::campaign::Recording) -> PreRun {
    let mut plain = case.clone();
    plain.effect = Effect::None;
    let short = crate::campaign::Recording {
        duration_s: 1.0,
        from_rpm: rec.from_rpm,
        to_rpm: rec.from_rpm,
        ..rec.clone()
    };
    let plant = sim::plant_for(&plain, &short);
    let c = &case.truth.connections[conn];
    let (from, to, g) = (c.from, c.to, c.lever());
    let n_nodes = case.truth.nodes.len();
    let (mut p, mut s1, mut s2, mut r2, mut n) = (0.0, 0.0, 0.0, 0.0, 0.0);
    sim::run(&case.truth, &plant, 2000.0, |_, y| {
        p += plant.rubber_loss_w(y);
        let d = g * y[from] - y[to];
        let dd = g * y[n_nodes + from] - y[n_nodes + to];
        s1 += d;
        s2 += d * d;
        r2 += dd * dd;
        n += 1.0;
    });
    let var = (s2 / n - (s1 / n).powi(2)).max(0.0);
    PreRun {
        loss_w: p / n,
        twist_amplitude_rad: (2.0 * var).sqrt(),
        twist_rate_rad_s: (2.0 * r2 / n).sqrt(),
    }
}

#[cfg(test)]
mod tests {
    use crate::effects::{Effect, HystereticLaw};
    use crate::sim;

    /// Development seed 2116's heat balance, sized on a long run drawn at 1920 rpm
    /// (1.6 W), would have warmed `regime-b` at 1360 rpm (467 W) by 970 K. Sized on the
    /// heat run, no full-load steady regime loses more than the long run, so none warms
    /// more than the long run's drift asks for.
    #[test]
    fn the_heat_run_is_the_hottest_full_load_regime() {
        let case = crate::draw::draw_case(2116, None).unwrap();
        let Effect::ThermalDrift { conn, law } = case.effect.clone() else {
            panic!("seed 2116 draws thermal drift: {:?}", case.effect);
        };
        let recs = &case.campaign.recordings;
        let long = recs.iter().find(|r| r.stem == "long-run").unwrap();
        let long_w = super::pre_run(&case, conn, long).loss_w;
        let mut regimes = 0;
        for r in recs.iter().filter(|r| !r.run_up && r.load == 1.0) {
            let w = super::pre_run(&case, conn, r).loss_w;
            assert!(
                w <= long_w * (1.0 + 1e-9),
                "{} loses {w} W, the long run {long_w} W",
                r.stem
            );
            regimes += 1;
        }
        assert!(regimes >= 3, "{regimes} full-load regimes");
        // The asymptotic rise of the hottest regime: the long run's, P/G.
        let rise_k = long_w / law.conductance_w_per_k;
        let drop = 1.0 - law.softening.factor(rise_k);
        assert!(drop < 0.5, "the hottest regime would soften by {drop}");
    }

    /// Seed 16 (Dahl friction) diverged at the start of `regime-b` while the RK4 step
    /// ignored the friction state's relaxation rate σ·|Δθ̇|/F_c. Sized now, the plant's
    /// step resolves it (the rate bound is in `fastest_rate`) and the run stays finite.
    #[test]
    fn a_sized_dahl_friction_is_integrated_stably() {
        let case = crate::draw::draw_case(16, None).unwrap();
        let Effect::Hysteretic {
            law:
                HystereticLaw::Dahl {
                    f_c_nm,
                    sigma_nm_per_rad,
                    twist_rate_rad_s,
                },
            ..
        } = case.effect
        else {
            panic!("seed 16 draws Dahl friction: {:?}", case.effect);
        };
        assert!(f_c_nm > 0.0 && twist_rate_rad_s > 0.0);
        let rec = case
            .campaign
            .recordings
            .iter()
            .find(|r| r.stem == "regime-b")
            .unwrap();
        let short = crate::campaign::Recording {
            duration_s: 0.2,
            ..rec.clone()
        };
        let plant = sim::plant_for(&case, &short);
        // The bound: the margin times the sized rate (to rounding).
        let rate = sigma_nm_per_rad * twist_rate_rad_s / f_c_nm;
        assert!(plant.fastest_rate >= 3.0 * rate * (1.0 - 1e-12));
        let mut finite = true;
        sim::run(&case.truth, &plant, 2000.0, |_, y| {
            finite &= y.iter().all(|v| v.is_finite())
        });
        assert!(finite);
    }
}
