//! Semantic checks on an in-memory [`Model`]: value ranges, names, the graph, the engine,
//! the harmonics, the operation ranges and the expectations (`spec/model-format.md`).
//!
//! The GUI calls [`validate`] on edited models, so errors carry key paths only (as in the
//! model file, e.g. `connection[2].stiffness`); the reader adds file and line.

use std::collections::HashSet;

/// Most segments a distributed shaft may be divided into (`segments`). A lumped chain of n
/// segments is ≈ (β/n)²/24 low in frequency at `β = ω·√(J/k)`: 10⁻⁴ at β = 49 for 1000.
pub const MAX_SEGMENTS: u32 = 1000;

use super::error::ModelError;
use super::graph;
use super::names::check_name;
use super::validate_engine;
use super::validate_scale;
use super::{AmplitudeForm, ConnectionKind, GROUND, Model, Poly, RubberStage, RubberStiffness};

/// Result of one check.
pub(crate) type Check = Result<(), ModelError>;

/// An error at `key`.
pub(crate) fn fail(key: impl Into<String>, message: impl Into<String>) -> Check {
    Err(ModelError::at(key, message))
}

/// `x` must be finite and > 0.
pub(crate) fn positive(key: &str, x: f64) -> Check {
    if x.is_finite() && x > 0.0 {
        Ok(())
    } else {
        fail(key, format!("must be a positive finite number, found {x}"))
    }
}

/// `x` must be finite and ≥ 0.
pub(crate) fn non_negative(key: &str, x: f64) -> Check {
    if x.is_finite() && x >= 0.0 {
        Ok(())
    } else {
        fail(key, format!("must be a finite number ≥ 0, found {x}"))
    }
}

/// `x` must be finite.
pub(crate) fn finite(key: &str, x: f64) -> Check {
    if x.is_finite() {
        Ok(())
    } else {
        fail(key, format!("must be a finite number, found {x}"))
    }
}

/// Every value of the list at `key` finite; the first that is not is named `key[i]`.
/// (The key of an element is built only then: models are validated in the diagnosis'
/// inner loops, where formatting every element's key cost 5 % of the time.)
pub(crate) fn all_finite(key: &str, values: &[f64]) -> Check {
    match values.iter().position(|x| !x.is_finite()) {
        Some(i) => finite(&format!("{key}[{i}]"), values[i]),
        None => Ok(()),
    }
}

/// `[min, max]` with `0 ≤ min < max`, finite.
pub(crate) fn range(key: &str, [lo, hi]: [f64; 2]) -> Check {
    if lo.is_finite() && hi.is_finite() && 0.0 <= lo && lo < hi {
        Ok(())
    } else {
        fail(
            key,
            format!("must be [min, max] with 0 ≤ min < max, found [{lo}, {hi}]"),
        )
    }
}

/// Values strictly increasing.
pub(crate) fn increasing(key: &str, values: &[f64]) -> Check {
    match values.windows(2).position(|w| w[0] >= w[1]) {
        None => Ok(()),
        Some(i) => fail(
            format!("{key}[{}]", i + 1),
            format!(
                "values must be strictly increasing, but {} follows {}",
                values[i + 1],
                values[i]
            ),
        ),
    }
}

/// Checks a model for everything the file format requires (see the module docs).
pub fn validate(model: &Model) -> Result<(), ModelError> {
    if model.inertias.is_empty() {
        fail(
            "inertia",
            "the model has no `[[inertia]]` nodes; a driveline needs at least one",
        )?;
    }
    nodes(model)?;
    connections(model)?;
    for (i, node) in model.inertias.iter().enumerate() {
        let used = model
            .connections
            .iter()
            .any(|c| c.from == node.name || c.to == node.name);
        if !used && model.inertias.len() > 1 {
            fail(
                format!("inertia[{i}]"),
                format!("node `{}` is connected to nothing", node.name),
            )?;
        }
    }
    let ratios = graph::speed_ratios(model)?;
    validate_scale::magnitudes(model, &ratios)?;
    if let Some(engine) = &model.engine {
        validate_engine::engine(model, engine)?;
    }
    validate_engine::harmonics(model)?;
    if let Some(load) = &model.load {
        if let Some(at) = &load.at {
            known_node(model, "load.at", at)?;
        }
        non_negative("load.damping", load.damping_nm_s_per_rad)?;
    }
    if let Some(d) = &model.modal_damping {
        super::modal_damping::validate(d)?;
    }
    validate_engine::operation_and_expect(model)
}

/// `name` must be a node of the model.
pub(crate) fn known_node(model: &Model, key: &str, name: &str) -> Check {
    if model.node_index(name).is_some() {
        Ok(())
    } else {
        fail(key, format!("unknown node `{name}`"))
    }
}

