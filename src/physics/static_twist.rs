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
    let lu = k.clone().lu();
    let angle = match lu
        .solve(&torque)
        .filter(|a| a.iter().all(|v| v.is_finite()))
    {
        Some(angle) => angle,
        None => return Err(unheld(system, &k, &lu.u())),
    };
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

/// The error of a static solve whose matrix is singular, naming the node whose pivot
/// vanished (issue 13: the message named no node). With partial pivoting the columns keep
/// their order, so a zero on U's diagonal at column `j` is DOF `j`: the last node of a
/// part of the driveline that nothing holds.
fn unheld(system: &System, k: &DMatrix<f64>, u: &DMatrix<f64>) -> PhysicsError {
    let scale = k.diagonal().amax();
    let pivot = (0..u.nrows())
        .map(|j| (j, u[(j, j)].abs()))
        .min_by(|a, b| a.1.total_cmp(&b.1).then(b.0.cmp(&a.0)))
        .filter(|&(_, p)| p.is_nan() || p <= 1e-12 * scale);
    let nodes: Vec<String> = pivot.map_or_else(Vec::new, |(dof, _)| {
        system
            .dof_of_node
            .iter()
            .zip(&system.node_names)
            .filter(|(d, _)| **d == dof)
            .map(|(_, name)| format!("`{name}`"))
            .collect()
    });
    let which = if nodes.is_empty() {
        "a part of the driveline".to_string()
    } else {
        format!("node {} (with what is joined to it)", nodes.join(" and "))
    };
    PhysicsError::Singular(format!(
        "the mean torque has no static equilibrium: {which} is held neither by the load \
         nor by ground"
    ))
}

#[cfg(test)]
mod tests {
    use super::static_connection_torques;
    use crate::physics::{ElementLaw, OperatingPoint, System};

    /// a —shaft— b —shaft— c, engine at a, load at c; the shaft b–c then cut (stiffness
    /// 0, which validation refuses, so the system is edited after building).
    #[test]
    fn a_singular_static_solve_names_the_unheld_node() {
        let text = r#"format = 1
name = "t"
[[inertia]]
name = "a"
inertia = 1.0
[[inertia]]
name = "b"
inertia = 1.0
[[inertia]]
name = "c"
inertia = 1.0
[[connection]]
kind = "shaft"
from = "a"
to = "b"
stiffness = 1000.0
[[connection]]
kind = "shaft"
from = "b"
to = "c"
stiffness = 1000.0
[engine]
at = "a"
cylinders = 1
bore = 0.1
crank_radius = 0.05
conrod_length = 0.2
pressure = { crank_angle_deg = [0, 90, 180], bar = [50, 10, 0] }
[load]
at = "c"
"#;
        let model = crate::model::parse_model(text, "t.toml").unwrap();
        let point = OperatingPoint {
            load: 1.0,
            temperature_c: None,
        };
        let mut system = System::new(&model, point).unwrap();
        assert!(static_connection_torques(&model, &system).is_ok());
        system.elements[1].law = ElementLaw::Linear {
            stiffness_nm_per_rad: 0.0,
            damping_nm_s_per_rad: 0.0,
            distributed_inertia_kg_m2: 0.0,
        };
        let e = static_connection_torques(&model, &system)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("node `b` (with what is joined to it) is held neither by the load"),
            "{e}"
        );
    }
}
