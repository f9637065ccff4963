//! The driveline as a time-domain plant: the state layout and everything the equations of
//! motion need, built once from a model for one run.
//!
//! Coordinates: every DOF's angle is its vibration about the mean rotation `φ_m(t)`,
//! referred to the engine shaft (as in [`crate::physics::System`]); the frame (`ground`)
//! turns with the mean rotation too (seed 001's brake side). State:
//! `[θ_0…θ_{n−1}, ω_0…ω_{n−1}, q (Maxwell arms, own-shaft rad), T (rubber °C)]`.

use super::TransientError;
use crate::model::{AmplitudeForm, ConnectionKind, GROUND, HarmonicAmplitude, Model, Poly};
use crate::physics::distributed::connection_rows;
use crate::physics::tooth_contact::ToothContact;
use crate::physics::{OperatingPoint, System, engine};
use crate::rubber::MaxwellChain;

/// A rubber stage in the time domain (seed 000 eq. 1–2, 10–15 with a Maxwell chain).
#[derive(Debug, Clone)]
pub struct RubberPlant {
    /// Static torsional stiffness at 25 °C, own shaft, N·m/rad.
    pub static_stiffness_nm_per_rad: f64,
    /// Element pitch radius × 1000 (mm of radial deformation per rad), when from elements.
    pub mm_per_rad: Option<f64>,
    /// α_x(x), x in mm of element deformation.
    pub amplitude_poly: Option<Poly>,
    /// A saturating α_x in place of `amplitude_poly`.
    pub amplitude_saturation: Option<crate::model::AmplitudeSaturation>,
    /// What α_x scales: the whole stage or its equilibrium spring only.
    pub amplitude_form: AmplitudeForm,
    /// α_Tc(T).
    pub temperature_stiffness_poly: Option<Poly>,
    /// α_Tξ(T).
    pub temperature_damping_poly: Option<Poly>,
    /// α_Tξ at the stage's `temperature_c`, where its chain meets the loss: the arms
    /// scale by α_Tξ(T) over this.
    pub damping_reference: f64,
    /// The stage's chain ([`crate::rubber`], from [`System::chains`]), less any arms taken
    /// out as a dashpot.
    pub chain: MaxwellChain,
    /// Static twist the mean torque puts on the stage at the run's load, own shaft, rad:
    /// the chain vibrates about it, and `κ0` holds it.
    pub static_twist_rad: f64,
    /// Index of the first arm state in the state vector.
    pub arm_offset: usize,
    /// `1/τ` of each arm of [`RubberPlant::chain`], 1/s (the right-hand side multiplies
    /// by it rather than divide by τ).
    pub arm_rates_per_s: Vec<f64>,
    /// The dashpot that stands in for the arms too fast to integrate
    /// ([`MaxwellChain::take_fast_arms`]), relative stiffness × s (0: none).
    pub viscous_s: f64,
    /// Index of this stage's temperature state, or the fixed temperature.
    pub temperature: Temperature,
}

/// A rubber stage's temperature: fixed, or a state of its own.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Temperature {
    /// Held at this value, °C.
    Fixed(f64),
    /// Evolves (`thermal`): state index, heat capacity J/K, conductance W/K, ambient °C.
    Thermal {
        /// Index in the state vector.
        state: usize,
        /// Heat capacity, J/K.
        capacity_j_per_k: f64,
        /// Conductance to ambient, W/K.
        conductance_w_per_k: f64,
        /// Ambient temperature, °C.
        ambient_c: f64,
    },
}

/// How a connection acts in the time domain.
#[derive(Debug, Clone)]
pub enum PlantLaw {
    /// Linear spring and viscous damper (referred).
    Linear {
        /// N·m/rad referred.
        stiffness: f64,
        /// N·m·s/rad referred.
        damping: f64,
    },
    /// A rubber stage.
    Rubber(Box<RubberPlant>),
    /// A gear mesh: `T = k·c(δ)`, `c` its tooth contact's law (free play ±half gap, own
    /// `to` side, hard or softened, linear or Hertzian: [`ToothContact`]).
    Backlash {
        /// Mesh stiffness, own shaft (`to` side), N·m/rad.
        stiffness_own: f64,
        /// Mesh damping, own shaft (`to` side), N·m·s/rad, on the twist rate whether or
        /// not the teeth touch ([`crate::model::Gear::mesh_damping_nm_s_per_rad`]).
        damping_own: f64,
        /// The tooth contact's law, rad at the `to` side.
        contact: ToothContact,
    },
}