fn nodes(model: &Model) -> Check {
    let mut seen = HashSet::new();
    for (i, node) in model.inertias.iter().enumerate() {
        let key = format!("inertia[{i}]");
        if node.name == GROUND {
            fail(format!("{key}.name"), "`ground` is reserved for the frame")?;
        }
        check_name(&format!("{key}.name"), "node", &node.name)?;
        if !seen.insert(node.name.as_str()) {
            fail(
                format!("{key}.name"),
                format!("duplicate node name `{}`", node.name),
            )?;
        }
        positive(&format!("{key}.inertia"), node.inertia_kg_m2)?;
        non_negative(&format!("{key}.damping"), node.damping_nm_s_per_rad)?;
    }
    Ok(())
}

fn connections(model: &Model) -> Check {
    let mut seen = HashSet::new();
    for (j, c) in model.connections.iter().enumerate() {
        let key = format!("connection[{j}]");
        let k = |sub: &str| format!("{key}.{sub}");
        if !seen.insert(c.name.as_str()) {
            fail(k("name"), format!("duplicate connection name `{}`", c.name))?;
        }
        for (end, name) in [("from", &c.from), ("to", &c.to)] {
            if name != GROUND {
                known_node(model, &k(end), name)?;
            }
        }
        check_name(&k("name"), "connection", &c.name)?;
        if c.from == GROUND && c.to == GROUND {
            fail(k("to"), "both ends are `ground`")?;
        }
        if c.from == c.to {
            fail(k("to"), format!("connects node `{}` to itself", c.from))?;
        }
        match &c.kind {
            ConnectionKind::Shaft(s) => {
                positive(&k("stiffness"), s.stiffness_nm_per_rad)?;
                non_negative(&k("damping"), s.damping_nm_s_per_rad)?;
                non_negative(&k("inertia"), s.inertia_kg_m2)?;
                if let Some(n) = s.segments
                    && !(1..=MAX_SEGMENTS).contains(&n)
                {
                    fail(
                        k("segments"),
                        format!("{n} segments: give 1 … {MAX_SEGMENTS}"),
                    )?;
                }
            }
            ConnectionKind::Rubber(r) => rubber(&key, r)?,
            ConnectionKind::Gear(g) => {
                let end = if c.from == GROUND { "from" } else { "to" };
                if c.from == GROUND || c.to == GROUND {
                    fail(k(end), "a gear cannot connect to `ground`")?;
                }
                validate_scale::gear_ratio(&k("ratio"), g.ratio)?;
                if let Some(mesh) = g.mesh_stiffness_nm_per_rad {
                    positive(&k("mesh_stiffness"), mesh)?;
                }
                non_negative(&k("mesh_damping"), g.mesh_damping_nm_s_per_rad)?;
                if g.mesh_damping_nm_s_per_rad > 0.0 && g.mesh_stiffness_nm_per_rad.is_none() {
                    fail(
                        k("mesh_damping"),
                        "needs `mesh_stiffness`: a rigid gear has no mesh twist to damp",
                    )?;
                }
                non_negative(&k("backlash_deg"), g.backlash_deg)?;
                non_negative(&k("backlash_softening_deg"), g.backlash_softening_deg)?;
                if !(1.0..=3.0).contains(&g.contact_exponent) {
                    fail(
                        k("contact_exponent"),
                        format!(
                            "is {}: a tooth contact's law has an exponent from 1 (linear) to 3 \
                             (1.5 is Hertz's)",
                            g.contact_exponent
                        ),
                    )?;
                }
                non_negative(&k("contact_reference_deg"), g.contact_reference_deg)?;
                if g.contact_exponent != 1.0 {
                    if g.mesh_stiffness_nm_per_rad.is_none() {
                        fail(
                            k("contact_exponent"),
                            "needs `mesh_stiffness`: a rigid gear has no tooth contact law",
                        )?;
                    }
                    if g.contact_reference_deg <= 0.0 {
                        fail(
                            k("contact_reference_deg"),
                            "must be > 0 with a `contact_exponent` other than 1: the \
                             deflection at which the contact is as stiff as `mesh_stiffness`",
                        )?;
                    }
                }
            }
        }
    }
    Ok(())
}

