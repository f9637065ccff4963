//! The mean torque through every connection: the engine's cycle-mean torque enters at the
//! cylinders' nodes and leaves at the load node (or through the ground connections).

use super::error::PhysicsError;
use super::system::System;
use crate::model::Model;
use nalgebra::{DMatrix, DVector};

/// Mean torque through each element of `system` (in element order), in the connection's
/// own shaft, N·m, positive when `from` drives `to`.
///
/// Solves `K θ = T_mean` with the linear (static) stiffnesses and the load node held;
/// for a tree the result does not depend on the stiffnesses (statically determinate).
/// A model with a connection to ground and no `[load]` lets the ground hold the torque.
pub fn static_connection_torques(model: &Model, system: &System) -> Result<Vec<f64>, PhysicsError> {
    let n = system.dof_count();
    let mut torque = DVector::<f64>::zeros(n);
    if let (Some(engine), Some(spectrum)) = (&model.engine, &system.cylinder_spectrum) {
        let per_cylinder = spectrum.mean_torque_nm();
        for cylinder in 0..engine.cylinders as usize {
            if let Some(node) = model.node_index(engine.node_of_cylinder(cylinder)) {
                torque[system.dof_of_node[node]] +=
                    per_cylinder * engine.pressure_scale_of(cylinder) * system.speed_ratio[node];
            }
        }
    }
    if torque.iter().all(|t| *t == 0.0) {
        return Ok(vec![0.0; system.elements.len()]);
    }
    let held = if model.load.is_some() || !model.is_grounded() {
        model
            .load_node()
            .and_then(|name| model.node_index(name))
            .map(|node| system.dof_of_node[node])
    } else {
        None
    };
    let mut k = DMatrix::<f64>::zeros(n, n);
    for e in &system.elements {
        let (stiffness, _) = e.stiffness_at(0.0);
        super::matrices::add_spring(&mut k, e.from_dof, e.to_dof, stiffness);
    }
    if let Some(h) = held {
        for i in 0..n {
            k[(h, i)] = 0.0;
            k[(i, h)] = 0.0;
        }
        k[(h, h)] = 1.0;
        torque[h] = 0.0;
    }
    let angle = k
        .lu()
        .solve(&torque)
        .filter(|a| a.iter().all(|v| v.is_finite()))
        .ok_or_else(|| {
            PhysicsError::Singular(
                "the mean torque has no static equilibrium (a part of the driveline is \
                 held neither by the load nor by ground)"
                    .into(),
            )
        })?;
    Ok(system
        .elements
        .iter()
        .map(|e| {
            let (stiffness, _) = e.stiffness_at(0.0);
            let a = e.from_dof.map_or(0.0, |d| angle[d]);
            let b = e.to_dof.map_or(0.0, |d| angle[d]);
            stiffness * (a - b) / e.torque_ratio
        })
        .collect())
}
