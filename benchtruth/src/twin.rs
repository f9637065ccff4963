//! A case's *twin*: the truth as drawn, with the same driveline and plain parameters, but
//! without its concealed effect (for a local mode, the extra inertia lumped onto its
//! host; for the crank's variable inertia, its mean; for hysteretic damping, the dashpot
//! the user's model has; for a sensor artefact, a perfect sensor). [`crate::visibility`]
//! compares the two over the same campaign.

use crate::draw::Case;
use crate::driveline::Kind;
use crate::effects::Effect;
use crate::order_meter::{OrderMeter, meter_for};
use crate::sim;
use std::f64::consts::TAU;

/// The truth of `case` without its effect (see the module doc): for hysteretic damping,
/// the stage as the user's model has it, a spring with a dashpot; `None` for the
/// controls, which have no effect to show.
pub fn twin(case: &Case) -> Option<Case> {
    let mut t = case.clone();
    t.effect = Effect::None;
    match &case.effect {
        Effect::None | Effect::ParameterError => return None,
        Effect::Hysteretic { conn, .. } => {
            // The user's dashpot for the stage, with the truth's stiffness, at the first
            // mode the draw gave the user's model.
            let f1 = case.modes_hz.first().copied()?;
            let c = &mut t.truth.connections[*conn];
            if let Kind::Rubber { stiffness, psi } = c.kind {
                c.kind = Kind::user_dashpot(stiffness, psi, f1);
            }
        }
        Effect::UnmodelledMode { host } => {
            let extra = t.truth.nodes.pop()?;
            t.truth.connections.pop()?;
            t.truth.nodes[*host].inertia_kg_m2 += extra.inertia_kg_m2;
        }
        Effect::CrankVariableInertia { .. } => {
            let e = &t.truth.engine;
            let lam = e.crank_radius_m / e.conrod_m;
            let mean = e.firing_deg.len() as f64
                * e.reciprocating_kg
                * e.crank_radius_m.powi(2)
                * (0.5 + lam * lam / 8.0);
            let node = e.node;
            t.truth.engine.reciprocating_kg = 0.0;
            t.truth.nodes[node].inertia_kg_m2 += mean;
        }
        _ => {}
    }
    let n = t.truth.nodes.len();
    t.campaign.stations.iter().all(|s| s.node < n).then_some(t)
}

/// The twin's order sums of recording `idx` (noise-free, a perfect sensor).
pub fn twin_meter(twin: &Case, idx: usize) -> OrderMeter {
    let rec = &twin.campaign.recordings[idx];
    let c = &twin.campaign;
    let plant = sim::plant_for(twin, rec);
    let n_nodes = plant.n;
    let mut meter = meter_for(twin, idx);
    let crank = twin.truth.engine.node;
    let mut rpm = vec![0.0; c.stations.len()];
    sim::run(&twin.truth, &plant, c.rate_hz, |_, y| {
        for (v, s) in rpm.iter_mut().zip(&c.stations) {
            *v = y[n_nodes + s.node] * 60.0 / TAU;
        }
        meter.add(y[crank], &rpm);
    });
    meter
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A control has no twin; a local mode's twin carries the extra inertia on its host
    /// (the driveline's total inertia is kept); the crank's twin carries the mean of the
    /// reciprocating inertia and no reciprocating mass.
    #[test]
    fn twins_keep_the_inertia_and_drop_the_effect() {
        let total = |c: &Case| c.truth.nodes.iter().map(|n| n.inertia_kg_m2).sum::<f64>();
        let none = crate::draw::draw_case(2002, None).unwrap();
        assert!(twin(&none).is_none());
        let local = crate::draw::draw_case(2008, None).unwrap();
        let t = twin(&local).unwrap();
        assert_eq!(t.truth.nodes.len() + 1, local.truth.nodes.len());
        assert!((total(&t) / total(&local) - 1.0).abs() < 1e-12);
        assert!(matches!(t.effect, Effect::None));
        let crank = crate::draw::draw_case(2009, None).unwrap();
        let t = twin(&crank).unwrap();
        assert_eq!(t.truth.engine.reciprocating_kg, 0.0);
        assert!(total(&t) > total(&crank));
    }
}