/// A connection in the plant.
#[derive(Debug, Clone)]
pub struct PlantElement {
    /// Model connection index.
    pub connection: usize,
    /// DOF at `from` (`None`: ground).
    pub from_dof: Option<usize>,
    /// DOF at `to` (`None`: ground).
    pub to_dof: Option<usize>,
    /// |Speed ratio| of the connection's own shaft: own angle = ratio × referred angle.
    pub ratio: f64,
    /// The law.
    pub law: PlantLaw,
}

/// One cylinder acting on a DOF.
#[derive(Debug, Clone, Copy)]
pub struct Cylinder {
    /// DOF it acts on.
    pub dof: usize,
    /// Speed ratio of its node (1 on the crank).
    pub ratio: f64,
    /// Firing angle after cylinder 1, rad.
    pub firing_rad: f64,
    /// Its sine and cosine.
    pub firing_sin_cos: (f64, f64),
    /// Factor on its gauge pressure (`[engine] pressure_scale`, default 1).
    pub pressure_scale: f64,
}

/// The engine's per-cylinder constants (seed 001 eq. 3–4).
#[derive(Debug, Clone)]
pub struct EnginePlant {
    /// Piston area, m².
    pub area_m2: f64,
    /// Crank radius r, m.
    pub crank_radius_m: f64,
    /// λ = r/l.
    pub lambda: f64,
    /// Oscillating mass `m_p + m_A − J0/l²`, kg.
    pub oscillating_mass_kg: f64,
    /// Working cycle, rad.
    pub cycle_rad: f64,
    /// Points of [`EnginePlant::pressure_pa`] per rad of the cycle: `len / cycle_rad`.
    pub pressure_points_per_rad: f64,
    /// Gauge pressure in Pa on a uniform grid over the cycle from firing TDC, through
    /// order 48 ([`super::pressure`]).
    pub pressure_pa: Vec<f64>,
    /// The cylinders.
    pub cylinders: Vec<Cylinder>,
    /// Cycle-mean torque of all cylinders, referred, N·m.
    pub mean_torque_nm: f64,
}

/// A prescribed harmonic torque.
#[derive(Debug, Clone)]
pub struct HarmonicPlant {
    /// DOF it acts on.
    pub dof: usize,
    /// Referral ratio.
    pub ratio: f64,
    /// Order.
    pub order: f64,
    /// Phase, rad.
    pub phase_rad: f64,
    /// Amplitude.
    pub amplitude: HarmonicAmplitude,
}

impl HarmonicPlant {
    /// Its amplitude at mean speed `speed_rpm` (held beyond a `BySpeed` table's ends), N·m.
    pub fn amplitude_nm(&self, speed_rpm: f64) -> f64 {
        match &self.amplitude {
            HarmonicAmplitude::Constant(a) => *a,
            HarmonicAmplitude::BySpeed {
                speed_rpm: rpm,
                amplitude_nm,
            } => crate::physics::excitation::interpolate_held(rpm, amplitude_nm, speed_rpm),
        }
    }
}

