//! Modal strain energy: where a mode stores its potential energy.
//!
//! For a mode of shape φ (referred coordinates) at frequency f, element e between DOFs a
//! and b (or a DOF and the frame) stores `E_e = ½·k_e(f)·(φ_a − φ_b)²` at unit modal
//! coordinate; the sum over the elements is `½ φᵀK(f)φ = ½ω²` for a mass-normalised shape
//! (Rayleigh). The share `E_e / Σ E` says which element the mode is "in": a coupling mode
//! has most of its energy in the rubber, a crank mode in the crankshaft. Rubber stiffness
//! is taken at the mode's own frequency (α_f(f), seed 000 eq. 9), as in [`super::modes`].

use super::undamped::Mode;
use crate::physics::System;
use crate::physics::distributed::connection_rows;

/// Strain energy of each element of `system` (in element order) for `mode` at unit modal
/// coordinate, J (N·m·rad² for a mass-normalised shape in kg·m²-referred coordinates).
pub fn strain_energy_j(system: &System, mode: &Mode) -> Vec<f64> {
    let at = |dof: Option<usize>| dof.map_or(0.0, |d| mode.shape_dof[d]);
    system
        .elements
        .iter()
        .map(|e| {
            let (k, _) = e.stiffness_at(mode.frequency_hz);
            let twist = at(e.from_dof) - at(e.to_dof);
            0.5 * k * twist * twist
        })
        .collect()
}

/// Share of the mode's strain energy in each element of `system` (in element order,
/// 0…1, summing to 1; all zero if the mode stores none).
pub fn strain_energy_shares(system: &System, mode: &Mode) -> Vec<f64> {
    let energy = strain_energy_j(system, mode);
    let total: f64 = energy.iter().sum();
    if total > 0.0 {
        energy.iter().map(|e| e / total).collect()
    } else {
        vec![0.0; energy.len()]
    }
}

/// Per-element `shares` summed per connection, `(connection index, share)` in the order of
/// each connection's first element: a distributed shaft's segments are one connection.
pub fn shares_by_connection(system: &System, shares: &[f64]) -> Vec<(usize, f64)> {
    let rows = connection_rows(system.elements.iter().map(|e| e.connection));
    let mut out: Vec<(usize, f64)> = Vec::new();
    for ((e, &share), (_, first)) in system.elements.iter().zip(shares).zip(rows) {
        match out.last_mut() {
            Some((_, sum)) if !first => *sum += share,
            _ => out.push((e.connection, share)),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::modal::modes;
    use crate::model::parse_model;
    use crate::physics::OperatingPoint;
    use std::f64::consts::TAU;

    fn system(text: &str) -> System {
        let model = parse_model(text, "energy.toml").unwrap();
        System::new(&model, OperatingPoint::default()).unwrap()
    }

    fn inertia(name: &str, j: f64) -> String {
        format!("[[inertia]]\nname = \"{name}\"\ninertia = {j}\n")
    }

    fn shaft(from: &str, to: &str, k: f64) -> String {
        format!(
            "[[connection]]\nkind = \"shaft\"\nfrom = \"{from}\"\nto = \"{to}\"\nstiffness = {k}\n"
        )
    }

    /// Rayleigh: the element energies of a mass-normalised mode add up to ½ω².
    fn assert_rayleigh(system: &System, mode: &Mode) {
        let total: f64 = strain_energy_j(system, mode).iter().sum();
        let half_omega2 = 0.5 * (TAU * mode.frequency_hz).powi(2);
        assert!(
            (total - half_omega2).abs() < 1e-10 * half_omega2,
            "{total} vs {half_omega2}"
        );
    }

    /// Two inertias and one spring, free-free: the one flexible mode keeps all of its
    /// strain energy in the spring.
    #[test]
    fn two_dof_free_free_is_all_in_the_spring() {
        let s = system(&format!(
            "format = 1\nname = \"ff\"\n{}{}{}",
            inertia("a", 0.4),
            inertia("b", 1.3),
            shaft("a", "b", 5.0e4)
        ));
        let m = modes(&s).unwrap();
        assert_eq!(m.len(), 1);
        assert_eq!(strain_energy_shares(&s, &m[0]), vec![1.0]);
        assert_rayleigh(&s, &m[0]);
    }

    /// Fixed-free chain of two equal inertias J on two equal springs k: mode 1 has
    /// φ_b/φ_a = g = (1+√5)/2, so the ground spring holds k·1² and the other k·(g−1)² =
    /// k/g²: shares g²/(g²+1) and 1/(g²+1) (0.7236, 0.2764). Mode 2 has φ_b/φ_a = 1 − g:
    /// shares 1/(1+g²) and g²/(1+g²). A longer chain's shares sum to 1.
    #[test]
    fn chain_shares_are_exact_and_sum_to_one() {
        let s = system(&format!(
            "format = 1\nname = \"chain\"\n{}{}{}{}",
            inertia("a", 0.5),
            inertia("b", 0.5),
            shaft("ground", "a", 2.0e4),
            shaft("a", "b", 2.0e4)
        ));
        let m = modes(&s).unwrap();
        let g2 = ((1.0 + 5f64.sqrt()) / 2.0).powi(2);
        let first = strain_energy_shares(&s, &m[0]);
        let second = strain_energy_shares(&s, &m[1]);
        for (got, want) in [
            (first[0], g2 / (g2 + 1.0)),
            (first[1], 1.0 / (g2 + 1.0)),
            (second[0], 1.0 / (g2 + 1.0)),
            (second[1], g2 / (g2 + 1.0)),
        ] {
            assert!((got - want).abs() < 1e-12, "{got} vs {want}");
        }
        let long = system(&format!(
            "format = 1\nname = \"long\"\n{}{}{}{}{}{}{}",
            inertia("a", 0.2),
            inertia("b", 0.9),
            inertia("c", 0.05),
            inertia("d", 2.0),
            shaft("a", "b", 3.0e4),
            shaft("b", "c", 8.0e5),
            shaft("c", "d", 1.2e4)
        ));
        for mode in modes(&long).unwrap() {
            let shares = strain_energy_shares(&long, &mode);
            assert!((shares.iter().sum::<f64>() - 1.0).abs() < 1e-12);
            assert!(shares.iter().all(|s| (0.0..=1.0).contains(s)));
            assert_rayleigh(&long, &mode);
        }
    }
}
