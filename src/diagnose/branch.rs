//! The second form of the `unmodelled_mode` candidate: a local mode hanging on a node
//! ([`crate::effects::branch`]), at every node of the model (issue 14: "a local mode at
//! any node, not only a coupling half").
//!
//! One parameter is fitted, the branch's own frequency `frequency_hz` (held-host
//! tuning), over the band the recordings excite: every order analysed at every speed
//! recorded. Its inertia is a fixed share of the host's, one candidate per share of
//! [`INERTIA_RATIOS`] (a multi-start; the inertia's place in the report is
//! `inertia_ratio`): near its own frequency a branch acts on its host as a dynamic
//! stiffness `−ω²J_b·k/(k − ω²J_b)`, whose pole the frequency places and whose strength
//! the share sets. The linear model represents the branch, so it is screened there like the
//! other forms ([`super::screen`]), and only the best place is verified in the time
//! domain.

use super::candidates::{Candidate, Param};
use super::observe::Observed;
use crate::effects::Effect;
use crate::model::Model;

/// The band a branch's frequency is fitted over, Hz: from 0.8 × the lowest excitation
/// frequency recorded to 1.25 × the highest (a mode just outside the band still shapes
/// the amplitudes at its edge), never below 1 Hz.
pub fn excited_band_hz(observed: &Observed) -> Option<[f64; 2]> {
    let f: Vec<f64> = observed
        .observations
        .iter()
        .map(|o| o.order * o.speed_rpm / 60.0)
        .filter(|f| f.is_finite() && *f > 0.0)
        .collect();
    let lo = f.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = f.iter().copied().fold(0.0, f64::max);
    (lo.is_finite() && hi > lo).then(|| [(0.8 * lo).max(1.0), 1.25 * hi])
}

/// The branch's inertia as a share of its host's, as a multi-start: a light ring (a
/// pulley's rim), a typical damper ring, a heavy one (a flywheel on a soft hub). The
/// share sets how far the branch splits its host's modes, which the frequency alone
/// cannot mimic; the screening keeps the best of the three at each node.
pub const INERTIA_RATIOS: [f64; 3] = [0.05, 0.15, 0.4];

/// A branch candidate at every node of `model` and every share of [`INERTIA_RATIOS`],
/// its frequency fitted over `band_hz` (start: the band's geometric middle; the fit
/// starts from the best of a fine grid, [`Param::resonance`]).
pub fn branch_candidates(model: &Model, band_hz: [f64; 2]) -> Vec<Candidate> {
    let [lo, hi] = band_hz;
    let places = model
        .inertias
        .iter()
        .flat_map(|n| INERTIA_RATIOS.map(|r| (n.name.clone(), r)));
    places
        .map(|(node, ratio)| Candidate {
            effect: Effect::UnmodelledMode,
            fixed: vec![
                ("node", node),
                ("form", "branch".to_string()),
                ("inertia_ratio", ratio.to_string()),
            ],
            param: Param {
                key: "frequency_hz",
                start: (lo * hi).sqrt(),
                lo,
                hi,
                log: true,
                resonance: true,
            },
        })
        .collect()
}

/// The fitted branch's inertia, kg·m², when `c` is the branch form and `model` its fitted
/// model: the node [`crate::effects::branch`] names `<node>_branch` (the report's
/// `inertia_kg_m2` beside `frequency_hz`).
pub fn branch_inertia_kg_m2(c: &Candidate, model: &Model) -> Option<f64> {
    let form = c.fixed.iter().find(|(k, _)| *k == "form")?;
    let (_, host) = c.fixed.iter().find(|(k, _)| *k == "node")?;
    (c.effect == Effect::UnmodelledMode && form.1 == "branch").then_some(())?;
    let i = model.node_index(&format!("{host}_branch"))?;
    Some(model.inertias[i].inertia_kg_m2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::parse_model;

    #[test]
    fn a_branch_candidate_at_every_node_builds_its_model() {
        let text = "format = 1\nname = \"two\"\n[[inertia]]\nname = \"a\"\ninertia = 1\n\
                    [[inertia]]\nname = \"b\"\ninertia = 0.5\n[[connection]]\nkind = \
                    \"shaft\"\nfrom = \"a\"\nto = \"b\"\nstiffness = 1e5\n";
        let model = parse_model(text, "two.toml").unwrap();
        let list = branch_candidates(&model, [10.0, 400.0]);
        assert_eq!(list.len(), 2 * INERTIA_RATIOS.len());
        for c in &list {
            assert_eq!(c.name(), format!("unmodelled_mode at {}", c.fixed[0].1));
            let (m, joint) = c.apply(&model, 80.0).unwrap();
            assert!(joint.is_none());
            assert_eq!(m.inertias.len(), 3);
            assert_eq!(m.connections.len(), 2);
            let host = model.node_index(&c.fixed[0].1).unwrap();
            let ratio: f64 = c.fixed[2].1.parse().unwrap();
            let j = branch_inertia_kg_m2(c, &m).unwrap();
            assert!((j - ratio * model.inertias[host].inertia_kg_m2).abs() < 1e-15);
            // The start lies inside the bounds the fit keeps to.
            assert!(c.param.lo < c.param.start && c.param.start < c.param.hi);
        }
    }
}
