//! The static state: the mean torque through every connection (the engine's cycle-mean
//! torque enters at the cylinders' nodes and leaves at the load node, or through the
//! ground connections), the twist it makes, and the elements linearised there.

use super::element::{ElementLaw, rubber_law};
use super::error::PhysicsError;
use super::system::System;
use crate::model::{ConnectionKind, Model};
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

/// The static state of `system` at `point`: the mean torque through every connection
/// ([`static_connection_torques`]), the static twist it makes, and each element's law
/// linearised there — a rubber stage at its tangent stiffness (seed 000 eq. 1–2, 13), a
/// gear with a softened contact at its tangent ([`super::dead_zone::contact_point`]).
pub(super) fn static_state(
    model: &Model,
    system: &mut System,
    point: super::system::OperatingPoint,
) -> Result<(), PhysicsError> {
    let mean_torques = static_connection_torques(model, system)?;
    for (e, torque) in system.elements.iter().zip(&mean_torques) {
        system.mean_torque_nm[e.connection] = Some(*torque);
    }
    let mut segments_of = vec![1; model.connections.len()];
    for d in &system.distributed {
        segments_of[d.connection] = d.segments();
    }
    // Each element at its static twist: rubber and softened gear contacts at their tangent.
    for e in &mut system.elements {
        let c = &model.connections[e.connection];
        let torque = system.mean_torque_nm[e.connection].unwrap_or(0.0);
        let r2 = e.torque_ratio * e.torque_ratio;
        match &c.kind {
            ConnectionKind::Rubber(stage) => {
                let temperature = point.temperature_c.unwrap_or(stage.temperature_c);
                let (law, twist) = rubber_law(
                    stage,
                    &c.name,
                    torque,
                    temperature,
                    r2,
                    &mut system.warnings,
                )?;
                e.law = law;
                system.static_twist_rad[e.connection] = Some(twist);
            }
            ConnectionKind::Gear(g) if g.backlash_deg > 0.0 || g.contact_exponent != 1.0 => {
                // A softened or power-law contact works at the twist its mean torque
                // needs, with its tangent there (`tooth_contact`); a hard linear one at
                // the mesh stiffness.
                let (k, _) = e.stiffness_at(0.0);
                let deflection = torque / (k / r2);
                let contact = super::tooth_contact::ToothContact {
                    half_gap_rad: 0.5 * g.backlash_deg.to_radians(),
                    softening_rad: g.backlash_softening_deg.to_radians(),
                    exponent: g.contact_exponent,
                    reference_rad: g.contact_reference_deg.to_radians(),
                }
                .working_point(deflection);
                let (twist, share) = contact.unwrap_or((deflection, 1.0));
                if let ElementLaw::Linear {
                    stiffness_nm_per_rad,
                    ..
                } = &mut e.law
                {
                    *stiffness_nm_per_rad *= share;
                }
                system.static_twist_rad[e.connection] = Some(twist);
            }
            _ => {
                // A distributed shaft's segments each carry the torque: n × one's twist.
                let (k, _) = e.stiffness_at(0.0);
                let segments = segments_of[e.connection] as f64;
                system.static_twist_rad[e.connection] = Some(segments * torque / (k / r2));
            }
        }
    }
    Ok(())
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
