//! How far each rubber stage's causal chain departs from seed 000's nominal law at each
//! mode (issue 15, `spec/model-format.md` `kind = "rubber"`): what `torsim modes` reports.
//!
//! The nominal law `k·α_f(f)·(1 + iξ_T)` is not causal, so no chain meets it everywhere;
//! [`crate::rubber`] fits it where the model's modes lie, weighted by each stage's share
//! of the mode's strain energy. A stage that holds little of a mode's energy may depart
//! further there without moving the mode, which is why the share is reported beside it.

use super::energy::strain_energy_shares;
use super::undamped::Mode;
use crate::physics::{ElementLaw, System};

/// One rubber stage at one mode.
#[derive(Debug, Clone, PartialEq)]
pub struct LawDeviation {
    /// Connection name.
    pub connection: String,
    /// Mode number, from 1 (rigid-body modes not counted).
    pub mode: usize,
    /// Natural frequency, Hz.
    pub frequency_hz: f64,
    /// The stage's share of the mode's strain energy, 0…1.
    pub energy_share: f64,
    /// Storage stiffness of the chain over the nominal law's, minus 1.
    pub stiffness_deviation: f64,
    /// Loss factor of the chain over the nominal law's, minus 1.
    pub loss_deviation: f64,
}

/// The deviations of every causal rubber element of `causal` from the same element of
/// `nominal` ([`System::nominal`] of the same model and point) at each of `modes` (the
/// causal system's).
pub fn law_deviations(causal: &System, nominal: &System, modes: &[Mode]) -> Vec<LawDeviation> {
    let mut out = Vec::new();
    for (m, mode) in modes.iter().enumerate() {
        let shares = strain_energy_shares(causal, mode);
        for (index, (c, n)) in causal.elements.iter().zip(&nominal.elements).enumerate() {
            if !matches!(c.law, ElementLaw::Causal { .. }) || c.connection != n.connection {
                continue;
            }
            let (k_c, eta_c) = c.stiffness_at(mode.frequency_hz);
            let (k_n, eta_n) = n.stiffness_at(mode.frequency_hz);
            out.push(LawDeviation {
                connection: causal.connection_names[c.connection].clone(),
                mode: m + 1,
                frequency_hz: mode.frequency_hz,
                energy_share: shares[index],
                stiffness_deviation: k_c / k_n - 1.0,
                loss_deviation: if eta_n > 0.0 {
                    eta_c / eta_n - 1.0
                } else {
                    0.0
                },
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::modal::modes;
    use crate::model::parse_model;
    use crate::physics::OperatingPoint;

    /// Two inertias on one rubber stage (ψ = 0.9, seed 000's α_f held above 300 Hz): one
    /// mode (87 Hz), wholly in the stage. The chain meets the nominal law there: storage
    /// within 0.2 % and loss factor within 1 % (measured −0.12 % and +0.26 %: the band's
    /// rows, which seed 000's steep α_f cannot all meet, pull a little).
    #[test]
    fn a_single_mode_is_met_by_its_stage() {
        let text = r#"format = 1
name = "one mode"
[[inertia]]
name = "a"
inertia = 0.5
[[inertia]]
name = "b"
inertia = 0.2
[[connection]]
name = "c"
kind = "rubber"
from = "a"
to = "b"
stiffness = 2.0e4
psi = 0.9
frequency_poly = [-0.000023, 0.01519, 1.0]
frequency_poly_range = [0, 300]
"#;
        let model = parse_model(text, "one.toml").unwrap();
        let point = OperatingPoint::default();
        let causal = System::new(&model, point).unwrap();
        let nominal = System::nominal(&model, point).unwrap();
        let found = modes(&causal).unwrap();
        let deviations = law_deviations(&causal, &nominal, &found);
        assert_eq!(deviations.len(), 1);
        let d = &deviations[0];
        assert!((d.energy_share - 1.0).abs() < 1e-12);
        assert!(d.stiffness_deviation.abs() < 2e-3, "{d:?}");
        assert!(d.loss_deviation.abs() < 1e-2, "{d:?}");
        // And the mode is the nominal one: f² ∝ storage, so within 0.1 %.
        let f_nominal = modes(&nominal).unwrap()[0].frequency_hz;
        assert!(
            (d.frequency_hz / f_nominal - 1.0).abs() < 1e-3,
            "{d:?} vs {f_nominal}"
        );
    }
}
