//! A direct solve of the dynamic stiffness equations in O(n) for tree-shaped drivelines.
//!
//! A driveline's elements join its DOFs (after rigid gears are merged) into a forest in
//! almost every real case: a chain of crank throws, flywheel, coupling stages and
//! generator, with gears that branch but never close a loop. Eliminating a tree's DOFs
//! leaves first creates no fill-in: each leaf only updates its parent's diagonal and
//! right-hand side (`d_p −= z²/d_i`, `b_p −= z·b_i/d_i`), and the back substitution runs
//! root first (`x_i = (b_i − z·x_p)/d_i`, with `z` the off-diagonal entry). That replaces
//! the dense n×n assembly and LU of every (speed, order) pair.
//!
//! The elimination order is fixed by the graph, not by pivoting. It is exact when every
//! pivot is well away from zero; a pivot that shrinks below [`PIVOT_FLOOR`] times the
//! DOF's own diagonal (a subtree sitting within 1e-6 of its blocked-end resonance)
//! returns `false`, and the caller falls back to the pivoting dense LU for that frequency.
//! Graphs with a loop (a ring of DOFs) are not trees: [`TreeSolver::new`] returns `None`.

use crate::physics::System;
use num_complex::Complex64;

/// Smallest |pivot| accepted, relative to the DOF's diagonal before elimination.
const PIVOT_FLOOR: f64 = 1e-6;

/// The elimination order of a tree-shaped system, reused for every frequency.
#[derive(Debug, Clone)]
pub(crate) struct TreeSolver {
    /// DOFs leaves first: every DOF comes after all of its children.
    order: Vec<usize>,
    /// Parent of each DOF (`None` for a root of its component).
    parent: Vec<Option<usize>>,
    /// For each element joining two DOFs: the child DOF of that edge (the edge's
    /// off-diagonal entry is stored at the child); `None` for grounded elements.
    element_child: Vec<Option<usize>>,
    /// Diagonal, off-diagonal (at the child) and the diagonals before elimination.
    diag: Vec<Complex64>,
    off: Vec<Complex64>,
    original: Vec<Complex64>,
}

