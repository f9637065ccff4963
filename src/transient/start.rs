//! The state a run starts from: the static twist of the mean torque (the rubber stages at
//! their secant stiffness there), no vibration speed, Maxwell arms relaxed, rubber at its
//! start temperature. Starting there shortens settling to the decay of the vibration.

use super::TransientError;
use super::plant::{Plant, PlantLaw, Temperature};
use crate::physics::matrices::add_spring;
use nalgebra::{DMatrix, DVector};

/// Initial state vector of `plant`.
pub fn initial_state(plant: &Plant) -> Result<Vec<f64>, TransientError> {
    let n = plant.n_dof;
    let sys = &plant.system;
    let mut y = vec![0.0; plant.state_len];
    let mut torque = DVector::<f64>::zeros(n);
    if let Some(engine) = &plant.engine {
        let per_cylinder = sys
            .cylinder_spectrum
            .as_ref()
            .map_or(0.0, |s| s.mean_torque_nm());
        for c in &engine.cylinders {
            torque[c.dof] += per_cylinder * c.pressure_scale * c.ratio;
        }
    }
    if torque.iter().any(|t| *t != 0.0) {
        let mut k = DMatrix::<f64>::zeros(n, n);
        for e in &plant.elements {
            let linear = sys.elements.iter().find(|s| s.connection == e.connection);
            let secant_ref = match (
                &e.law,
                sys.mean_torque_nm[e.connection],
                sys.static_twist_rad[e.connection],
                linear,
            ) {
                // A linear element is its own stiffness (a distributed shaft's segment too).
                (PlantLaw::Linear { stiffness, .. }, ..) => *stiffness,
                (_, Some(t), Some(twist), _) if twist != 0.0 => t / twist * e.ratio * e.ratio,
                (_, _, _, Some(s)) => s.stiffness_at(0.0).0,
                _ => 0.0,
            };
            add_spring(&mut k, e.from_dof, e.to_dof, secant_ref);
        }
        if let Some(g) = &plant.governor {
            for i in 0..n {
                k[(g.dof, i)] = 0.0;
                k[(i, g.dof)] = 0.0;
            }
            k[(g.dof, g.dof)] = 1.0;
            torque[g.dof] = 0.0;
        }
        let angles = k
            .lu()
            .solve(&torque)
            .filter(|a| a.iter().all(|v| v.is_finite()))
            .ok_or_else(|| {
                TransientError::Model(
                    "no static equilibrium under the mean torque (a free part of the driveline)"
                        .into(),
                )
            })?;
        y[..n].copy_from_slice(angles.as_slice());
    }
    for e in &plant.elements {
        if let PlantLaw::Rubber(r) = &e.law {
            let twist_own =
                e.ratio * (e.from_dof.map_or(0.0, |d| y[d]) - e.to_dof.map_or(0.0, |d| y[d]));
            for j in 0..r.chain.arms.len() {
                y[r.arm_offset + j] = twist_own;
            }
            if let Temperature::Thermal { state, .. } = r.temperature {
                y[state] = plant.system_temperature(e.connection);
            }
        }
    }
    Ok(y)
}
