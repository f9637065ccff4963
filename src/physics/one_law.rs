//! One rubber law in every view (issue 15, `spec/model-format.md` `kind = "rubber"`):
//! [`System::new`] builds each rubber stage as the causal chain fitted by
//! [`crate::rubber`]'s rule, so modes, damped modes, Campbell, forced response, `compare`,
//! the time domain (which takes its chains from here), `synth` and the diagnosis all
//! read the same law.
//!
//! The chain is fitted at the model's modes, which depend on the chain; the modes of the
//! nominal law (seed 000, [`System::nominal`]) are where the law is to be met, so they
//! are computed first and the chain fitted at them, weighted by each stage's share of
//! each mode's strain energy. One pass: a chain that meets the law at the nominal modes
//! puts the modes where the nominal law does (the deviations `torsim modes` reports).

use super::element::causal_law;
use super::error::PhysicsError;
use super::system::{OperatingPoint, System};
use crate::modal::{modes, strain_energy_shares};
use crate::model::{ConnectionKind, Model, RubberStage};
use crate::rubber::{MaxwellChain, ModeTarget, law_band_hz};

impl System {
    /// Builds the system of a validated model at an operating point, every rubber stage
    /// as its causal chain ([`ElementLaw::Causal`](super::ElementLaw::Causal)); the
    /// chains are kept in [`System::chains`].
    pub fn new(model: &Model, point: OperatingPoint) -> Result<Self, PhysicsError> {
        let mut system = Self::nominal(model, point)?;
        if !model
            .connections
            .iter()
            .any(|c| matches!(c.kind, ConnectionKind::Rubber(_)))
        {
            return Ok(system);
        }
        let band = law_band_hz(model);
        // α_f must stay positive from rest to the top of the band: a chain cannot follow
        // a negative stiffness (seed 000 eq. 9 turns negative near 720 Hz unless its
        // `frequency_poly_range` holds it).
        for c in &model.connections {
            if let ConnectionKind::Rubber(stage) = &c.kind
                && let Some((frequency_hz, value)) = stage
                    .frequency_poly
                    .as_ref()
                    .map(|p| p.min_over([0.0, band[1]]))
                    .filter(|(_, v)| v.is_nan() || *v <= 0.0)
            {
                return Err(PhysicsError::FrequencyFactor {
                    connection: c.name.clone(),
                    frequency_hz,
                    value,
                });
            }
        }
        let targets = system.mode_targets();
        let temperature = |stage: &RubberStage| point.temperature_c.unwrap_or(stage.temperature_c);
        for (index, e) in system.elements.iter_mut().enumerate() {
            let ConnectionKind::Rubber(stage) = &model.connections[e.connection].kind else {
                continue;
            };
            let chain = MaxwellChain::fit_at_modes(stage, band, &targets[index]);
            let twist = system.static_twist_rad[e.connection].unwrap_or(0.0);
            e.law = causal_law(
                stage,
                &chain,
                temperature(stage),
                twist,
                e.torque_ratio * e.torque_ratio,
            );
            system.chains[e.connection] = Some(chain);
        }
        system.apply_modal_damping(model);
        Ok(system)
    }

    /// Where each element's law is to be met ([`crate::rubber::chain`]): every mode of this
    /// system with the element's share of its strain energy, per element (in element
    /// order). A system whose modes cannot be found gives none (the chain is then fitted
    /// over the band alone).
    pub fn mode_targets(&self) -> Vec<Vec<ModeTarget>> {
        let found = modes(self).unwrap_or_default();
        let shares: Vec<Vec<f64>> = found
            .iter()
            .map(|m| strain_energy_shares(self, m))
            .collect();
        (0..self.elements.len())
            .map(|index| {
                found
                    .iter()
                    .zip(&shares)
                    .map(|(m, s)| ModeTarget {
                        frequency_hz: m.frequency_hz,
                        energy_share: s[index],
                    })
                    .collect()
            })
            .collect()
    }

    /// Puts `chain` in place of connection `connection`'s chain (a rubber stage of
    /// `model`) at `temperature_c`, linearized at its static twist as [`System::new`] does;
    /// the time domain's reduced chain ([`MaxwellChain::take_fast_arms`]) seen linearly.
    pub fn set_chain(
        &mut self,
        model: &Model,
        connection: usize,
        chain: MaxwellChain,
        temperature_c: Option<f64>,
    ) {
        let Some(ConnectionKind::Rubber(stage)) =
            model.connections.get(connection).map(|c| &c.kind)
        else {
            return;
        };
        let twist = self.static_twist_rad[connection].unwrap_or(0.0);
        for e in self
            .elements
            .iter_mut()
            .filter(|e| e.connection == connection)
        {
            e.law = causal_law(
                stage,
                &chain,
                temperature_c.unwrap_or(stage.temperature_c),
                twist,
                e.torque_ratio * e.torque_ratio,
            );
        }
        self.chains[connection] = Some(chain);
    }
}
