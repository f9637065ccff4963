//! `gear_backlash`: free play in a gear mesh ([`crate::model::Gear::backlash_deg`]), its
//! tooth contact softened or hard, and, where the user's mesh has no damping, the mesh
//! damping that a real gear pair always has.
//!
//! Why the damping belongs to the effect: a mesh with play rattles, and what the
//! recordings show of it (the impacts' orders and how fast they die) depends on the
//! mesh's damping as much as on the play. A user's model rarely gives mesh damping
//! (`spec/model-format.md` has no key for it; torsim's `mesh_damping` is an extension),
//! and without backlash it hardly matters: the mesh mode sits far above the excited band.
//! Measured on development case 2087 (held-out χ²/N of the whole model): the user's
//! model 447; with the true play and softening but no mesh damping 1840, worse than
//! without the play; with both and the mesh damped at ζ = 0.13 (the bench's own), 2.86.
//! Damping alone, without play, 449. So the play is judged with a damped mesh.

use super::EffectError;
use super::effect::{EffectSpec, Params};
use super::truth::Applied;
use crate::model::{ConnectionKind, Model};

/// The mesh mode's damping ratio the diagnosis' backlash candidates give a mesh the user
/// left undamped, as their fixed `mesh_damping_ratio`
/// ([`crate::diagnose::candidates_backlash`]). Gear-pair models assume a few to about
/// 15 %; 0.1 is the middle.
pub const DEFAULT_MESH_DAMPING_RATIO: f64 = 0.1;

/// `gear_backlash`: gear `connection` (default the first with a mesh stiffness) has
/// `backlash_deg` of total free play at its `to` side (default 0.2°), its tooth contact
/// softened over `softening` times the half play (default 0: a hard contact;
/// [`crate::model::Gear::backlash_softening_deg`]). With `mesh_damping_ratio` ζ (default
/// none: the mesh keeps its damping) and a mesh without damping, the mesh gets the viscous
/// damping c = 2ζ√(k·J) of its own mode, k the mesh stiffness and J the two meshing
/// nodes' inertias in series at the `to` side ([`mesh_mode_inertia_kg_m2`]).
pub(crate) fn backlash(model: &mut Model, spec: &EffectSpec) -> Result<Applied, EffectError> {
    let mut p = Params::new(
        spec,
        &[
            "connection",
            "backlash_deg",
            "softening",
            "mesh_damping_ratio",
            "contact_exponent",
            "contact_reference_deg",
        ],
    )?;
    let first = model
        .connections
        .iter()
        .find(
            |c| matches!(&c.kind, ConnectionKind::Gear(g) if g.mesh_stiffness_nm_per_rad.is_some()),
        )
        .map(|c| c.name.clone());
    let name = p.text("connection", first)?;
    // 0 closes the play: what is left is the mesh damping, if any
    // ([`crate::diagnose::own_gain`] compares the two).
    let deg = p.number("backlash_deg", 0.2, 0.0, 10.0)?;
    let softening = p.optional_number("softening", 0.0, 10.0)?.unwrap_or(0.0);
    let ratio = p.optional_number("mesh_damping_ratio", 0.0, 2.0)?;
    // Optional, so a linear contact resolves to the parameters it always had.
    let exponent = p
        .optional_number("contact_exponent", 1.0, 3.0)?
        .unwrap_or(1.0);
    // A reference is the deflection a power law is referred to: a linear contact has none,
    // and one given to it would be silently ignored.
    if exponent == 1.0 && spec.params.contains_key("contact_reference_deg") {
        return Err(p.bad(
            "contact_reference_deg",
            "a linear contact has no reference deflection: give contact_exponent > 1 with it",
        ));
    }
    // Without play the effect is absent: the contact stays linear too.
    let reference_deg = if exponent == 1.0 || deg == 0.0 {
        None
    } else {
        // The mesh stiffness is quoted at the working load, and a contact that works
        // inside the play is referred to the play itself.
        let working = working_deflection_deg(model, &name).unwrap_or(0.0);
        let default = working.max(0.5 * deg).max(1e-6);
        Some(p.number("contact_reference_deg", default, 1e-9, 10.0)?)
    };
    let inertia = mesh_mode_inertia_kg_m2(model, &name);
    let Some(c) = model.connections.iter_mut().find(|c| c.name == name) else {
        return Err(p.bad("connection", format!("no connection `{name}`")));
    };
    let ConnectionKind::Gear(g) = &mut c.kind else {
        return Err(p.bad("connection", format!("`{name}` is no gear")));
    };
    let Some(k) = g.mesh_stiffness_nm_per_rad else {
        return Err(p.bad(
            "connection",
            format!("gear `{name}` is rigid: backlash needs a mesh_stiffness"),
        ));
    };
    if g.backlash_deg != 0.0 {
        return Err(p.bad("connection", format!("gear `{name}` already has backlash")));
    }
    g.backlash_deg = deg;
    g.backlash_softening_deg = 0.5 * softening * deg;
    let mut contact = if softening > 0.0 {
        format!(", its contact softened over {softening} of the half play")
    } else {
        String::new()
    };
    if let Some(r) = reference_deg {
        g.contact_exponent = exponent;
        g.contact_reference_deg = r;
        contact += &format!(
            ", its contact law a power {exponent} as stiff as the mesh at {r:.4e}° of \
             deflection"
        );
    }
    let damped = match (ratio, inertia) {
        (Some(z), Some(j)) if z > 0.0 && g.mesh_damping_nm_s_per_rad == 0.0 => {
            let c = 2.0 * z * (k * j).sqrt();
            g.mesh_damping_nm_s_per_rad = c;
            format!(", its mesh damped at ζ = {z} ({c:.4} N·m·s/rad)")
        }
        _ => String::new(),
    };
    let summary =
        format!("gear `{name}` has {deg}° of free play at its output side{contact}{damped}");
    Ok((p.resolved, summary))
}

