//! Magnitudes that make the system numerically singular (issue 13: a gear ratio of
//! 1e-300 or a stiffness of 1e-308 gave "singular system: the mean torque has no static
//! equilibrium…", which named neither the cause nor where it was).
//!
//! Every stiffness and inertia is referred to the reference shaft (× speed ratio²), as the
//! analyses use them. One that is below [`ROUND_OFF`] times the largest of its kind is
//! lost in the round-off of the sums it enters (an `f64` carries ~16 digits; 1e-12 keeps
//! four of them for the small one), so the matrices would be singular or meaningless. Such
//! a value is refused at its key, naming the largest it is compared with.

use super::validate::{Check, fail};
use super::{ConnectionKind, GROUND, Model, RubberStiffness};

/// Smallest ratio of a referred stiffness (or inertia) to the largest of its kind.
pub const ROUND_OFF: f64 = 1e-12;

/// A gear ratio's magnitude must lie in `[1/GEAR_RATIO_MAX, GEAR_RATIO_MAX]`: beyond
/// 1:10 000 in one stage (worm and multi-stage planetary gearboxes reach ~1:1000) it
/// scales referred stiffnesses by more than 10⁸ and is a typing error, not a gear.
pub const GEAR_RATIO_MAX: f64 = 1e4;

/// A gear ratio: finite, non-zero, of magnitude within [`GEAR_RATIO_MAX`].
pub(crate) fn gear_ratio(key: &str, ratio: f64) -> Check {
    let size = ratio.abs();
    if ratio.is_finite() && (1.0 / GEAR_RATIO_MAX..=GEAR_RATIO_MAX).contains(&size) {
        Ok(())
    } else {
        fail(
            key,
            format!(
                "must be finite and non-zero, with a magnitude from 1e-4 to 1e4 (one gear \
                 stage), found {ratio:e}"
            ),
        )
    }
}

/// One referred value: where it is (connection or node index, and the key under it) and
/// its value. Keys and names are built only for an error (models are validated in the
/// diagnosis' inner loops).
#[derive(Clone, Copy)]
struct Referred {
    index: usize,
    sub: &'static str,
    value: f64,
}

/// Refuses a stiffness or inertia that is lost in the others' round-off (module docs).
/// `ratios` are the model's speed ratios ([`super::graph::speed_ratios`]).
pub(crate) fn magnitudes(model: &Model, ratios: &[f64]) -> Check {
    if ratios.len() != model.inertias.len() {
        return Ok(());
    }
    let r2 = |name: &str| {
        model
            .node_index(name)
            .map_or(1.0, |i| ratios[i] * ratios[i])
    };
    let mut stiffness = Vec::with_capacity(model.connections.len());
    for (j, c) in model.connections.iter().enumerate() {
        let own = if c.from == GROUND { &c.to } else { &c.from };
        let (sub, k, r2) = match &c.kind {
            ConnectionKind::Shaft(s) => ("stiffness", s.stiffness_nm_per_rad, r2(own)),
            ConnectionKind::Rubber(r) => {
                let sub = match r.stiffness {
                    RubberStiffness::Direct(_) => "stiffness",
                    RubberStiffness::Elements(_) => "elements",
                };
                (sub, r.static_stiffness_nm_per_rad(), r2(own))
            }
            ConnectionKind::Gear(g) => match g.mesh_stiffness_nm_per_rad {
                Some(k) => ("mesh_stiffness", k, r2(&c.to)),
                None => continue,
            },
        };
        stiffness.push(Referred {
            index: j,
            sub,
            value: k * r2,
        });
    }
    let connection = |r: Referred| {
        let c = &model.connections[r.index];
        (
            format!("connection[{}].{}", r.index, r.sub),
            format!("connection `{}`", c.name),
        )
    };
    above_round_off(&stiffness, "stiffness", "N·m/rad", connection)?;
    let inertia: Vec<Referred> = model
        .inertias
        .iter()
        .enumerate()
        .map(|(i, n)| Referred {
            index: i,
            sub: "inertia",
            value: n.inertia_kg_m2 * ratios[i] * ratios[i],
        })
        .collect();
    let node = |r: Referred| {
        let name = &model.inertias[r.index].name;
        (
            format!("inertia[{}].inertia", r.index),
            format!("node `{name}`"),
        )
    };
    above_round_off(&inertia, "inertia", "kg·m²", node)
}

/// Each value at least [`ROUND_OFF`] of the largest; `name` gives a value's key and what
/// it is, for the error.
fn above_round_off(
    values: &[Referred],
    kind: &str,
    unit: &str,
    name: impl Fn(Referred) -> (String, String),
) -> Check {
    let Some(&largest) = values.iter().max_by(|a, b| a.value.total_cmp(&b.value)) else {
        return Ok(());
    };
    match values
        .iter()
        .find(|v| v.value.is_nan() || v.value < ROUND_OFF * largest.value)
    {
        None => Ok(()),
        Some(&v) => {
            let ((key, what), (_, big)) = (name(v), name(largest));
            fail(
                key,
                format!(
                    "the {kind} of {what} ({:.4e} {unit} referred to the reference shaft) is \
                     below 1e-12 of the largest, {big}'s {:.4e} {unit}: it is lost in \
                     round-off and makes the system numerically singular",
                    v.value, largest.value
                ),
            )
        }
    }
}
