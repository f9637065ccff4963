//! The linear system at an operating point: degrees of freedom, inertias and elements
//! referred to the engine (reference) shaft through the gear tree.
//!
//! Referral (`spec/model-format.md`, gears): a node turning at `r` times the reference
//! speed has its inertia, stiffness and damping multiplied by `r²` and its torques by `r`;
//! its own-shaft angle is `r` times the referred one. A rigid gear makes its two nodes one
//! degree of freedom; a gear with mesh stiffness `k_m` (given at the `to` side) is a spring
//! `k_m·r_to²` between them.

use super::distributed::{Assembly, DistributedShaft, expand};
use super::element::{Element, ElementLaw};
use super::error::PhysicsError;
use super::excitation::{CylinderSpectrum, cylinder_spectrum};
use super::static_twist::static_state;
use super::topology::{free_components, merge_rigid_gears};
use crate::model::{ConnectionKind, GROUND, Model, graph};
use crate::rubber::MaxwellChain;

/// Where the linear analyses are evaluated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OperatingPoint {
    /// Engine load 0..1: picks the pressure curve (`pressure_by_load`) and so the mean
    /// torque that twists the rubber stages. Default 1.
    pub load: f64,
    /// Rubber temperature for every stage, °C; `None`: each stage's `temperature_c`.
    pub temperature_c: Option<f64>,
}

impl Default for OperatingPoint {
    fn default() -> Self {
        Self {
            load: 1.0,
            temperature_c: None,
        }
    }
}

/// The linear driveline at an operating point, referred to the reference shaft.
#[derive(Debug, Clone, PartialEq)]
pub struct System {
    /// Node names, in model order.
    pub node_names: Vec<String>,
    /// Mean speed of each node over the reference node's (signed).
    pub speed_ratio: Vec<f64>,
    /// DOF of each node (rigid gears put several nodes on one DOF).
    pub dof_of_node: Vec<usize>,
    /// Referred inertia of each DOF including the engine's cycle-mean reciprocating
    /// inertia, kg·m².
    pub inertia_kg_m2: Vec<f64>,
    /// Referred absolute damping of each DOF (node damping and load damping), N·m·s/rad.
    pub absolute_damping_nm_s_per_rad: Vec<f64>,
    /// The springs.
    pub elements: Vec<Element>,
    /// Connection names, in model order.
    pub connection_names: Vec<String>,
    /// Mean (static) torque through each connection in its own shaft, N·m; `None` for a
    /// rigid gear (no element carries it).
    pub mean_torque_nm: Vec<Option<f64>>,
    /// Static twist of each connection in its own shaft, rad (`None` for rigid gears).
    pub static_twist_rad: Vec<Option<f64>>,
    /// The reference node (engine speed).
    pub reference_node: usize,
    /// Number of rigid-body modes (free components of the DOF graph).
    pub rigid_body_modes: usize,
    /// One cylinder's torque spectrum at the operating point's load (`None` without an
    /// engine): the mean torque that twists the stages and the harmonics that drive them.
    pub cylinder_spectrum: Option<CylinderSpectrum>,
    /// Engine load the system was built at, 0..1.
    pub load: f64,
    /// Warnings raised while building (polynomials outside their range), for a person.
    pub warnings: Vec<String>,
    /// The causal chain each rubber stage is represented by, per connection (`None` for
    /// other connections, and for every connection of a [`System::nominal`]).
    pub chains: Vec<Option<MaxwellChain>>,
    /// Modal damping matrix `C_m` (`[modal_damping]`, [`super::modal_damping`]) in referred
    /// DOFs, N·m·s/rad; `None` without it. Part of C in every analysis.
    pub modal_damping: Option<nalgebra::DMatrix<f64>>,
    /// Shafts with their own inertia ([`super::distributed`]): each is a chain of segment
    /// elements whose internal DOFs follow the nodes' (no node maps to them).
    pub distributed: Vec<DistributedShaft>,
}

