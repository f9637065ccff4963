//! The driveline as a graph: which node is the speed reference, and how fast each node
//! turns relative to it through the gear tree (`spec/model-format.md`, `kind = "gear"`).

use super::error::ModelError;
use super::types::{ConnectionKind, GROUND, Model};

/// Relative tolerance for two paths through the gear tree to agree on a node's speed.
const SPEED_RATIO_TOLERANCE: f64 = 1e-9;

/// The node whose speed defines engine orders: the engine's first node, else the first
/// harmonic's node, else the first node. `None` for a model without nodes.
pub fn reference_node(model: &Model) -> Option<usize> {
    let name = model
        .engine
        .as_ref()
        .and_then(|e| e.at.first())
        .or_else(|| model.harmonics.first().map(|h| &h.at));
    match name {
        Some(name) => model.node_index(name),
        None => (!model.inertias.is_empty()).then_some(0),
    }
}

/// Mean speed of every node divided by the reference node's, following the gear tree:
/// shafts and rubber stages keep the speed, a gear multiplies it by its `ratio` from
/// `from` to `to`.
///
/// Errors: a node that the connections do not reach from the reference (key
/// `inertia[i]`), or a loop of gears that gives a node two speeds (key
/// `connection[j].ratio`). Unknown node names must have been rejected before.
pub fn speed_ratios(model: &Model) -> Result<Vec<f64>, ModelError> {
    let n = model.inertias.len();
    let mut ratio: Vec<Option<f64>> = vec![None; n];
    let Some(reference) = reference_node(model) else {
        return Ok(Vec::new());
    };
    ratio[reference] = Some(1.0);
    let mut queue = vec![reference];
    while let Some(node) = queue.pop() {
        let here = ratio[node].unwrap_or(1.0);
        for (j, c) in model.connections.iter().enumerate() {
            if c.from == GROUND || c.to == GROUND {
                continue;
            }
            let (Some(from), Some(to)) = (model.node_index(&c.from), model.node_index(&c.to))
            else {
                continue;
            };
            let gear_ratio = match &c.kind {
                ConnectionKind::Gear(g) => g.ratio,
                _ => 1.0,
            };
            let (other, other_ratio) = if from == node {
                (to, here * gear_ratio)
            } else if to == node {
                (from, here / gear_ratio)
            } else {
                continue;
            };
            match ratio[other] {
                None => {
                    ratio[other] = Some(other_ratio);
                    queue.push(other);
                }
                Some(existing) => {
                    let scale = existing.abs().max(other_ratio.abs());
                    if (existing - other_ratio).abs() > SPEED_RATIO_TOLERANCE * scale {
                        return Err(ModelError::at(
                            format!("connection[{j}].ratio"),
                            format!(
                                "the gear tree gives node `{}` two speeds: {} and {} times \
                                 the speed of `{}`",
                                model.inertias[other].name,
                                existing,
                                other_ratio,
                                model.inertias[reference].name
                            ),
                        ));
                    }
                }
            }
        }
    }
    ratio
        .iter()
        .enumerate()
        .map(|(i, r)| {
            r.ok_or_else(|| {
                ModelError::at(
                    format!("inertia[{i}]"),
                    format!(
                        "node `{}` is not connected to the reference node `{}` (every node \
                         must turn with the driveline)",
                        model.inertias[i].name, model.inertias[reference].name
                    ),
                )
            })
        })
        .collect()
}
