//! Elements: the springs (and dampers) between degrees of freedom, and how a rubber
//! stage becomes one — linearized at its static twist (seed 000 eq. 1–2, 13, 15).

use super::error::PhysicsError;
use crate::model::{AmplitudeForm, Poly, PowerLaw, RubberStage, ZenerLaw};

/// How an element's stiffness behaves.
#[derive(Debug, Clone, PartialEq)]
pub enum ElementLaw {
    /// A shaft or a gear mesh: constant stiffness and viscous damping (referred).
    Linear {
        /// Referred stiffness, N·m/rad.
        stiffness_nm_per_rad: f64,
        /// Referred viscous damping, N·m·s/rad.
        damping_nm_s_per_rad: f64,
        /// Referred inertia of this segment of a distributed shaft, kg·m², lumped half at
        /// each end DOF for the matrix analyses; the forced response adds the exact
        /// element's difference ([`super::distributed`]). 0 for a massless shaft or mesh.
        distributed_inertia_kg_m2: f64,
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
        /// A fractional Zener law in place of α_f; its loss at each frequency follows from
        /// `loss_factor`, then the catalogue's ([`crate::model::frequency_zener`]).
        frequency_zener: Option<ZenerLaw>,
        /// Loss factor `ξ_T = ψ/2π·α_Tξ` of the part `base·α_f` (with a Zener law, its
        /// rate-independent part, to which the law's own is added).
        loss_factor: f64,
        /// Referred stiffness added without loss or frequency dependence, N·m/rad: the
        /// stiffening of the equilibrium spring of an `amplitude_form = "elastic"` stage,
        /// `c_Tstat·(dα_x x/dx − 1)·α_f(0)·α_Tc·r²` (then the base has no α_x); 0 else.
        elastic_nm_per_rad: f64,
    },
    /// A rubber stage as every analysis represents it ([`crate::rubber`]): a base
    /// stiffness times the complex stiffness of its causal generalized Maxwell chain
    /// (`k∞ + Σ k_j·iωτ_j/(1 + iωτ_j)`, relative), plus a lossless spring; the time
    /// domain's rubber torque linearized at the static twist ([`causal_law`]).
    Causal {
        /// Referred stiffness the chain multiplies, N·m/rad: `c_Tstat·h'·α_Tc·r²` with
        /// `h' = d(α_x x)/dx` the tangent (`c_Tstat·α_Tc·r²` for an `elastic` stage).
        base_stiffness_nm_per_rad: f64,
        /// `k∞`, relative.
        equilibrium: f64,
        /// Arms `(k_j·α_Tξ(T)/α_Tξ(T0), τ_j)`: relative stiffness and relaxation time, s.
        arms: Vec<(f64, f64)>,
        /// Referred stiffness added without loss or frequency dependence, N·m/rad: the
        /// stiffening of an `elastic` stage's static curve, `c_Tstat·(h' − 1)·κ0·α_Tc·r²`
        /// ([`causal_law`]); 0 else.
        elastic_nm_per_rad: f64,
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
                frequency_zener,
                loss_factor,
                elastic_nm_per_rad,
            } => {
                let (alpha_f, loss_factor) = match (frequency_zener, frequency_power_law) {
                    (Some(z), _) => (
                        z.storage(frequency_hz),
                        z.loss_factor(frequency_hz, *loss_factor),
                    ),
                    (None, Some(law)) => (law.storage(frequency_hz), *loss_factor),
                    (None, None) => (
                        frequency_poly
                            .as_ref()
                            .map_or(1.0, |p| p.eval(frequency_hz)),
                        *loss_factor,
                    ),
                };
                let lossy = base_stiffness_nm_per_rad * alpha_f;
                if *elastic_nm_per_rad == 0.0 {
                    return (lossy, loss_factor);
                }
                with_elastic(lossy, lossy * loss_factor, *elastic_nm_per_rad)
            }
            ElementLaw::Causal {
                base_stiffness_nm_per_rad,
                equilibrium,
                arms,
                elastic_nm_per_rad,
            } => {
                let omega = std::f64::consts::TAU * frequency_hz;
                let (re, im) = arms.iter().fold((*equilibrium, 0.0), |(re, im), (k, tau)| {
                    let x = omega * tau;
                    (re + k * x * x / (1.0 + x * x), im + k * x / (1.0 + x * x))
                });
                if *elastic_nm_per_rad == 0.0 {
                    return (base_stiffness_nm_per_rad * re, im / re.max(1e-12));
                }
                with_elastic(
                    base_stiffness_nm_per_rad * re,
                    base_stiffness_nm_per_rad * im,
                    *elastic_nm_per_rad,
                )
            }
        }
    }

    /// Referred inertia of a distributed shaft's segment, kg·m² (0 for every other).
    pub fn distributed_inertia(&self) -> f64 {
        match &self.law {
            ElementLaw::Linear {
                distributed_inertia_kg_m2,
                ..
            } => *distributed_inertia_kg_m2,
            _ => 0.0,
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
            } | ElementLaw::Rubber {
                frequency_zener: Some(_),
                ..
            } | ElementLaw::Causal { .. }
        )
    }
}

