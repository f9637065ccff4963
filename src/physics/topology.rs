//! Topology of the degrees of freedom: rigid gears merge nodes, free components are
//! rigid-body modes.

use super::element::Element;
use crate::model::{ConnectionKind, Model};

/// DOF index of every node: nodes joined by rigid gears share one (union-find).
pub(super) fn merge_rigid_gears(model: &Model) -> Vec<usize> {
    let n = model.inertias.len();
    let mut parent: Vec<usize> = (0..n).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for c in &model.connections {
        if let ConnectionKind::Gear(g) = &c.kind
            && g.mesh_stiffness_nm_per_rad.is_none()
            && let (Some(a), Some(b)) = (model.node_index(&c.from), model.node_index(&c.to))
        {
            let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
            parent[ra.max(rb)] = ra.min(rb);
        }
    }
    let mut dof_of_root = vec![usize::MAX; n];
    let mut next = 0;
    (0..n)
        .map(|i| {
            let r = root(&mut parent, i);
            if dof_of_root[r] == usize::MAX {
                dof_of_root[r] = next;
                next += 1;
            }
            dof_of_root[r]
        })
        .collect()
}

/// Number of connected components of the DOF graph that no element ties to ground: each
/// is one rigid-body mode.
pub(super) fn free_components(n_dof: usize, elements: &[Element]) -> usize {
    let mut parent: Vec<usize> = (0..=n_dof).collect(); // index n_dof is ground
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for e in elements {
        let a = e.from_dof.unwrap_or(n_dof);
        let b = e.to_dof.unwrap_or(n_dof);
        let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
        parent[ra.max(rb)] = ra.min(rb);
    }
    let ground = root(&mut parent, n_dof);
    let mut roots: Vec<usize> = (0..n_dof)
        .map(|i| root(&mut parent, i))
        .filter(|&r| r != ground)
        .collect();
    roots.sort_unstable();
    roots.dedup();
    roots.len()
}
