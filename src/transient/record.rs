//! Recording a run: the [`Simulation`] sized for all its samples, and each sample written
//! into it from the integrator's state — every node's speed, every element's torque and
//! the mean power it dissipates, every thermal stage's temperature.

use super::plant::{Plant, PlantLaw, Temperature};
use super::run::Simulation;
use super::settle::Settling;
use super::speed::SpeedProfile;
use std::f64::consts::TAU;

/// The simulation of `plant` with every series zeroed at `samples` samples.
pub(super) fn empty_simulation(plant: &Plant, samples: usize, settling: Settling) -> Simulation {
    let sys = &plant.system;
    let thermal = plant.elements.iter().filter_map(|e| match &e.law {
        PlantLaw::Rubber(r) if matches!(r.temperature, Temperature::Thermal { .. }) => {
            Some((e.connection, vec![0.0; samples]))
        }
        _ => None,
    });
    Simulation {
        node_names: sys.node_names.clone(),
        reference_node: sys.reference_node,
        speed_ratio: sys.speed_ratio.clone(),
        time_s: vec![0.0; samples],
        speed_rpm: vec![vec![0.0; samples]; sys.node_names.len()],
        torque_nm: plant
            .elements
            .iter()
            .zip(plant.output_rows.iter().copied())
            .filter(|(_, (_, first))| *first)
            .map(|(e, _)| (e.connection, vec![0.0; samples]))
            .collect(),
        power_loss_w: plant
            .elements
            .iter()
            .zip(plant.output_rows.iter().copied())
            .filter(|(_, (_, first))| *first)
            .map(|(e, _)| (e.connection, 0.0))
            .collect(),
        temperature_c: thermal.collect(),
        connection_names: sys.connection_names.clone(),
        chains: plant
            .elements
            .iter()
            .filter_map(|e| match &e.law {
                PlantLaw::Rubber(r) => Some((e.connection, r.chain.clone())),
                _ => None,
            })
            .collect(),
        settling,
        steps: (0, 0),
        warnings: Vec::new(),
    }
}

/// What a run records per sample, worked out once: where each node's speed is in the
/// state, which states are temperatures, how many samples the mean power is over.
pub(super) struct Recorder<'a> {
    plant: &'a Plant,
    /// Per node: the index of its DOF's speed in the state and `|speed ratio|·60/2π`
    /// (rad/s of the reference's shaft to rpm of the node's).
    nodes: Vec<(usize, f64)>,
    /// The temperature state of every thermal rubber stage, in the order of
    /// [`Simulation::temperature_c`].
    thermal: Vec<usize>,
    /// 1 / samples of the whole recording.
    per_sample: f64,
}

impl<'a> Recorder<'a> {
    /// The recorder of `samples` samples of `plant`.
    pub(super) fn new(plant: &'a Plant, samples: usize) -> Self {
        let sys = &plant.system;
        Self {
            plant,
            nodes: sys
                .dof_of_node
                .iter()
                .zip(&sys.speed_ratio)
                .map(|(&dof, ratio)| (plant.n_dof + dof, ratio.abs() * 60.0 / TAU))
                .collect(),
            thermal: plant.thermal_states(),
            per_sample: 1.0 / samples.max(1) as f64,
        }
    }

    /// Writes sample `k` of every output from state `y` at time `t`; appends the
    /// instantaneous power of each element to `power_now` when given (an observed run's
    /// chunks carry it; [`Simulation`] keeps only its mean).
    pub(super) fn record(
        &self,
        profile: &SpeedProfile,
        t: f64,
        y: &[f64],
        k: usize,
        sim: &mut Simulation,
        mut power_now: Option<&mut [Vec<f64>]>,
    ) {
        let plant = self.plant;
        let big_omega = profile.at(t).1;
        for (speeds, &(state, ratio)) in sim.speed_rpm.iter_mut().zip(&self.nodes) {
            speeds[k] = ratio * (big_omega + y[state]);
        }
        let rows = plant.output_rows.iter().copied();
        for (e, (row, first)) in plant.elements.iter().zip(rows) {
            let state = plant.element_state(e, y, None);
            if first {
                // A shaft's own ratio is 1: the division would change nothing.
                sim.torque_nm[row].1[k] = if e.ratio == 1.0 {
                    state.torque_ref_nm
                } else {
                    state.torque_ref_nm / e.ratio
                };
            }
            if let Some(power) = power_now.as_deref_mut() {
                if first {
                    power[row].push(state.power_w);
                } else if let Some(last) = power[row].last_mut() {
                    *last += state.power_w;
                }
            }
            sim.power_loss_w[row].1 += state.power_w * self.per_sample;
        }
        for ((_, temps), &state) in sim.temperature_c.iter_mut().zip(&self.thermal) {
            temps[k] = y[state];
        }
    }
}