/// Storage stiffness and loss factor of a lossy part (storage `storage`, loss modulus
/// `loss`, N·m/rad) beside a lossless spring `elastic`: `(storage + elastic, loss/(…))`.
fn with_elastic(storage: f64, loss: f64, elastic: f64) -> (f64, f64) {
    let k = storage + elastic;
    let loss_factor = if storage == 0.0 && loss == 0.0 {
        0.0
    } else {
        loss / k.max(1e-12 * storage.abs())
    };
    (k, loss_factor)
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
    let tangent = state.tangent_stiffness_nm_per_rad * r2;
    let (base, elastic) = match stage.amplitude_form {
        AmplitudeForm::Whole => (tangent, 0.0),
        // The equilibrium spring k∞ = α_f(0) alone stiffens (as in the time domain).
        AmplitudeForm::Elastic => {
            let base = tangent / state.alpha_x_tangent;
            let k_inf = stage.frequency_factor(0.0);
            (base, base * (state.alpha_x_tangent - 1.0) * k_inf)
        }
    };
    Ok((
        ElementLaw::Rubber {
            base_stiffness_nm_per_rad: base,
            frequency_poly: stage.frequency_poly.clone(),
            frequency_power_law: stage.frequency_power_law,
            frequency_zener: stage.frequency_zener,
            loss_factor: match stage.frequency_zener {
                Some(_) => stage.catalogue_loss_factor(state.alpha_txi),
                None => state.loss_factor,
            },
            elastic_nm_per_rad: elastic,
        },
        twist,
    ))
}

