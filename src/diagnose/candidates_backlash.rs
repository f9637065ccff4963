//! The `gear_backlash` candidates of one gear: free play with a hard tooth contact, with
//! a softened one, and with a softened Hertzian one; each with the mesh damped where the
//! user's mesh has no damping ([`crate::effects::backlash`]).
//!
//! Why two contacts: a hard contact (the classical dead zone) and a contact softened over
//! a quarter of the half play (Hertzian flattening, profile errors) rattle differently,
//! and the one fitted parameter, the play, cannot make one look like the other. Measured
//! on the independent bench's development cases 2087–2164 (8 backlash cases, half with a
//! softened dead zone, half Hertzian; its softening is 0.1–0.3 of the half play):
//!
//! | candidates | named right | held-out χ²/N after, median |
//! |---|---|---|
//! | hard contact, undamped mesh (before) | 1/8 | 484 |
//! | hard contact, mesh ζ = 0.1 | 5/8 | 295 |
//! | softened contact, mesh ζ = 0.1 | 6/8 | 79.8 |
//! | both | 8/8 | 75.6 |
//!
//! The softening is a fixed form, not fitted: the bench's own range is known here, so a
//! quarter of the half play, inside it, is a choice to check on cases not drawn yet.
//!
//! Why a Hertzian contact too ([`crate::physics::tooth_contact`], exponent 1.5, as stiff
//! as the user's mesh at the deflection of the mean torque at full load, no less than the
//! half play): the mesh stiffness a user enters is the one at the working load; a point
//! contact is softer below it and stiffer beyond it, which changes how a mesh rattles.
//! Measured on the independent bench's development cases with a Hertzian truth, the
//! truth's own play and mesh damping put into the user's model, held-out χ²/N: 3022 0.46
//! with the Hertzian contact against 5.45 with the softened linear one (plain fit 2.53);
//! 3077 1.05 against 8.44 (plain 47.3). Where the mesh rattles through both flanks half
//! the time (101736) neither contact fits (327 against 246).

use super::candidates::Candidate;
use super::param::Param;
use crate::effects::Effect;
use crate::effects::backlash::DEFAULT_MESH_DAMPING_RATIO;
use crate::model::Gear;

/// The softened contact's width over the half play (the effect's `softening` key).
pub const SOFTENING: f64 = 0.25;

/// The fixed key a candidate damps an undamped mesh with.
pub const MESH_DAMPING_KEY: &str = "mesh_damping_ratio";

/// The mesh damping ratio `c` fixes, as written in its keys; `None` when it fixes none.
pub fn mesh_damping_ratio(c: &Candidate) -> Option<&str> {
    c.fixed_value(MESH_DAMPING_KEY)
}

/// The softened candidate's form, as the report names it.
pub const SOFTENED_FORM: &str = "softened";

/// The Hertzian candidate's form, as the report names it.
pub const HERTZIAN_FORM: &str = "hertzian";

/// The Hertzian candidate's contact exponent (Hertz's point contact).
pub const HERTZ_EXPONENT: f64 = 1.5;

/// The backlash candidates of gear `name` (none for a rigid gear): a softened contact, a
/// hard one and a softened Hertzian one, each fitting `backlash_deg` from 0.05°, the mesh
/// damped at
/// [`DEFAULT_MESH_DAMPING_RATIO`] when `gear` has no mesh damping.
pub fn backlash_candidates(name: &str, gear: &Gear) -> Vec<Candidate> {
    if gear.mesh_stiffness_nm_per_rad.is_none() {
        return Vec::new();
    }
    let mut hard = vec![("connection", name.to_string())];
    if gear.mesh_damping_nm_s_per_rad == 0.0 {
        hard.push((MESH_DAMPING_KEY, DEFAULT_MESH_DAMPING_RATIO.to_string()));
    }
    let mut soft = hard.clone();
    soft.push(("softening", SOFTENING.to_string()));
    let mut hertz = soft.clone();
    hertz.push(("contact_exponent", HERTZ_EXPONENT.to_string()));
    [soft, hard, hertz]
        .into_iter()
        .map(|fixed| Candidate {
            effect: Effect::GearBacklash,
            fixed,
            param: Param::new("backlash_deg", 0.05, 0.002, 2.0, true).absent_at(0.0),
            artifact_gains: None,
        })
        .collect()
}