impl System {
    /// Number of degrees of freedom.
    pub fn dof_count(&self) -> usize {
        self.inertia_kg_m2.len()
    }

    /// True when some rubber stiffness depends on frequency.
    pub fn is_frequency_dependent(&self) -> bool {
        self.elements.iter().any(Element::is_frequency_dependent)
    }

    /// Checks that every rubber stage's α_f is positive at `frequency_hz` (seed 000 eq. 9
    /// turns negative above ~720 Hz unless a `frequency_poly_range` holds it).
    pub fn check_frequency(&self, frequency_hz: f64) -> Result<(), PhysicsError> {
        for e in &self.elements {
            if let ElementLaw::Rubber {
                frequency_poly: Some(p),
                ..
            } = &e.law
            {
                let value = p.eval(frequency_hz);
                if value.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                    return Err(PhysicsError::FrequencyFactor {
                        connection: self.connection_names[e.connection].clone(),
                        frequency_hz,
                        value,
                    });
                }
            }
        }
        Ok(())
    }

    /// Warnings for rubber stages whose α_f is held at an end of its measured range for
    /// some of `frequencies_hz` (one line per stage, for a person).
    pub fn frequency_range_warnings(&self, frequencies_hz: &[f64]) -> Vec<String> {
        let mut out = Vec::new();
        for e in &self.elements {
            if let ElementLaw::Rubber {
                frequency_poly: Some(p),
                ..
            } = &e.law
                && let Some([lo, hi]) = p.range
            {
                let outside: Vec<f64> = frequencies_hz
                    .iter()
                    .copied()
                    .filter(|f| *f < lo || *f > hi)
                    .collect();
                if let (Some(min), Some(max)) = (
                    outside.iter().copied().reduce(f64::min),
                    outside.iter().copied().reduce(f64::max),
                ) {
                    out.push(format!(
                        "rubber stage `{}`: frequency_poly was measured over {lo} … {hi} Hz; α_f is \
                         held at its end value for {} frequencies in {min:.1} … {max:.1} Hz",
                        self.connection_names[e.connection],
                        outside.len()
                    ));
                }
            }
        }
        out
    }

    /// Builds the system of a validated model at an operating point with seed 000's
    /// nominal rubber law, `k·α_f(f)·(1 + iξ_T)` ([`ElementLaw::Rubber`]), which is not
    /// causal: for comparison with the paper and closed-form checks, labelled "nominal"
    /// wherever it is shown. Every analysis uses [`System::new`].
    pub fn nominal(model: &Model, point: OperatingPoint) -> Result<Self, PhysicsError> {
        crate::model::validate(model)?;
        let ratios = graph::speed_ratios(model)?;
        let reference_node = graph::reference_node(model).ok_or(PhysicsError::Empty)?;
        let dof_of_node = merge_rigid_gears(model);
        let n_dof = dof_of_node.iter().max().map_or(0, |m| m + 1);

        let mut inertia = vec![0.0; n_dof];
        let mut damping = vec![0.0; n_dof];
        for (i, node) in model.inertias.iter().enumerate() {
            let r2 = ratios[i] * ratios[i];
            inertia[dof_of_node[i]] += node.inertia_kg_m2 * r2;
            damping[dof_of_node[i]] += node.damping_nm_s_per_rad * r2;
        }
        if let Some(engine) = &model.engine {
            for cylinder in 0..engine.cylinders as usize {
                if let Some(node) = model.node_index(engine.node_of_cylinder(cylinder)) {
                    let r2 = ratios[node] * ratios[node];
                    inertia[dof_of_node[node]] +=
                        super::engine::mean_reciprocating_inertia_kg_m2(engine) * r2;
                }
            }
        }
        if let (Some(load), Some(name)) = (&model.load, model.load_node())
            && let Some(node) = model.node_index(name)
        {
            damping[dof_of_node[node]] += load.damping_nm_s_per_rad * ratios[node] * ratios[node];
        }

        let dof = |name: &str| {
            (name != GROUND)
                .then(|| model.node_index(name).map(|i| dof_of_node[i]))
                .flatten()
        };
        let ratio_of = |name: &str| model.node_index(name).map_or(1.0, |i| ratios[i].abs());
        let shaft_ratio = |c: &crate::model::Connection| {
            if c.from == GROUND {
                ratio_of(&c.to)
            } else {
                ratio_of(&c.from)
            }
        };

        // Linear elements first (rubber at its linear static stiffness) for the static solve.
        let mut elements = Vec::new();
        let mut distributed = Vec::new();
        let mut warnings = Vec::new();
        let band_top_hz = crate::rubber::law_band_hz(model)[1];
        for (j, c) in model.connections.iter().enumerate() {
            let (from_dof, to_dof) = (dof(&c.from), dof(&c.to));
            let (torque_ratio, law) = match &c.kind {
                ConnectionKind::Shaft(s) if s.inertia_kg_m2 > 0.0 => {
                    let into = Assembly {
                        inertia: &mut inertia,
                        damping: &mut damping,
                        elements: &mut elements,
                        warnings: &mut warnings,
                    };
                    let shaft = (j, c.name.as_str(), s);
                    let ends = (from_dof, to_dof, shaft_ratio(c));
                    distributed.push(expand(shaft, ends, band_top_hz, into));
                    continue;
                }
                ConnectionKind::Shaft(s) => {
                    let r = shaft_ratio(c);
                    (
                        r,
                        ElementLaw::Linear {
                            stiffness_nm_per_rad: s.stiffness_nm_per_rad * r * r,
                            damping_nm_s_per_rad: s.damping_nm_s_per_rad * r * r,
                            distributed_inertia_kg_m2: 0.0,
                        },
                    )
                }
                ConnectionKind::Rubber(stage) => {
                    let r = shaft_ratio(c);
                    let temperature = point.temperature_c.unwrap_or(stage.temperature_c);
                    let state = stage.state(None, temperature, 0.0);
                    (
                        r,
                        ElementLaw::Linear {
                            stiffness_nm_per_rad: state.stiffness_nm_per_rad * r * r,
                            damping_nm_s_per_rad: 0.0,
                            distributed_inertia_kg_m2: 0.0,
                        },
                    )
                }
                ConnectionKind::Gear(g) => match g.mesh_stiffness_nm_per_rad {
                    None => continue,
                    Some(k) => {
                        let r = ratio_of(&c.to);
                        (
                            r,
                            ElementLaw::Linear {
                                stiffness_nm_per_rad: k * r * r,
                                damping_nm_s_per_rad: g.mesh_damping_nm_s_per_rad * r * r,
                                distributed_inertia_kg_m2: 0.0,
                            },
                        )
                    }
                },
            };
            elements.push(Element {
                connection: j,
                from_dof,
                to_dof,
                torque_ratio,
                law,
            });
        }

        let rigid_body_modes = free_components(inertia.len(), &elements);
        let mut system = System {
            node_names: model.inertias.iter().map(|n| n.name.clone()).collect(),
            speed_ratio: ratios,
            dof_of_node,
            inertia_kg_m2: inertia,
            absolute_damping_nm_s_per_rad: damping,
            elements,
            connection_names: model.connections.iter().map(|c| c.name.clone()).collect(),
            mean_torque_nm: vec![None; model.connections.len()],
            static_twist_rad: vec![None; model.connections.len()],
            reference_node,
            rigid_body_modes,
            cylinder_spectrum: model
                .engine
                .as_ref()
                .map(|e| cylinder_spectrum(e, point.load)),
            load: point.load,
            warnings,
            chains: vec![None; model.connections.len()],
            modal_damping: None,
            distributed,
        };

        static_state(model, &mut system, point)?;
        system.apply_modal_damping(model);
        Ok(system)
    }
}