impl TreeSolver {
    /// The solver for `system`, or `None` when its DOF graph has a loop, its damping
    /// matrix is full (modal damping couples every DOF) or it has a distributed shaft
    /// (whose exact element is no spring). Parallel elements between the
    /// same two DOFs share one edge.
    pub(crate) fn new(system: &System) -> Option<Self> {
        if system.modal_damping.is_some() || !system.distributed.is_empty() {
            return None;
        }
        let n = system.dof_count();
        let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); n];
        for e in &system.elements {
            if let (Some(a), Some(b)) = (e.from_dof, e.to_dof) {
                if a == b {
                    continue;
                }
                if !neighbours[a].contains(&b) {
                    neighbours[a].push(b);
                    neighbours[b].push(a);
                }
            }
        }
        // Depth-first from each unvisited DOF; a visited neighbour other than the parent
        // closes a loop.
        let mut parent: Vec<Option<usize>> = vec![None; n];
        let mut visited = vec![false; n];
        let mut preorder = Vec::with_capacity(n);
        for root in 0..n {
            if visited[root] {
                continue;
            }
            visited[root] = true;
            let mut stack = vec![root];
            while let Some(i) = stack.pop() {
                preorder.push(i);
                for &j in &neighbours[i] {
                    if Some(j) == parent[i] {
                        continue;
                    }
                    if visited[j] {
                        return None;
                    }
                    visited[j] = true;
                    parent[j] = Some(i);
                    stack.push(j);
                }
            }
        }
        // Reversed preorder puts every child before its parent.
        preorder.reverse();
        let element_child = system
            .elements
            .iter()
            .map(|e| match (e.from_dof, e.to_dof) {
                (Some(a), Some(b)) if a != b => Some(if parent[a] == Some(b) { a } else { b }),
                _ => None,
            })
            .collect();
        Some(Self {
            order: preorder,
            parent,
            element_child,
            diag: vec![Complex64::default(); n],
            off: vec![Complex64::default(); n],
            original: vec![Complex64::default(); n],
        })
    }

    /// Solves `(K(f)(1 + iξ) − ω²M + iωC) x = rhs` in place, with each element's complex
    /// stiffness `z_e = k(1 + iξ) + iωc` given in element order. Returns false when a
    /// pivot is too small (then `rhs` is garbage and the caller solves densely).
    pub(crate) fn solve(
        &mut self,
        system: &System,
        omega_rad_s: f64,
        element_z: &[Complex64],
        rhs: &mut [Complex64],
    ) -> bool {
        let w2 = omega_rad_s * omega_rad_s;
        for (i, d) in self.diag.iter_mut().enumerate() {
            *d = Complex64::new(
                -w2 * system.inertia_kg_m2[i],
                omega_rad_s * system.absolute_damping_nm_s_per_rad[i],
            );
        }
        self.off.fill(Complex64::default());
        for ((e, &z), &child) in system
            .elements
            .iter()
            .zip(element_z)
            .zip(&self.element_child)
        {
            if let Some(a) = e.from_dof {
                self.diag[a] += z;
            }
            if let Some(b) = e.to_dof {
                self.diag[b] += z;
            }
            if let Some(c) = child {
                self.off[c] -= z;
            }
        }
        self.original.copy_from_slice(&self.diag);
        // `diag[i]` is replaced by its inverse once eliminated: one complex division per
        // DOF, multiplications elsewhere.
        let floor_sqr = PIVOT_FLOOR * PIVOT_FLOOR;
        for &i in &self.order {
            let d = self.diag[i];
            if d.norm_sqr() <= floor_sqr * self.original[i].norm_sqr() {
                return false;
            }
            let inverse = d.inv();
            self.diag[i] = inverse;
            if let Some(p) = self.parent[i] {
                let scaled = self.off[i] * inverse;
                self.diag[p] -= scaled * self.off[i];
                rhs[p] -= scaled * rhs[i];
            }
        }
        for &i in self.order.iter().rev() {
            let coupled = self.parent[i].map_or(Complex64::default(), |p| self.off[i] * rhs[p]);
            rhs[i] = (rhs[i] - coupled) * self.diag[i];
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{parse_model, presets};
    use crate::physics::{OperatingPoint, matrices};
    use crate::response::lu::LuWorkspace;
    use nalgebra::DMatrix;

    fn system(text: &str) -> System {
        let model = parse_model(text, "test.toml").expect("model");
        System::new(&model, OperatingPoint::default()).expect("system")
    }

    fn element_z(system: &System, omega: f64) -> Vec<Complex64> {
        system
            .elements
            .iter()
            .map(|e| {
                let (k, loss) = e.stiffness_at(omega / std::f64::consts::TAU);
                Complex64::new(k, k * loss + omega * e.viscous_damping())
            })
            .collect()
    }

    /// Tree solve and the pivoting dense LU at `omega`, on a right-hand side that loads
    /// every DOF differently.
    fn both(
        system: &System,
        tree: &mut TreeSolver,
        omega: f64,
    ) -> Option<(Vec<Complex64>, Vec<Complex64>)> {
        let n = system.dof_count();
        let rhs: Vec<Complex64> = (0..n)
            .map(|i| Complex64::new(1.0 + i as f64, 0.5 - 0.1 * i as f64))
            .collect();
        let mut by_tree = rhs.clone();
        if !tree.solve(system, omega, &element_z(system, omega), &mut by_tree) {
            return None;
        }
        let mut dense = DMatrix::<Complex64>::zeros(n, n);
        matrices::dynamic_stiffness(system, omega, &mut dense);
        let mut by_lu = rhs;
        assert!(LuWorkspace::default().factor_solve(&mut dense, &mut by_lu));
        Some((by_tree, by_lu))
    }

    /// On every shipped preset, over 0.5–400 Hz through all their resonances, the tree
    /// solve equals the pivoting LU to 1e-9 of the largest response: both are backward
    /// stable here (pivots stay above 1e-6 of their diagonal), and the difference is
    /// rounding amplified at most by the resonance's 1/ζ.
    #[test]
    fn equals_the_dense_lu_on_every_preset() {
        for preset in presets::PRESETS {
            let model = parse_model(preset.text, preset.name).expect("preset");
            let system = System::new(&model, OperatingPoint::default()).expect("system");
            let mut tree = TreeSolver::new(&system).expect("presets are trees");
            let mut solved = 0;
            for step in 1..=800 {
                let omega = std::f64::consts::TAU * 0.5 * step as f64;
                if let Some((a, b)) = both(&system, &mut tree, omega) {
                    let scale = b.iter().map(|v| v.norm()).fold(0.0, f64::max);
                    for (x, y) in a.iter().zip(&b) {
                        assert!(
                            (x - y).norm() <= 1e-9 * scale,
                            "{}: {x} vs {y} at {omega} rad/s",
                            preset.name
                        );
                    }
                    solved += 1;
                }
            }
            assert!(
                solved >= 790,
                "{}: only {solved} of 800 by the tree",
                preset.name
            );
        }
    }

    /// A gear that branches (one pinion driving two shafts through meshes) is still a tree.
    /// The tolerance is the condition number's: at 1 Hz this free system's dynamic
    /// stiffness spans ~1e7 (mesh stiffness referred by ratio² against ω²J), so two
    /// backward-stable solves may differ by ~1e7 × 1e-16.
    #[test]
    fn a_branched_geared_driveline_is_a_tree_and_solves_exactly() {
        let text = r#"
format = 1
name = "branched"
[[inertia]]
name = "engine"
inertia = 1.0
[[inertia]]
name = "pinion"
inertia = 0.05
[[inertia]]
name = "wheel_a"
inertia = 0.2
[[inertia]]
name = "wheel_b"
inertia = 0.3
[[inertia]]
name = "pump"
inertia = 0.4
[[connection]]
kind = "shaft"
name = "input"
from = "engine"
to = "pinion"
stiffness = 5.0e4
damping = 3.0
[[connection]]
kind = "gear"
name = "mesh_a"
from = "pinion"
to = "wheel_a"
ratio = 2.0
mesh_stiffness = 1.0e6
[[connection]]
kind = "gear"
name = "mesh_b"
from = "pinion"
to = "wheel_b"
ratio = 3.0
mesh_stiffness = 2.0e6
[[connection]]
kind = "rubber"
name = "coupling"
from = "wheel_b"
to = "pump"
stiffness = 2.0e4
psi = 0.8
"#;
        let system = system(text);
        let mut tree = TreeSolver::new(&system).expect("a tree");
        for hz in [1.0, 7.3, 25.0, 81.0, 260.0] {
            let (a, b) = both(&system, &mut tree, std::f64::consts::TAU * hz).expect("solved");
            let scale = b.iter().map(|v| v.norm()).fold(0.0, f64::max);
            for (x, y) in a.iter().zip(&b) {
                assert!((x - y).norm() <= 1e-9 * scale, "{x} vs {y} at {hz} Hz");
            }
        }
    }

    /// Three inertias in a ring close a loop: no tree solver.
    #[test]
    fn a_ring_is_not_a_tree() {
        let mut text = String::from("format = 1\nname = \"ring\"\n");
        for n in ["a", "b", "c"] {
            text += &format!("[[inertia]]\nname = \"{n}\"\ninertia = 1.0\n");
        }
        for (from, to) in [("a", "b"), ("b", "c"), ("c", "a")] {
            text += &format!(
                "[[connection]]\nkind = \"shaft\"\nfrom = \"{from}\"\nto = \"{to}\"\nstiffness = 1.0e4\n"
            );
        }
        assert!(TreeSolver::new(&system(&text)).is_none());
    }

    /// An undamped leaf (J on k) at its blocked-end resonance ω² = k/J gives a zero pivot:
    /// the tree solve declines and the caller's dense LU takes over.
    #[test]
    fn a_leaf_at_its_blocked_resonance_falls_back() {
        let text = r#"
format = 1
name = "leaf"
[[inertia]]
name = "hub"
inertia = 1.0
damping = 5.0
[[inertia]]
name = "leaf"
inertia = 0.25
[[connection]]
kind = "shaft"
from = "hub"
to = "leaf"
stiffness = 1.0e4
[[connection]]
kind = "shaft"
from = "hub"
to = "ground"
stiffness = 3.0e4
"#;
        let system = system(text);
        let mut tree = TreeSolver::new(&system).expect("a tree");
        let leaf = system.dof_of_node[1];
        let root_is_hub = tree.parent[leaf] == Some(system.dof_of_node[0]);
        assert!(root_is_hub, "the leaf is eliminated first");
        let omega = (1.0e4_f64 / 0.25).sqrt();
        let mut rhs = vec![Complex64::new(1.0, 0.0); 2];
        assert!(!tree.solve(&system, omega, &element_z(&system, omega), &mut rhs));
        assert!(both(&system, &mut tree, omega * 1.01).is_some());
    }
}