/// The brake or generator that holds the mean speed of a driveline not tied to ground: it
/// takes the engine's mean torque (less what accelerates the driveline in a ramp) at the
/// load node, and corrects slow drift like a speed governor — a critically damped PI loop
/// at 0.5 Hz on the driveline's rigid-body motion.
///
/// The correction acts on the inertia-weighted mean of the vibration (the rigid-body
/// coordinate `Σ J_i θ_i / Σ J_i`) and is applied to every DOF in proportion to its
/// inertia, so it cannot touch the vibration modes: each is mass-orthogonal to the rigid
/// body (`Σ J_i φ_k,i = 0`), so it neither feeds the loop nor is driven by it. Its
/// proportional part sees the rigid-body speed low-passed at [`GOVERNOR_FILTER_HZ`] (one
/// more state), so on the rigid-body part of an order at ω it adds
/// `(2ω_g·ω_f + ω_g²)/ω²` = 9 (ω_g/ω)² of its inertia force: 0.09 % at 50 Hz, 2.3 % at
/// 10 Hz. Closed loop (in units of ω_g): s³ + 4s² + 9s + 4, poles −0.57 and
/// −1.72 ± 2.03i.
///
/// Applied at the load node on the raw speed, as it was, the proportional part was a
/// damper of `2ω_g·ΣJ` there at every frequency (27 N·m·s/rad on a 4.3 kg·m² driveline,
/// more than its declared load damping), which the frequency domain does not have: order
/// 3 at resonance came out 7.5 % below `response` (README, issue 15).
#[derive(Debug, Clone)]
pub struct Governor {
    /// DOF of the load node.
    pub dof: usize,
    /// Proportional gain, N·m·s/rad.
    pub kp: f64,
    /// Integral gain, N·m/rad.
    pub ki: f64,
    /// Total referred inertia of the driveline, kg·m².
    pub total_inertia_kg_m2: f64,
    /// Each DOF's share of the total inertia: the rigid-body coordinate's weights and the
    /// correction's distribution.
    pub inertia_share: Vec<f64>,
    /// The rigid-body angle the loop holds, rad: the start state's (default 0).
    pub rigid_angle_ref_rad: f64,
    /// Index in the state of the low-passed rigid-body speed the proportional part sees.
    pub filter_state: usize,
    /// Mean torque the vibration takes from the engine at the start speed, N·m referred
    /// (its dissipated power over the reference speed, from the linear periodic start,
    /// [`super::periodic_start::add_periodic_state`]); the load gets the engine's mean
    /// torque less this. Default 0 (the PI loop finds it, in seconds).
    pub dissipation_torque_nm: f64,
}

/// Governor bandwidth, Hz.
pub const GOVERNOR_HZ: f64 = 0.5;
/// Corner of the low-pass on the rigid-body speed of the governor's proportional part, Hz:
/// four times its bandwidth ([`Governor`]).
pub const GOVERNOR_FILTER_HZ: f64 = 4.0 * GOVERNOR_HZ;

/// Everything the equations of motion need.
#[derive(Debug, Clone)]
pub struct Plant {
    /// Number of DOFs.
    pub n_dof: usize,
    /// Referred inertia per DOF without the reciprocating masses, kg·m².
    pub inertia_kg_m2: Vec<f64>,
    /// Referred absolute damping per DOF (nodes, load), on vibration, N·m·s/rad.
    pub damping_nm_s_per_rad: Vec<f64>,
    /// Connections.
    pub elements: Vec<PlantElement>,
    /// The engine, if any.
    pub engine: Option<EnginePlant>,
    /// Prescribed harmonics.
    pub harmonics: Vec<HarmonicPlant>,
    /// Speed holder of a free driveline.
    pub governor: Option<Governor>,
    /// DOF of the reference node (crank).
    pub reference_dof: usize,
    /// Length of the state vector.
    pub state_len: usize,
    /// The linear system the plant was built from (names, ratios, static twist).
    pub system: System,
    /// Start temperature of each connection that is a rubber stage, °C.
    pub start_temperature_c: Vec<Option<f64>>,
    /// The output row of each element and whether it gives the row's torque: one row per
    /// connection with elements, in element order; a distributed shaft's segments share
    /// one row (torque at its `from` end, the power of all its segments).
    pub output_rows: Vec<(usize, bool)>,
}

