//! Elements: the springs (and dampers) between degrees of freedom, and how a rubber
//! stage becomes one — linearized at its static twist (seed 000 eq. 1–2, 13, 15).

use super::error::PhysicsError;
use crate::model::{Poly, PowerLaw, RubberStage};

/// How an element's stiffness behaves.
#[derive(Debug, Clone, PartialEq)]
pub enum ElementLaw {
    /// A shaft or a gear mesh: constant stiffness and viscous damping (referred).
    Linear {
        /// Referred stiffness, N·m/rad.
        stiffness_nm_per_rad: f64,
        /// Referred viscous damping, N·m·s/rad.
        damping_nm_s_per_rad: f64,
    },
    /// A rubber stage linearized at its static twist: `k(f) = k_base·α_f(f)`, hysteretic
    /// with loss factor `ξ_T` (seed 000 eq. 13, 15).
    Rubber {
        /// Referred tangent stiffness without α_f, N·m/rad: `c_Tstat·dα_x x/dx·α_Tc·r²`.
        base_stiffness_nm_per_rad: f64,
        /// α_f(f) (seed 000 eq. 9); `None`: no frequency dependence.
        frequency_poly: Option<Poly>,
        /// A causal power law in place of α_f (its loss is in `loss_factor` already).
        frequency_power_law: Option<PowerLaw>,
        /// Loss factor `ξ_T = ψ/2π·α_Tξ`.
        loss_factor: f64,
    },
    /// A rubber stage as the time domain represents it: the same base stiffness times
    /// the complex stiffness of a causal generalized Maxwell chain
    /// (`k∞ + Σ k_j·iωτ_j/(1 + iωτ_j)`, relative; [`crate::transient::maxwell`]), so
    /// that a linear model can stand in for the time domain (the diagnosis' surrogate).
    Causal {
        /// As for [`ElementLaw::Rubber`], N·m/rad.
        base_stiffness_nm_per_rad: f64,
        /// `k∞`, relative.
        equilibrium: f64,
        /// Arms `(k_j, τ_j)`: relative stiffness and relaxation time, s.
        arms: Vec<(f64, f64)>,
    },
}

/// A spring (and damper) between two degrees of freedom, or one and the frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Element {
    /// Index of the model connection.
    pub connection: usize,
    /// DOF at the `from` end (`None`: ground).
    pub from_dof: Option<usize>,
    /// DOF at the `to` end (`None`: ground).
    pub to_dof: Option<usize>,
    /// |Speed ratio| of the shaft the connection's torque is given in (its own shaft;
    /// the `to` side for gears). Own-shaft torque = referred torque / this.
    pub torque_ratio: f64,
    /// Stiffness law.
    pub law: ElementLaw,
}

impl Element {
    /// Referred stiffness at vibration frequency `frequency_hz`, N·m/rad, and the loss
    /// factor (zero for linear elements).
    pub fn stiffness_at(&self, frequency_hz: f64) -> (f64, f64) {
        match &self.law {
            ElementLaw::Linear {
                stiffness_nm_per_rad,
                ..
            } => (*stiffness_nm_per_rad, 0.0),
            ElementLaw::Rubber {
                base_stiffness_nm_per_rad,
                frequency_poly,
                frequency_power_law,
                loss_factor,
            } => {
                let alpha_f = match (frequency_power_law, frequency_poly) {
                    (Some(law), _) => law.storage(frequency_hz),
                    (None, Some(p)) => p.eval(frequency_hz),
                    (None, None) => 1.0,
                };
                (base_stiffness_nm_per_rad * alpha_f, *loss_factor)
            }
            ElementLaw::Causal {
                base_stiffness_nm_per_rad,
                equilibrium,
                arms,
            } => {
                let omega = std::f64::consts::TAU * frequency_hz;
                let (re, im) = arms.iter().fold((*equilibrium, 0.0), |(re, im), (k, tau)| {
                    let x = omega * tau;
                    (re + k * x * x / (1.0 + x * x), im + k * x / (1.0 + x * x))
                });
                (base_stiffness_nm_per_rad * re, im / re.max(1e-12))
            }
        }
    }

    /// Referred viscous damping, N·m·s/rad (zero for rubber: it is hysteretic).
    pub fn viscous_damping(&self) -> f64 {
        match &self.law {
            ElementLaw::Linear {
                damping_nm_s_per_rad,
                ..
            } => *damping_nm_s_per_rad,
            ElementLaw::Rubber { .. } | ElementLaw::Causal { .. } => 0.0,
        }
    }

    /// True when the stiffness depends on frequency.
    pub fn is_frequency_dependent(&self) -> bool {
        matches!(
            &self.law,
            ElementLaw::Rubber {
                frequency_poly: Some(_),
                ..
            } | ElementLaw::Rubber {
                frequency_power_law: Some(_),
                ..
            } | ElementLaw::Causal { .. }
        )
    }
}

/// The rubber law linearized at the static twist that `torque_nm` (own shaft) puts on it.
pub(super) fn rubber_law(
    stage: &RubberStage,
    name: &str,
    torque_nm: f64,
    temperature_c: f64,
    r2: f64,
    warnings: &mut Vec<String>,
) -> Result<(ElementLaw, f64), PhysicsError> {
    let twist = stage
        .static_twist_rad(torque_nm, temperature_c)
        .ok_or_else(|| PhysicsError::Twist {
            connection: name.to_string(),
            torque_nm,
        })?;
    let state = stage.state(None, temperature_c, twist);
    for w in &state.warnings {
        warnings.push(format!(
            "rubber stage `{name}`: {} evaluated at {:.4}, outside its range [{}, {}]; held at the end value",
            w.factor.key(), w.argument, w.range[0], w.range[1]
        ));
    }
    for (value, key) in [
        (state.alpha_tc, "temperature_stiffness_poly"),
        (state.alpha_txi, "temperature_damping_poly"),
        (state.alpha_x_tangent, "amplitude_poly"),
    ] {
        if value.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return Err(PhysicsError::Factor {
                connection: name.to_string(),
                key,
                value,
            });
        }
    }
    Ok((
        ElementLaw::Rubber {
            base_stiffness_nm_per_rad: state.tangent_stiffness_nm_per_rad * r2,
            frequency_poly: stage.frequency_poly.clone(),
            frequency_power_law: stage.frequency_power_law,
            loss_factor: state.loss_factor,
        },
        twist,
    ))
}
