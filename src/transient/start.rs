//! The state a run starts from: the static twist of the mean torque (the rubber stages at
//! their secant stiffness there), no vibration speed, Maxwell arms relaxed, rubber at its
//! start temperature. Starting there shortens settling to the decay of the vibration.

use super::TransientError;
use super::plant::{Plant, PlantLaw, Temperature};
use crate::physics::matrices::add_spring;
use nalgebra::{DMatrix, DVector};

/// Initial state vector of `plant` at reference speed `start_rad_s` (the nodes' absolute
/// damping drags the mean rotation there, as in [`Plant::derivatives`]).
pub fn initial_state(plant: &Plant, start_rad_s: f64) -> Result<Vec<f64>, TransientError> {
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
    if let Some(g) = &plant.governor {
        for i in (0..n).filter(|&i| i != g.dof) {
            torque[i] -= plant.damping_nm_s_per_rad[i] * start_rad_s;
        }
    }
    if torque.iter().any(|t| *t != 0.0) {
        let mut k = DMatrix::<f64>::zeros(n, n);
        for e in &plant.elements {
            let linear = sys.elements.iter().find(|s| s.connection == e.connection);
            let secant_ref = match (
                sys.mean_torque_nm[e.connection],
                sys.static_twist_rad[e.connection],
                linear,
            ) {
                (Some(t), Some(twist), _) if twist != 0.0 => t / twist * e.ratio * e.ratio,
                (_, _, Some(s)) => s.stiffness_at(0.0).0,
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

#[cfg(test)]
mod tests {
    use super::initial_state;
    use crate::transient::SpeedProfile;
    use crate::transient::plant::Plant;
    use std::f64::consts::TAU;

    /// a —shaft— b —shaft— c, load at c, absolute damping 0.5 N·m·s/rad at a only, a
    /// vanishing harmonic (the model needs an excitation).
    const DRAGGED: &str = r#"format = 1
name = "t"
[[inertia]]
name = "a"
inertia = 0.2
damping = 0.5
[[inertia]]
name = "b"
inertia = 0.1
[[inertia]]
name = "c"
inertia = 1.0
[[connection]]
kind = "shaft"
from = "a"
to = "b"
stiffness = 1.0e4
[[connection]]
kind = "shaft"
from = "b"
to = "c"
stiffness = 2.0e4
[[harmonic]]
at = "a"
order = 1
amplitude = 1e-12
phase_deg = 0
[load]
at = "c"
"#;

    /// The start is the static equilibrium with the mean drag `c·Ω` of a's absolute
    /// damping (model-format.md "to the frame"): both shafts carry −c·Ω (the load drives
    /// a against its drag), and no DOF accelerates there. Without the drag the twists are
    /// zero; without it in the forces a accelerates at c·Ω/J_a = 785 rad/s².
    #[test]
    fn the_start_and_the_forces_carry_the_mean_drag_of_absolute_damping() {
        let model = crate::model::parse_model(DRAGGED, "t.toml").unwrap();
        let plant = Plant::new(&model, 1.0, [3000.0, 3000.0], None).unwrap();
        let omega = 3000.0 * TAU / 60.0;
        let y = initial_state(&plant, omega).unwrap();
        let drag = 0.5 * omega;
        // Static solve of two springs: exact to rounding.
        assert!(((y[0] - y[1]) * 1.0e4 + drag).abs() < 1e-9 * drag, "{y:?}");
        assert!(((y[1] - y[2]) * 2.0e4 + drag).abs() < 1e-9 * drag, "{y:?}");
        let mut dy = vec![0.0; y.len()];
        let mut mass = vec![0.0; plant.n_dof];
        plant.derivatives(0.0, &y, &mut dy, &SpeedProfile::steady(3000.0), &mut mass);
        // Accelerations of a and b: the spring and drag cancel to rounding of ~80 N·m.
        assert!(dy[3..6].iter().all(|a| a.abs() < 1e-9), "{dy:?}");
    }
}