impl Plant {
    /// Builds the plant of `model` at engine `load`, each rubber stage as the chain of
    /// the model's [`System`] (one law in every view, [`crate::rubber`]). Maxwell arms
    /// relaxing faster than `viscous_above_hz` (if given) become a dashpot
    /// ([`MaxwellChain::take_fast_arms`]).
    pub fn new(
        model: &Model,
        load: f64,
        viscous_above_hz: Option<f64>,
    ) -> Result<Self, TransientError> {
        let system = System::new(
            model,
            OperatingPoint {
                load,
                temperature_c: None,
            },
        )?;
        let n = system.dof_count();
        let mut inertia = vec![0.0; n];
        for (i, node) in model.inertias.iter().enumerate() {
            inertia[system.dof_of_node[i]] += node.inertia_kg_m2 * system.speed_ratio[i].powi(2);
        }
        for (j, segments) in inertia.iter_mut().zip(system.segment_inertia_kg_m2()) {
            *j += segments;
        }
        let damping = system.absolute_damping_nm_s_per_rad.clone();
        let dof_of = |name: &str| {
            (name != GROUND)
                .then(|| model.node_index(name).map(|i| system.dof_of_node[i]))
                .flatten()
        };
        let ratio_of = |name: &str| {
            model
                .node_index(name)
                .map_or(1.0, |i| system.speed_ratio[i].abs())
        };
        let mut state_len = 2 * n;
        let mut elements = Vec::new();
        for (j, c) in model.connections.iter().enumerate() {
            let (from_dof, to_dof) = (dof_of(&c.from), dof_of(&c.to));
            let own = if c.from == GROUND {
                ratio_of(&c.to)
            } else {
                ratio_of(&c.from)
            };
            let (ratio, law) = match &c.kind {
                // A shaft as the system has it: one element, or a distributed shaft's
                // chain of segments (internal DOFs included).
                ConnectionKind::Shaft(_) => {
                    for e in system.elements.iter().filter(|e| e.connection == j) {
                        elements.push(PlantElement {
                            connection: j,
                            from_dof: e.from_dof,
                            to_dof: e.to_dof,
                            ratio: own,
                            law: PlantLaw::Linear {
                                stiffness: e.stiffness_at(0.0).0,
                                damping: e.viscous_damping(),
                            },
                        });
                    }
                    continue;
                }
                ConnectionKind::Gear(g) => match (g.mesh_stiffness_nm_per_rad, g.backlash_deg) {
                    (None, b) if b > 0.0 => {
                        return Err(TransientError::Model(format!(
                            "gear `{}`: backlash_deg needs mesh_stiffness (a rigid gear has no free play)",
                            c.name
                        )));
                    }
                    (None, _) => continue,
                    (Some(k), b) => (
                        ratio_of(&c.to),
                        PlantLaw::Backlash {
                            stiffness_own: k,
                            damping_own: g.mesh_damping_nm_s_per_rad,
                            contact: ToothContact {
                                half_gap_rad: 0.5 * b.to_radians(),
                                softening_rad: g.backlash_softening_deg.to_radians(),
                                exponent: g.contact_exponent,
                                reference_rad: g.contact_reference_deg.to_radians(),
                            },
                        },
                    ),
                },
                ConnectionKind::Rubber(stage) => {
                    // [`System::new`] gave every rubber stage its chain.
                    let mut chain = system.chains[j].clone().ok_or_else(|| {
                        TransientError::Model(format!("rubber stage `{}` has no chain", c.name))
                    })?;
                    let viscous_s = viscous_above_hz.map_or(0.0, |f| chain.take_fast_arms(f));
                    let arm_offset = state_len;
                    state_len += chain.arms.len();
                    let temperature = match &stage.thermal {
                        None => Temperature::Fixed(stage.temperature_c),
                        Some(t) => {
                            state_len += 1;
                            Temperature::Thermal {
                                state: state_len - 1,
                                capacity_j_per_k: t.capacity_j_per_k,
                                conductance_w_per_k: t.conductance_w_per_k,
                                ambient_c: t.ambient_c,
                            }
                        }
                    };
                    (
                        own,
                        PlantLaw::Rubber(Box::new(RubberPlant {
                            static_stiffness_nm_per_rad: stage.static_stiffness_nm_per_rad(),
                            mm_per_rad: stage.pitch_radius_m().map(|r| r * 1000.0),
                            amplitude_poly: stage.amplitude_poly.clone(),
                            amplitude_saturation: stage.amplitude_saturation,
                            amplitude_form: stage.amplitude_form,
                            temperature_stiffness_poly: stage.temperature_stiffness_poly.clone(),
                            temperature_damping_poly: stage.temperature_damping_poly.clone(),
                            damping_reference: stage
                                .state(None, stage.temperature_c, 0.0)
                                .alpha_txi,
                            arm_rates_per_s: chain.arms.iter().map(|(_, tau)| 1.0 / tau).collect(),
                            chain,
                            static_twist_rad: system.static_twist_rad[j].unwrap_or(0.0),
                            arm_offset,
                            viscous_s,
                            temperature,
                        })),
                    )
                }
            };
            elements.push(PlantElement {
                connection: j,
                from_dof,
                to_dof,
                ratio,
                law,
            });
        }
        let engine = model.engine.as_ref().map(|e| {
            let cycle_rad = e.cycle_deg().to_radians();
            let pressure_pa = super::pressure::cycle_table_pa(e, load);
            let cylinders: Vec<Cylinder> = e
                .firing_angles_or_even_deg()
                .iter()
                .enumerate()
                .filter_map(|(c, a)| {
                    let node = model.node_index(e.node_of_cylinder(c))?;
                    Some(Cylinder {
                        dof: system.dof_of_node[node],
                        ratio: system.speed_ratio[node],
                        firing_rad: a.to_radians(),
                        firing_sin_cos: a.to_radians().sin_cos(),
                        pressure_scale: e.pressure_scale_of(c),
                    })
                })
                .collect();
            let per_cylinder = system
                .cylinder_spectrum
                .as_ref()
                .map_or(0.0, |s| s.mean_torque_nm());
            EnginePlant {
                area_m2: engine::piston_area_m2(e),
                crank_radius_m: e.crank_radius_m,
                lambda: engine::lambda(e),
                oscillating_mass_kg: engine::oscillating_mass_kg(e),
                cycle_rad,
                pressure_points_per_rad: pressure_pa.len() as f64 / cycle_rad,
                pressure_pa,
                mean_torque_nm: cylinders
                    .iter()
                    .map(|c| per_cylinder * c.pressure_scale * c.ratio)
                    .sum(),
                cylinders,
            }
        });
        let harmonics = model
            .harmonics
            .iter()
            .filter_map(|h| {
                let node = model.node_index(&h.at)?;
                Some(HarmonicPlant {
                    dof: system.dof_of_node[node],
                    ratio: system.speed_ratio[node],
                    order: h.order,
                    phase_rad: h.phase_deg.to_radians(),
                    amplitude: h.amplitude.clone(),
                })
            })
            .collect();
        let total: f64 = system.inertia_kg_m2.iter().sum();
        let governor = (model.load.is_some() || !model.is_grounded())
            .then(|| model.load_node().and_then(|name| model.node_index(name)))
            .flatten()
            .map(|node| {
                let w = std::f64::consts::TAU * GOVERNOR_HZ;
                Governor {
                    dof: system.dof_of_node[node],
                    kp: 2.0 * w * total,
                    ki: w * w * total,
                    total_inertia_kg_m2: total,
                    inertia_share: system.inertia_kg_m2.iter().map(|j| j / total).collect(),
                    rigid_angle_ref_rad: 0.0,
                    filter_state: state_len,
                    dissipation_torque_nm: 0.0,
                }
            });
        let state_len = state_len + usize::from(governor.is_some());
        let output_rows = connection_rows(elements.iter().map(|e| e.connection));
        Ok(Plant {
            output_rows,
            n_dof: n,
            inertia_kg_m2: inertia,
            damping_nm_s_per_rad: damping,
            elements,
            engine,
            harmonics,
            governor,
            reference_dof: system.dof_of_node[system.reference_node],
            state_len,
            system,
            start_temperature_c: model
                .connections
                .iter()
                .map(|c| match &c.kind {
                    ConnectionKind::Rubber(r) => Some(r.temperature_c),
                    _ => None,
                })
                .collect(),
        })
    }
}

