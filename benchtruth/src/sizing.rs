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
            let rec = case
                .campaign
                .recordings
                .iter()
                .find(|r| r.stem == "long-run")
                .cloned();
            let Some(rec) = rec else { return };
            let (loss_w, _) = pre_run(case, conn, &rec);
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
            let (_, amp) = pre_run(case, conn, &rec);
            let (k, psi) = match case.truth.connections[conn].kind {
                crate::driveline::Kind::Rubber { stiffness, psi } => (stiffness, psi),
                _ => (1.0, 1.0),
            };
            // Coulomb loss 4·F_c·A per cycle = ψ·½kA² (DIN 740's relative damping).
            let f_c = (psi * k * amp / 8.0).max(1e-3);
            case.params.push(("friction_nm".into(), f_c));
            case.effect = Effect::Hysteretic {
                conn,
                law: HystereticLaw::Dahl {
                    f_c_nm: f_c,
                    sigma_nm_per_rad,
                },
            };
        }
        _ => {}
    }
}

/// Mean rubber loss power (W) and twist amplitude (rad, √2·RMS about the mean) of
/// connection `conn` over a 1 s run without the effect.
fn pre_run(case: &Case, conn: usize, rec: &crate::campaign::Recording) -> (f64, f64) {
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
    let (mut p, mut s1, mut s2, mut n) = (0.0, 0.0, 0.0, 0.0);
    sim::run(&case.truth, &plant, 2000.0, |_, y| {
        p += plant.rubber_loss_w(y);
        let d = g * y[from] - y[to];
        s1 += d;
        s2 += d * d;
        n += 1.0;
    });
    let var = (s2 / n - (s1 / n).powi(2)).max(0.0);
    (p / n, (2.0 * var).sqrt())
}
