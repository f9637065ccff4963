//! The IAS amplitude of every node per order over a list of speeds, and nothing else: the
//! diagnosis' linear surrogate asks for it tens of thousands of times a diagnosis
//! (a benchtruth campaign of seven recordings: 43 000 predictions, each over some 200
//! speeds), and the full sweep's element torques, losses and their nested result
//! vectors were most of its cost. Each point is solved as the full sweep solves it
//! ([`super::point::PointSolver`]), so the amplitudes are the same to the bit
//! (`tests::the_amplitudes_are_the_full_sweeps`).
//!
//! A speed whose point cannot be solved (a frequency outside the model's validity, an
//! undamped resonance) is marked as such; the others are still given, so one bad speed
//! does not take a whole campaign's prediction with it.

use super::point::PointSolver;
use super::sweep::check_sizes;
use crate::physics::{Excitation, PhysicsError, System};

/// IAS amplitudes per node, order and speed, rpm zero-to-peak, in each node's own shaft.
#[derive(Debug, Clone, PartialEq)]
pub struct OrderAmplitudes {
    n_orders: usize,
    n_speeds: usize,
    /// `[node][order][speed]`, flattened.
    values_rpm: Vec<f64>,
    /// Whether each speed's points were all solved.
    solved: Vec<bool>,
}

impl OrderAmplitudes {
    /// The amplitude of `node` (model node index) at order index `q` and speed index `s`,
    /// rpm; `None` when that speed could not be solved.
    pub fn rpm(&self, node: usize, q: usize, s: usize) -> Option<f64> {
        self.solved
            .get(s)
            .copied()
            .unwrap_or(false)
            .then(|| self.values_rpm[(node * self.n_orders + q) * self.n_speeds + s])
    }

    /// Whether every point of speed index `s` was solved.
    pub fn solved(&self, s: usize) -> bool {
        self.solved.get(s).copied().unwrap_or(false)
    }
}

/// The amplitudes of `system` driven by `excitation` at `speeds_rpm`, every order of the
/// excitation. An error only when the sweep is larger than the limits allow.
pub fn order_amplitudes(
    system: &System,
    excitation: &Excitation,
    speeds_rpm: &[f64],
) -> Result<OrderAmplitudes, PhysicsError> {
    let n_orders = excitation.orders.len();
    let n_speeds = speeds_rpm.len();
    check_sizes(&excitation.orders, n_speeds)?;
    let n_nodes = system.node_names.len();
    let mut out = OrderAmplitudes {
        n_orders,
        n_speeds,
        values_rpm: vec![0.0; n_nodes * n_orders * n_speeds],
        solved: vec![true; n_speeds],
    };
    let mut point = PointSolver::new(system, excitation);
    for (s, &speed) in speeds_rpm.iter().enumerate() {
        for q in 0..n_orders {
            let Ok(omega) = point.solve(speed, q) else {
                out.solved[s] = false;
                break;
            };
            for node in 0..n_nodes {
                out.values_rpm[(node * n_orders + q) * n_speeds + s] =
                    point.ias_amplitude_rpm(node, omega);
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::presets;
    use crate::physics::OperatingPoint;
    use crate::response::forced_response;

    /// On a 10-DOF engine model with rubber, over speeds that cross its resonances, every
    /// amplitude equals the full sweep's bit for bit.
    #[test]
    fn the_amplitudes_are_the_full_sweeps() {
        let preset = presets::preset("cng-genset").expect("preset");
        let model = crate::model::parse_model(preset.text, "cng-genset.toml").expect("model");
        let system = System::new(&model, OperatingPoint::default()).expect("system");
        let orders: Vec<f64> = (1..=12).map(|k| 0.5 * k as f64).collect();
        let excitation = Excitation::new(&model, &system, 1.0, &orders);
        let speeds: Vec<f64> = (0..150).map(|i| 400.0 + 11.3 * i as f64).collect();
        let full = forced_response(&system, &excitation, &speeds).expect("sweep");
        let lean = order_amplitudes(&system, &excitation, &speeds).expect("amplitudes");
        for (node, per_order) in full.ias_amplitude_rpm.iter().enumerate() {
            for (q, per_speed) in per_order.iter().enumerate() {
                for (s, v) in per_speed.iter().enumerate() {
                    assert_eq!(lean.rpm(node, q, s), Some(*v), "{node} {q} {s}");
                }
            }
        }
    }

    /// A speed whose order-1 frequency is past the point where the rubber's frequency
    /// factor `1 − 10⁻⁴f²` reaches zero (100 Hz, 6000 rpm) is marked unsolved; the speeds
    /// on either side keep their amplitudes, the full sweep's.
    #[test]
    fn an_unsolvable_speed_leaves_the_others() {
        let text = r#"format = 1
name = "two-dof"
[[inertia]]
name = "a"
inertia = 0.4
[[inertia]]
name = "b"
inertia = 1.5
[[connection]]
kind = "rubber"
name = "rubber"
from = "a"
to = "b"
stiffness = 6.0e3
psi = 0.8
frequency_poly = [-1.0e-4, 0.0, 1.0]
[[connection]]
kind = "shaft"
name = "shaft"
from = "b"
to = "ground"
stiffness = 4.0e4
[[harmonic]]
at = "a"
order = 1
amplitude = 100.0
phase_deg = 0.0
"#;
        let model = crate::model::parse_model(text, "two-dof.toml").expect("model");
        let system = System::nominal(&model, OperatingPoint::default()).expect("system");
        let excitation = Excitation::new(&model, &system, 1.0, &[1.0]);
        let speeds = [1500.0, 7000.0, 1800.0];
        let lean = order_amplitudes(&system, &excitation, &speeds).expect("amplitudes");
        assert!(lean.solved(0) && !lean.solved(1) && lean.solved(2));
        assert_eq!(lean.rpm(0, 0, 1), None);
        assert!(forced_response(&system, &excitation, &speeds).is_err());
        let full = forced_response(&system, &excitation, &[1500.0, 1800.0]).expect("sweep");
        assert_eq!(lean.rpm(1, 0, 0), Some(full.ias_amplitude_rpm[1][0][0]));
        assert_eq!(lean.rpm(1, 0, 2), Some(full.ias_amplitude_rpm[1][0][1]));
    }
}
