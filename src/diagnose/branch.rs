//! The second form of the `unmodelled_mode` candidate: a local mode hanging on a node
//! ([`crate::effects::branch`]), at every node of the model (issue 14: "a local mode at
//! any node, not only a coupling half").
//!
//! One parameter is fitted, the branch's own frequency `frequency_hz` (held-host
//! tuning), over the band the recordings excite: every order analysed at every speed
//! recorded. Its inertia is a fixed share of the host's
//! ([`crate::effects::branch::DEFAULT_INERTIA_RATIO`]), which the host's plain inertia
//! factor and the frequency absorb: near its own frequency a branch acts on its host as
//! a dynamic stiffness `k·ω²J_b/(k − ω²J_b)`, set by where its pole sits much more than
//! by its size. The linear model represents the branch, so it is screened there like the
//! other forms ([`super::screen`]), and only the best place is verified in the time
//! domain.

use super::candidates::{Candidate, Param};
use super::observe::Observed;
use crate::effects::Effect;
use crate::effects::branch::DEFAULT_INERTIA_RATIO;
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

/// A branch candidate at every node of `model`, its frequency fitted over `band_hz`
/// (start: the band's geometric middle; the fit starts from the best of a fine grid,
/// [`Param::resonance`]).
pub fn branch_candidates(model: &Model, band_hz: [f64; 2]) -> Vec<Candidate> {
    let [lo, hi] = band_hz;
    model
        .inertias
        .iter()
        .map(|n| Candidate {
            effect: Effect::UnmodelledMode,
            fixed: vec![
                ("node", n.name.clone()),
                ("form", "branch".to_string()),
                ("inertia_ratio", DEFAULT_INERTIA_RATIO.to_string()),
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
        assert_eq!(list.len(), 2);
        for c in &list {
            assert_eq!(c.name(), format!("unmodelled_mode at {}", c.fixed[0].1));
            let (m, joint) = c.apply(&model, 80.0).unwrap();
            assert!(joint.is_none());
            assert_eq!(m.inertias.len(), 3);
            assert_eq!(m.connections.len(), 2);
            // The start lies inside the bounds the fit keeps to.
            assert!(c.param.lo < c.param.start && c.param.start < c.param.hi);
        }
    }
}