/// The causal law of `stage` represented by `chain` ([`crate::rubber`]), linearized at
/// the static twist `twist_rad` (own shaft) and `temperature_c`; `r2` refers it to the
/// reference shaft.
///
/// The time domain's torque ([`crate::transient::forces`]) is
/// `c·α_Tc·[κ0·α_x(x)·φ + h'(φ)·D]`, `D` the chain's part above `κ0` about the static
/// twist and `h' = d(α_x x)/dx` (seed 000 eq. 1–2). At `φ = φ_s` with the arms relaxed
/// its derivative is `c·α_Tc·h'·(k∞ + a·arms)` (`a = α_Tξ(T)/α_Tξ(T0)`, 1 at the stage's
/// own temperature): the tangent times the chain, as the
/// nominal law's `c·α_Tc·h'·α_f(f)·(1 + iξ_T)`. An `elastic` stage puts α_x on the static
/// curve only: `c·α_Tc·(k∞ + a·arms) + c·α_Tc·(h' − 1)·κ0`.
pub(super) fn causal_law(
    stage: &RubberStage,
    chain: &crate::rubber::MaxwellChain,
    temperature_c: f64,
    twist_rad: f64,
    r2: f64,
) -> ElementLaw {
    let state = stage.state(None, temperature_c, twist_rad);
    let c = stage.static_stiffness_nm_per_rad() * state.alpha_tc * r2;
    let tangent = state.alpha_x_tangent;
    // The chain meets the loss at the stage's own temperature; its arms scale by
    // α_Tξ(T)/α_Tξ(T0) elsewhere ([`crate::rubber::chain`]).
    let damping = state.alpha_txi / stage.state(None, stage.temperature_c, 0.0).alpha_txi;
    let (base, elastic) = match stage.amplitude_form {
        AmplitudeForm::Whole => (c * tangent, 0.0),
        AmplitudeForm::Elastic => (c, c * (tangent - 1.0) * chain.static_stiffness),
    };
    ElementLaw::Causal {
        base_stiffness_nm_per_rad: base,
        equilibrium: chain.equilibrium,
        arms: chain
            .arms
            .iter()
            .map(|&(k, tau)| (k * damping, tau))
            .collect(),
        elastic_nm_per_rad: elastic,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{RubberElements, RubberStiffness};

    /// A stage of 8 elements on a 0.2 m pitch diameter (100 mm of element deformation
    /// per rad) with a cubic spring, α_x = 1 + a2·x² (a1 = 0), x in mm.
    fn cubic_stage(a2: f64, form: AmplitudeForm) -> RubberStage {
        let mut e = RubberElements {
            count: 8,
            per_side: 4,
            pitch_diameter_m: 0.2,
            radial_stiffness_n_per_m: 1.0,
        };
        e.radial_stiffness_n_per_m = 5.0e4 / e.torsional_stiffness_nm_per_rad();
        RubberStage {
            stiffness: RubberStiffness::Elements(e),
            psi: 0.6,
            temperature_c: 25.0,
            amplitude_poly: Some(Poly {
                coeffs: [a2, 0.0, 1.0],
                range: None,
            }),
            amplitude_saturation: None,
            amplitude_form: form,
            frequency_poly: None,
            frequency_power_law: None,
            frequency_zener: None,
            temperature_stiffness_poly: None,
            temperature_damping_poly: None,
            thermal: None,
            rating: None,
        }
    }

    #[test]
    fn an_elastic_stage_stiffens_by_the_cubic_tangent_and_keeps_its_loss_modulus() {
        // k0 = 5e4 N·m/rad; T = k0·(1 + a2·(100 θ)²)·θ (eq. 1–2, 13). At T = 150 N·m and
        // a2 = 20 /mm²: θ solves the cubic; the tangent is k0·(1 + 3·a2·(100 θ)²).
        let (k0, a2, torque, xi) = (5.0e4, 20.0, 150.0, 0.6 / std::f64::consts::TAU);
        let mut w = Vec::new();
        let whole = rubber_law(
            &cubic_stage(a2, AmplitudeForm::Whole),
            "c",
            torque,
            25.0,
            1.0,
            &mut w,
        );
        let elastic = rubber_law(
            &cubic_stage(a2, AmplitudeForm::Elastic),
            "c",
            torque,
            25.0,
            1.0,
            &mut w,
        );
        let ((whole, twist), (elastic, twist_e)) = (whole.unwrap(), elastic.unwrap());
        // The static twist is the same in both forms: the cubic's root.
        assert_eq!(twist, twist_e);
        let x2 = (100.0 * twist) * (100.0 * twist);
        assert!((k0 * (1.0 + a2 * x2) * twist - torque).abs() < 1e-9 * torque);
        let tangent = k0 * (1.0 + 3.0 * a2 * x2);
        assert!(
            tangent > 1.2 * k0,
            "the test must stiffen noticeably: {tangent}"
        );
        let el = Element {
            connection: 0,
            from_dof: Some(0),
            to_dof: None,
            torque_ratio: 1.0,
            law: whole,
        };
        let (k_w, eta_w) = el.stiffness_at(40.0);
        let (k_e, eta_e) = Element { law: elastic, ..el }.stiffness_at(40.0);
        // Storage: the tangent in both forms (1e-12: rounding of a few products).
        assert!(
            (k_w - tangent).abs() < 1e-12 * tangent,
            "{k_w} vs {tangent}"
        );
        assert!(
            (k_e - tangent).abs() < 1e-12 * tangent,
            "{k_e} vs {tangent}"
        );
        // Loss modulus: scaled by the stiffening (whole), the user's k0·ξ (elastic).
        assert!((eta_w - xi).abs() < 1e-12);
        assert!((eta_e * k_e - xi * k0).abs() < 1e-12 * xi * k0, "{eta_e}");
    }

    #[test]
    fn a_saturating_stage_stiffens_by_its_tangent_at_the_static_twist() {
        // k0 = 5e4 N·m/rad, α_x = 1 + s·tanh(u), u = (x/x_s)², x = 100·θ mm. At
        // T = 150 N·m the linear twist is 3 mrad (x = 0.3 mm, u ≈ 1.4: in the bend). The
        // storage is the tangent k0·(α_x + 2·s·u·sech²u).
        let (k0, s, x_s, torque) = (5.0e4, 0.4, 0.25, 150.0);
        let mut stage = cubic_stage(0.0, AmplitudeForm::Elastic);
        stage.amplitude_poly = None;
        stage.amplitude_saturation = Some(crate::model::AmplitudeSaturation {
            stiffening: s,
            deformation_mm: x_s,
        });
        let mut w = Vec::new();
        let (law, twist) = rubber_law(&stage, "c", torque, 25.0, 1.0, &mut w).unwrap();
        let u = (100.0 * twist / x_s).powi(2);
        assert!(u > 0.5 && u < 2.0, "in the bend: u = {u}");
        assert!((k0 * (1.0 + s * u.tanh()) * twist - torque).abs() < 1e-9 * torque);
        let tangent = k0 * (1.0 + s * u.tanh() + 2.0 * s * u / u.cosh().powi(2));
        let el = Element {
            connection: 0,
            from_dof: Some(0),
            to_dof: None,
            torque_ratio: 1.0,
            law,
        };
        let (k, eta) = el.stiffness_at(40.0);
        // The twist is solved to 1e-9 relative; the tangent follows it to ~1e-9.
        assert!((k - tangent).abs() < 1e-8 * tangent, "{k} vs {tangent}");
        // Elastic form: the loss modulus stays the user's k0·ξ.
        let xi = 0.6 / std::f64::consts::TAU;
        assert!((eta * k - xi * k0).abs() < 1e-12 * xi * k0, "{eta}");
    }

    #[test]
    fn a_causal_law_adds_its_elastic_spring_without_loss() {
        // One arm at τ = 1/(2π·40 Hz): at 40 Hz it adds k1/2 storage and k1/2 loss.
        let (k0, k1, extra) = (5.0e4, 0.1, 1.2e4);
        let law = |elastic_nm_per_rad| ElementLaw::Causal {
            base_stiffness_nm_per_rad: k0,
            equilibrium: 1.0,
            arms: vec![(k1, 1.0 / (std::f64::consts::TAU * 40.0))],
            elastic_nm_per_rad,
        };
        let el = |l| Element {
            connection: 0,
            from_dof: Some(0),
            to_dof: None,
            torque_ratio: 1.0,
            law: l,
        };
        let (k, eta) = el(law(extra)).stiffness_at(40.0);
        let storage = k0 * (1.0 + k1 / 2.0);
        assert!((k - (storage + extra)).abs() < 1e-9 * k, "{k}");
        assert!((eta * k - k0 * k1 / 2.0).abs() < 1e-9 * k0 * k1, "{eta}");
        let (k_plain, eta_plain) = el(law(0.0)).stiffness_at(40.0);
        assert!(
            (k_plain - storage).abs() < 1e-9 * k && (eta_plain * k_plain - eta * k).abs() < 1e-6
        );
    }
}