impl Plant {
    /// State index of every self-heating rubber stage's temperature, in element order.
    pub fn thermal_states(&self) -> Vec<usize> {
        self.elements
            .iter()
            .filter_map(|e| match &e.law {
                PlantLaw::Rubber(r) => match r.temperature {
                    Temperature::Thermal { state, .. } => Some(state),
                    Temperature::Fixed(_) => None,
                },
                _ => None,
            })
            .collect()
    }

    /// Start temperature of the rubber stage of connection `connection`, °C.
    pub fn system_temperature(&self, connection: usize) -> f64 {
        self.start_temperature_c
            .get(connection)
            .copied()
            .flatten()
            .unwrap_or(25.0)
    }
}

impl Plant {
    /// The fastest rate of the linearized plant, rad/s: its highest natural frequency
    /// (undamped modes of the linear system) or its fastest Maxwell arm (1/τ), whichever
    /// is larger. Sets whether a run is stiff.
    pub fn fastest_rate_rad_s(&self) -> f64 {
        let modes = crate::modal::modes(&self.system).map_or(0.0, |m| {
            m.last()
                .map_or(0.0, |mode| std::f64::consts::TAU * mode.frequency_hz)
        });
        let arms = self
            .elements
            .iter()
            .filter_map(|e| match &e.law {
                PlantLaw::Rubber(r) => r
                    .chain
                    .arms
                    .iter()
                    .map(|(_, tau)| 1.0 / tau)
                    .reduce(f64::max),
                _ => None,
            })
            .fold(0.0, f64::max);
        modes.max(arms)
    }
}