/// The deflection of gear `name`'s mesh under its mean torque at full load, degrees at its
/// `to` side (the torque over the mesh stiffness); `None` when the model has no static
/// state there or `name` is no elastic gear.
pub fn working_deflection_deg(model: &Model, name: &str) -> Option<f64> {
    let j = model.connections.iter().position(|c| c.name == name)?;
    let system =
        crate::physics::System::nominal(model, crate::physics::OperatingPoint::default()).ok()?;
    let e = system.elements.iter().find(|e| e.connection == j)?;
    let torque = system.mean_torque_nm.get(j).copied().flatten()?;
    let (k_ref, _) = e.stiffness_at(0.0);
    let own = k_ref / (e.torque_ratio * e.torque_ratio);
    Some((torque / own).abs().to_degrees())
}

/// The inertia of gear `name`'s own mode, kg·m² at its `to` side: its two nodes in series,
/// J_to·J_from/ρ² / (J_to + J_from/ρ²), ρ the ratio (a node on ground counts as
/// infinitely heavy). `None` when `name` is no gear or both ends are ground.
pub fn mesh_mode_inertia_kg_m2(model: &Model, name: &str) -> Option<f64> {
    let c = model.connections.iter().find(|c| c.name == name)?;
    let ConnectionKind::Gear(g) = &c.kind else {
        return None;
    };
    let of = |node: &str| {
        model
            .node_index(node)
            .map(|i| model.inertias[i].inertia_kg_m2)
    };
    match (of(&c.from).map(|j| j / (g.ratio * g.ratio)), of(&c.to)) {
        (Some(a), Some(b)) => Some(a * b / (a + b)),
        (Some(j), None) | (None, Some(j)) => Some(j),
        (None, None) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::{Effect, build_truth};
    use crate::model::{parse_model, presets};

    fn bench() -> Model {
        let text = presets::preset("diagnosis-bench").expect("shipped").text;
        parse_model(text, "diagnosis-bench.toml").expect("valid")
    }

    fn gear(m: &Model) -> &crate::model::Gear {
        m.connections
            .iter()
            .find_map(|c| match &c.kind {
                ConnectionKind::Gear(g) => Some(g),
                _ => None,
            })
            .expect("the bench has a gear")
    }

    /// ζ gives c = 2ζ√(kJ): the mesh mode of the two nodes alone (a two-mass oscillator
    /// with stiffness k and series inertia J) then has exactly the damping ratio ζ.
    #[test]
    fn the_mesh_damping_ratio_is_that_of_the_mesh_mode() {
        let user = bench();
        let spec = EffectSpec::new(Effect::GearBacklash)
            .with("backlash_deg", 0.1)
            .with("mesh_damping_ratio", 0.1);
        let truth = build_truth(&user, &spec, 0.0, 0).expect("applies");
        let name = user
            .connections
            .iter()
            .find(|c| matches!(c.kind, ConnectionKind::Gear(_)))
            .map(|c| c.name.clone())
            .expect("a gear");
        let (g, j) = (gear(&truth.model), mesh_mode_inertia_kg_m2(&user, &name));
        let (k, j) = (
            g.mesh_stiffness_nm_per_rad.expect("meshing"),
            j.expect("both ends"),
        );
        let zeta = g.mesh_damping_nm_s_per_rad / (2.0 * (k * j).sqrt());
        assert!((zeta - 0.1).abs() < 1e-12, "ζ = {zeta}");
        assert!(
            truth.effect.summary.contains("ζ = 0.1"),
            "{}",
            truth.effect.summary
        );
    }

    /// A mesh the user damped keeps its damping; without the key nothing is added.
    #[test]
    fn a_damped_mesh_or_no_ratio_keeps_the_users_damping() {
        let mut user = bench();
        let plain = EffectSpec::new(Effect::GearBacklash).with("backlash_deg", 0.1);
        let truth = build_truth(&user, &plain, 0.0, 0).expect("applies");
        assert_eq!(gear(&truth.model).mesh_damping_nm_s_per_rad, 0.0);
        for c in &mut user.connections {
            if let ConnectionKind::Gear(g) = &mut c.kind {
                g.mesh_damping_nm_s_per_rad = 3.0;
            }
        }
        let damped = plain.with("mesh_damping_ratio", 0.1);
        let truth = build_truth(&user, &damped, 0.0, 0).expect("applies");
        assert_eq!(gear(&truth.model).mesh_damping_nm_s_per_rad, 3.0);
    }

    /// A Hertzian contact: as stiff as the mesh at the full-load deflection T/k (here
    /// below the half play, which it takes instead), or at the reference given; its
    /// absence (no play) leaves the contact linear too; an exponent outside 1–3, or a reference
    /// without a power law, is refused.
    #[test]
    fn a_hertzian_contact_is_referred_to_the_working_load_or_the_play() {
        let user = bench();
        let working = working_deflection_deg(&user, "gearbox").expect("a static state");
        // T/k by hand: the bench's mean torque at full load over the mesh stiffness.
        let system = crate::physics::System::nominal(&user, Default::default()).expect("valid");
        let j = user
            .connections
            .iter()
            .position(|c| c.name == "gearbox")
            .expect("a gear");
        let torque = system.mean_torque_nm[j].expect("a mean torque");
        let k = gear(&user).mesh_stiffness_nm_per_rad.expect("elastic");
        let e = system
            .elements
            .iter()
            .find(|e| e.connection == j)
            .expect("an element");
        let own = e.stiffness_at(0.0).0 / (e.torque_ratio * e.torque_ratio);
        assert!(
            (own - k).abs() < 1e-9 * k,
            "the element's own stiffness is the mesh's"
        );
        assert!((working - (torque / k).abs().to_degrees()).abs() < 1e-15);
        let hertz = EffectSpec::new(Effect::GearBacklash)
            .with("backlash_deg", 0.2)
            .with("contact_exponent", 1.5);
        let g = gear(&build_truth(&user, &hertz, 0.0, 0).expect("applies").model).clone();
        assert_eq!(g.contact_exponent, 1.5);
        assert_eq!(g.contact_reference_deg, working.max(0.1));
        let given = hertz.clone().with("contact_reference_deg", 0.05);
        let g = gear(&build_truth(&user, &given, 0.0, 0).expect("applies").model).clone();
        assert_eq!(g.contact_reference_deg, 0.05);
        let absent = hertz.clone().with("backlash_deg", 0.0);
        let g = gear(&build_truth(&user, &absent, 0.0, 0).expect("applies").model).clone();
        assert_eq!((g.contact_exponent, g.contact_reference_deg), (1.0, 0.0));
        let steep = hertz.with("contact_exponent", 3.5);
        assert!(build_truth(&user, &steep, 0.0, 0).is_err());
        // A reference without a power law is refused by its key, not ignored.
        let linear = EffectSpec::new(Effect::GearBacklash)
            .with("backlash_deg", 0.2)
            .with("contact_reference_deg", 0.05);
        let e = build_truth(&user, &linear, 0.0, 0).expect_err("a linear contact");
        assert!(e.to_string().contains("contact_reference_deg"), "{e}");
    }
}