/// `Some("hertzian")` or `Some("softened")` for those backlash candidates; `None` for
/// every other.
pub fn contact_form(candidate: &Candidate) -> Option<&'static str> {
    if candidate.effect != Effect::GearBacklash {
        return None;
    }
    let has = |key: &str| candidate.fixed.iter().any(|(k, _)| *k == key);
    if has("contact_exponent") {
        Some(HERTZIAN_FORM)
    } else if has("softening") {
        Some(SOFTENED_FORM)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::candidates::candidates;
    use crate::effects::backlash::mesh_mode_inertia_kg_m2;
    use crate::model::{ConnectionKind, Model, parse_model, presets};

    fn bench() -> Model {
        let text = presets::preset("diagnosis-bench").expect("shipped").text;
        parse_model(text, "diagnosis-bench.toml").expect("valid")
    }

    fn gear_of(m: &Model) -> &Gear {
        m.connections
            .iter()
            .find_map(|c| match &c.kind {
                ConnectionKind::Gear(g) => Some(g),
                _ => None,
            })
            .expect("a gear")
    }

    /// The bench's gear has all three contacts, told apart by name; each applied model
    /// has the fitted play, its contact, and the mesh damped at ζ = 0.1 of its own mode.
    #[test]
    fn a_gear_has_a_softened_a_hard_and_a_hertzian_candidate_with_a_damped_mesh() {
        let user = bench();
        let all = candidates(&user, &[], false);
        let mine: Vec<&Candidate> = all
            .iter()
            .filter(|c| c.effect == Effect::GearBacklash)
            .collect();
        let names: Vec<String> = mine.iter().map(|c| c.name()).collect();
        assert_eq!(
            names,
            [
                "gear_backlash at gearbox (softened)",
                "gear_backlash at gearbox",
                "gear_backlash at gearbox (hertzian)"
            ]
        );
        let j = mesh_mode_inertia_kg_m2(&user, "gearbox").expect("two nodes");
        // The Hertzian contact is as stiff as the mesh at the full-load deflection
        // T/k, here below the half play 0.1°, which it takes instead.
        let working = crate::effects::backlash::working_deflection_deg(&user, "gearbox")
            .expect("a static state");
        assert!(working > 0.0 && working < 0.1, "{working}");
        for (c, softening, exponent) in mine
            .iter()
            .zip([(SOFTENING, 1.0), (0.0, 1.0), (SOFTENING, HERTZ_EXPONENT)])
            .map(|(c, (s, n))| (c, s, n))
        {
            let (model, _) = c.apply(&user, 0.2).expect("applies");
            let g = gear_of(&model);
            assert_eq!(g.backlash_deg, 0.2);
            assert!((g.backlash_softening_deg - softening * 0.1).abs() < 1e-15);
            assert_eq!(g.contact_exponent, exponent);
            let reference = if exponent == 1.0 { 0.0 } else { 0.1 };
            assert_eq!(g.contact_reference_deg, reference);
            let k = g.mesh_stiffness_nm_per_rad.expect("meshing");
            let zeta = g.mesh_damping_nm_s_per_rad / (2.0 * (k * j).sqrt());
            assert!(
                (zeta - DEFAULT_MESH_DAMPING_RATIO).abs() < 1e-12,
                "ζ {zeta}"
            );
        }
    }

    /// A mesh the user damped is left as it is, and a rigid gear has no candidate.
    #[test]
    fn a_damped_mesh_keeps_its_damping_and_a_rigid_gear_has_none() {
        let mut user = bench();
        for c in &mut user.connections {
            if let ConnectionKind::Gear(g) = &mut c.kind {
                g.mesh_damping_nm_s_per_rad = 3.0;
            }
        }
        let mine = backlash_candidates("gearbox", gear_of(&user));
        assert_eq!(mine.len(), 3);
        for c in &mine {
            assert!(c.fixed.iter().all(|(k, _)| *k != "mesh_damping_ratio"));
            let (model, _) = c.apply(&user, 0.2).expect("applies");
            assert_eq!(gear_of(&model).mesh_damping_nm_s_per_rad, 3.0);
        }
        let mut rigid = gear_of(&user).clone();
        rigid.mesh_stiffness_nm_per_rad = None;
        assert!(backlash_candidates("gearbox", &rigid).is_empty());
    }
}