fn rubber(key: &str, r: &RubberStage) -> Check {
    let k = |sub: &str| format!("{key}.{sub}");
    match &r.stiffness {
        RubberStiffness::Direct(s) => positive(&k("stiffness"), *s)?,
        RubberStiffness::Elements(e) => {
            if e.count < 2 {
                fail(
                    k("elements.count"),
                    format!("must be at least 2, found {}", e.count),
                )?;
            }
            if e.per_side == 0 || e.per_side >= e.count {
                fail(
                    k("elements.per_side"),
                    format!(
                        "must satisfy 0 < per_side < count ({}), found {}",
                        e.count, e.per_side
                    ),
                )?;
            }
            positive(&k("elements.pitch_diameter"), e.pitch_diameter_m)?;
            positive(&k("elements.radial_stiffness"), e.radial_stiffness_n_per_m)?;
        }
    }
    positive(&k("psi"), r.psi)?;
    temperature(&k("temperature_c"), r.temperature_c)?;
    if r.amplitude_poly.is_some() && matches!(r.stiffness, RubberStiffness::Direct(_)) {
        fail(
            k("amplitude_poly"),
            "`amplitude_poly` needs `elements` (the deformation is measured at the elements)",
        )?;
    }
    if let Some(law) = &r.amplitude_saturation {
        if let Some((sub, why)) = law.problem() {
            fail(k(&format!("amplitude_saturation.{sub}")), why)?;
        }
        if matches!(r.stiffness, RubberStiffness::Direct(_)) {
            fail(
                k("amplitude_saturation"),
                "`amplitude_saturation` needs `elements` (the deformation is measured at the \
                 elements)",
            )?;
        }
        if r.amplitude_poly.is_some() {
            fail(
                k("amplitude_saturation"),
                "give either `amplitude_poly` or `amplitude_saturation`, not both",
            )?;
        }
    }
    if r.amplitude_form != AmplitudeForm::default() && !r.has_amplitude_law() {
        fail(
            k("amplitude_form"),
            "`amplitude_form` is given without `amplitude_poly` or `amplitude_saturation`",
        )?;
    }
    let polys = [
        ("amplitude_poly", &r.amplitude_poly),
        ("frequency_poly", &r.frequency_poly),
        ("temperature_stiffness_poly", &r.temperature_stiffness_poly),
        ("temperature_damping_poly", &r.temperature_damping_poly),
    ];
    for (name, poly) in polys {
        if let Some(p) = poly {
            poly_shape(&k(name), p)?;
        }
    }
    if let Some(law) = &r.frequency_power_law {
        if let Some(why) = law.problem() {
            fail(k("frequency_power_law"), why)?;
        }
        if r.frequency_poly.is_some() {
            fail(
                k("frequency_power_law"),
                "give either `frequency_poly` or `frequency_power_law`, not both",
            )?;
        }
    }
    if let Some(law) = &r.frequency_zener {
        if let Some(why) = law.problem() {
            fail(k("frequency_zener"), why)?;
        }
        if r.frequency_poly.is_some() || r.frequency_power_law.is_some() {
            fail(
                k("frequency_zener"),
                "give one of `frequency_poly`, `frequency_power_law` and `frequency_zener`",
            )?;
        }
    }
    if let Some((sub, why)) = r.rating.as_ref().and_then(|rt| rt.problem()) {
        fail(k(&format!("rating.{sub}")), why)?;
    }
    if let Some(t) = &r.thermal {
        positive(&k("thermal.capacity_j_per_k"), t.capacity_j_per_k)?;
        positive(&k("thermal.conductance_w_per_k"), t.conductance_w_per_k)?;
        temperature(&k("thermal.ambient_c"), t.ambient_c)?;
    }
    let temperatures = std::iter::once(("temperature_c", r.temperature_c)).chain(
        r.thermal
            .as_ref()
            .map(|t| ("thermal.ambient_c", t.ambient_c)),
    );
    for (where_, temp) in temperatures {
        for (name, poly) in &polys[2..] {
            let Some(p) = poly else { continue };
            let factor = p.eval(temp);
            if !(factor.is_finite() && factor > 0.0) {
                fail(
                    k(name),
                    format!("gives the factor {factor} (must be > 0) at {where_} = {temp} °C"),
                )?;
            }
        }
    }
    Ok(())
}

/// A rubber temperature within [`super::rubber::TEMPERATURE_RANGE_C`] (issue 13).
fn temperature(key: &str, temperature_c: f64) -> Check {
    match super::rubber::temperature_problem(temperature_c) {
        None => Ok(()),
        Some(problem) => fail(key, problem),
    }
}

fn poly_shape(key: &str, p: &Poly) -> Check {
    all_finite(key, &p.coeffs)?;
    if let Some([lo, hi]) = p.range
        && !(lo.is_finite() && hi.is_finite() && lo < hi)
    {
        fail(
            format!("{key}_range"),
            format!("must be [lo, hi] with lo < hi, found [{lo}, {hi}]"),
        )?;
    }
    Ok(())
}
