//! The linear model over a whole campaign: one system, one excitation and one amplitude
//! sweep ([`crate::response::order_amplitudes`]) per operating point, shared by every
//! run at it.
//!
//! A campaign's regimes are mostly at one load (every benchtruth campaign's are at full
//! load), and a prediction built the same causal system, with its chain fit
//! ([`crate::rubber`]), once per run and once more for the sensors' speed ratios: seven
//! or eight identical systems for one model. It also swept each steady part's wobble
//! speeds ([`super::spread`]) on their own. Here the runs at one load and with one set
//! of orders share one system and one sweep over the union of the speeds they ask for.
//! Every point is solved as before, so the prediction is the same to the bit
//! (`surrogate::tests`).

use super::observe::Observed;
use super::spread::run_orders;
use super::surrogate::causal_system;
use crate::model::Model;
use crate::physics::{Excitation, System};
use crate::response::{OrderAmplitudes, order_amplitudes};

/// The runs at one load with the same observed orders.
struct Group {
    /// Engine load 0..1.
    load: f64,
    /// The orders observed, sorted.
    orders: Vec<f64>,
    /// The causal system at `load`, and the amplitudes at `speeds_rpm` (sorted, each
    /// once); `None` when the system cannot be built or the sweep is over the limits.
    swept: Option<(System, OrderAmplitudes)>,
    speeds_rpm: Vec<f64>,
}

/// Where one station's amplitudes at one order are in [`CampaignSweeps`].
#[derive(Debug, Clone, Copy)]
pub(super) struct Found {
    group: usize,
    node: usize,
    q: usize,
}

/// The campaign's sweeps.
pub(super) struct CampaignSweeps {
    groups: Vec<Group>,
    /// The group of each run.
    group_of_run: Vec<usize>,
}

impl CampaignSweeps {
    /// Sweeps `model` at every speed `speeds_of(run)` asks for (rpm).
    pub(super) fn new(
        model: &Model,
        observed: &Observed,
        speeds_of: impl Fn(usize) -> Vec<f64>,
    ) -> Self {
        let mut groups: Vec<Group> = Vec::new();
        let mut group_of_run = Vec::with_capacity(observed.runs.len());
        for (r, run) in observed.runs.iter().enumerate() {
            let orders = run_orders(observed, r);
            let k = match groups
                .iter()
                .position(|g| g.load.to_bits() == run.load.to_bits() && g.orders == orders)
            {
                Some(k) => k,
                None => {
                    groups.push(Group {
                        load: run.load,
                        orders,
                        swept: None,
                        speeds_rpm: Vec::new(),
                    });
                    groups.len() - 1
                }
            };
            groups[k].speeds_rpm.extend(speeds_of(r));
            group_of_run.push(k);
        }
        for g in &mut groups {
            g.speeds_rpm.sort_by(f64::total_cmp);
            g.speeds_rpm.dedup_by(|a, b| a.to_bits() == b.to_bits());
            g.swept = causal_system(model, g.load).and_then(|system| {
                let excitation = Excitation::new(model, &system, g.load, &g.orders);
                let amplitudes = order_amplitudes(&system, &excitation, &g.speeds_rpm).ok()?;
                Some((system, amplitudes))
            });
        }
        Self {
            groups,
            group_of_run,
        }
    }

    /// The causal system of run `run`, if it could be built and swept.
    pub(super) fn system(&self, run: usize) -> Option<&System> {
        let g = &self.groups[*self.group_of_run.get(run)?];
        g.swept.as_ref().map(|(system, _)| system)
    }

    /// Where the amplitudes of `station` at `order` in run `run` are; `None` where the
    /// system, the node or the order is missing.
    pub(super) fn find(&self, run: usize, station: &str, order: f64) -> Option<Found> {
        let group = *self.group_of_run.get(run)?;
        let g = &self.groups[group];
        let (system, _) = g.swept.as_ref()?;
        Some(Found {
            group,
            node: system.node_names.iter().position(|n| n == station)?,
            q: g.orders.iter().position(|x| (x - order).abs() < 1e-9)?,
        })
    }

    /// The amplitude at `found` and `speed_rpm` (one of the speeds asked for), rpm;
    /// `None` where that speed's solve failed.
    pub(super) fn at(&self, found: Found, speed_rpm: f64) -> Option<f64> {
        let g = &self.groups[found.group];
        let (_, amplitudes) = g.swept.as_ref()?;
        let s = g
            .speeds_rpm
            .binary_search_by(|v| v.total_cmp(&speed_rpm))
            .ok()?;
        amplitudes.rpm(found.node, found.q, s)
    }

    /// Each node's mean speed over the reference's, from a system at full load (that of
    /// [`super::surrogate::ratios`]) when the campaign has one; `None` otherwise.
    pub(super) fn ratios_at_full_load(&self) -> Option<Vec<(String, f64)>> {
        let g = self
            .groups
            .iter()
            .find(|g| g.load.to_bits() == 1f64.to_bits())?;
        let (system, _) = g.swept.as_ref()?;
        Some(
            system
                .node_names
                .iter()
                .cloned()
                .zip(system.speed_ratio.iter().copied())
                .collect(),
        )
    }
}
