//! Writing model files (`spec/model-format.md`, format 1): deterministic, readable TOML in
//! the spec's layout that [`parse_model`](super::read::parse_model) reads back to the same
//! [`Model`]. Keys equal to their defaults are left out; floats are written in Rust's
//! shortest round-trip form, so they parse back bit-identical.

use std::path::Path;

use super::{
    AmplitudeForm, Connection, ConnectionKind, Engine, Expect, Harmonic, HarmonicAmplitude, Model,
    Operation, Poly, Pressure, PressureCurve, RubberStage, RubberStiffness,
};

/// Arrays longer than this (written on one line) are wrapped.
const MAX_LINE: usize = 96;

/// The model as model-file text.
pub fn to_toml_string(model: &Model) -> String {
    let mut out = String::from("format = 1\n");
    kv(&mut out, "name", string(&model.name));
    if !model.description.is_empty() {
        kv(&mut out, "description", string(&model.description));
    }
    for node in &model.inertias {
        out.push_str("\n[[inertia]]\n");
        kv(&mut out, "name", string(&node.name));
        kv(&mut out, "inertia", num(node.inertia_kg_m2));
        opt_kv(&mut out, "damping", node.damping_nm_s_per_rad, 0.0);
    }
    for c in &model.connections {
        connection(&mut out, c);
    }
    if let Some(e) = &model.engine {
        engine(&mut out, e);
    }
    for h in &model.harmonics {
        harmonic(&mut out, h);
    }
    if let Some(load) = &model.load {
        out.push_str("\n[load]\n");
        if let Some(at) = &load.at {
            kv(&mut out, "at", string(at));
        }
        opt_kv(&mut out, "damping", load.damping_nm_s_per_rad, 0.0);
    }
    if let Some(d) = &model.modal_damping {
        super::modal_damping::write(&mut out, d, num);
    }
    operation(&mut out, &model.operation);
    expect(&mut out, &model.expect);
    out
}

/// Writes the model file atomically: a temporary file in the same directory, renamed
/// over `path` once it is complete.
pub fn save_model_file(model: &Model, path: &Path) -> std::io::Result<()> {
    crate::files::write_atomic(path, to_toml_string(model))
}

/// `key = value` on its own line.
fn kv(out: &mut String, key: &str, value: String) {
    out.push_str(key);
    out.push_str(" = ");
    out.push_str(&value);
    out.push('\n');
}

/// `key = x` unless `x` is (bit for bit) the default.
fn opt_kv(out: &mut String, key: &str, x: f64, default: f64) {
    if x.to_bits() != default.to_bits() {
        kv(out, key, num(x));
    }
}

/// A float that parses back bit-identical: shortest round-trip form, always with a `.0`
/// or an exponent so that TOML reads it as a float.
fn num(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.into()
    } else {
        format!("{x:?}")
    }
}

/// A TOML string, escaped by toml_edit.
fn string(s: &str) -> String {
    toml_edit::Value::from(s).to_string()
}

/// `[a, b, c]` starting at column `col`, wrapped over several lines (indented from
/// `indent`) when it would make the line long.
fn array(items: &[String], indent: usize, col: usize) -> String {
    let one_line = format!("[{}]", items.join(", "));
    if one_line.len() + col <= MAX_LINE {
        return one_line;
    }
    let pad = " ".repeat(indent + 4);
    let mut out = String::from("[\n");
    let mut line = String::new();
    for item in items {
        if !line.is_empty() && pad.len() + line.len() + item.len() + 2 > MAX_LINE {
            out.push_str(&format!("{pad}{}\n", line.trim_end()));
            line.clear();
        }
        line.push_str(item);
        line.push_str(", ");
    }
    out.push_str(&format!(
        "{pad}{}\n{}]",
        line.trim_end(),
        " ".repeat(indent)
    ));
    out
}

fn nums(xs: &[f64], indent: usize, col: usize) -> String {
    array(&xs.iter().map(|&x| num(x)).collect::<Vec<_>>(), indent, col)
}

/// `{ k = v, k = v }`.
fn inline(fields: &[(&str, String)]) -> String {
    let body: Vec<String> = fields.iter().map(|(k, v)| format!("{k} = {v}")).collect();
    format!("{{ {} }}", body.join(", "))
}

fn connection(out: &mut String, c: &Connection) {
    out.push_str("\n[[connection]]\n");
    kv(out, "kind", string(c.kind.kind_str()));
    if c.name != Connection::default_name(&c.from, &c.to) {
        kv(out, "name", string(&c.name));
    }
    kv(out, "from", string(&c.from));
    kv(out, "to", string(&c.to));
    match &c.kind {
        ConnectionKind::Shaft(s) => {
            kv(out, "stiffness", num(s.stiffness_nm_per_rad));
            opt_kv(out, "damping", s.damping_nm_s_per_rad, 0.0);
            opt_kv(out, "inertia", s.inertia_kg_m2, 0.0);
            if let Some(n) = s.segments {
                kv(out, "segments", n.to_string());
            }
        }
        ConnectionKind::Rubber(r) => rubber(out, r),
        ConnectionKind::Gear(g) => {
            kv(out, "ratio", num(g.ratio));
            if let Some(k) = g.mesh_stiffness_nm_per_rad {
                kv(out, "mesh_stiffness", num(k));
            }
            opt_kv(out, "mesh_damping", g.mesh_damping_nm_s_per_rad, 0.0);
            opt_kv(out, "backlash_deg", g.backlash_deg, 0.0);
            opt_kv(out, "backlash_softening_deg", g.backlash_softening_deg, 0.0);
            opt_kv(out, "contact_exponent", g.contact_exponent, 1.0);
            opt_kv(out, "contact_reference_deg", g.contact_reference_deg, 0.0);
        }
    }
}

fn rubber(out: &mut String, r: &RubberStage) {
    match &r.stiffness {
        RubberStiffness::Direct(k) => kv(out, "stiffness", num(*k)),
        RubberStiffness::Elements(e) => kv(
            out,
            "elements",
            inline(&[
                ("count", e.count.to_string()),
                ("per_side", e.per_side.to_string()),
                ("pitch_diameter", num(e.pitch_diameter_m)),
                ("radial_stiffness", num(e.radial_stiffness_n_per_m)),
            ]),
        ),
    }
    kv(out, "psi", num(r.psi));
    opt_kv(out, "temperature_c", r.temperature_c, 25.0);
    let polys = [
        ("amplitude_poly", &r.amplitude_poly),
        ("frequency_poly", &r.frequency_poly),
        ("temperature_stiffness_poly", &r.temperature_stiffness_poly),
        ("temperature_damping_poly", &r.temperature_damping_poly),
    ];
    for (key, poly) in polys {
        if let Some(Poly { coeffs, range }) = poly {
            kv(out, key, nums(coeffs, 0, 0));
            if let Some(range) = range {
                kv(out, &format!("{key}_range"), nums(range, 0, 0));
            }
        }
    }
    if let Some(law) = &r.frequency_power_law {
        let fields = [
            ("exponent", num(law.exponent)),
            ("reference_hz", num(law.reference_hz)),
        ];
        kv(out, "frequency_power_law", inline(&fields));
    }
    if let Some(law) = &r.frequency_zener {
        let fields = [
            ("delta", num(law.delta)),
            ("alpha", num(law.alpha)),
            ("relax_hz", num(law.relax_hz)),
            ("reference_hz", num(law.reference_hz)),
        ];
        kv(out, "frequency_zener", inline(&fields));
    }
    if let Some(law) = &r.amplitude_saturation {
        let fields = [
            ("stiffening", num(law.stiffening)),
            ("deformation_mm", num(law.deformation_mm)),
        ];
        kv(out, "amplitude_saturation", inline(&fields));
    }
    if r.amplitude_form != AmplitudeForm::default() {
        kv(out, "amplitude_form", string(r.amplitude_form.key()));
    }
    if let Some(t) = &r.thermal {
        let fields = [
            ("capacity_j_per_k", num(t.capacity_j_per_k)),
            ("conductance_w_per_k", num(t.conductance_w_per_k)),
            ("ambient_c", num(t.ambient_c)),
        ];
        kv(out, "thermal", inline(&fields));
    }
    if let Some(rating) = &r.rating {
        kv(out, "rating", inline(&super::rating::fields(rating, num)));
    }
}

fn engine(out: &mut String, e: &Engine) {
    out.push_str("\n[engine]\n");
    let at = match e.at.as_slice() {
        [one] => string(one),
        many => array(&many.iter().map(|s| string(s)).collect::<Vec<_>>(), 0, 5),
    };
    kv(out, "at", at);
    kv(out, "cylinders", e.cylinders.to_string());
    if e.strokes != 4 {
        kv(out, "strokes", e.strokes.to_string());
    }
    if let Some(angles) = &e.firing_angles_deg {
        kv(out, "firing_angles_deg", nums(angles, 0, 20));
    }
    kv(out, "bore", num(e.bore_m));
    kv(out, "crank_radius", num(e.crank_radius_m));
    kv(out, "conrod_length", num(e.conrod_length_m));
    opt_kv(out, "reciprocating_mass", e.reciprocating_mass_kg, 0.0);
    opt_kv(
        out,
        "rod_inertia_correction",
        e.rod_inertia_correction_kg,
        0.0,
    );
    if let Some(scale) = &e.pressure_scale {
        kv(out, "pressure_scale", nums(scale, 0, 17));
    }
    match &e.pressure {
        Pressure::Single(c) => kv(out, "pressure", inline(&curve(c, 0))),
        Pressure::ByLoad(curves) => {
            let rows: Vec<String> = curves
                .iter()
                .map(|lp| {
                    let mut fields = vec![("load", num(lp.load))];
                    fields.extend(curve(&lp.curve, 4));
                    format!("    {},\n", inline(&fields))
                })
                .collect();
            kv(out, "pressure_by_load", format!("[\n{}]", rows.concat()));
        }
    }
}

fn curve(c: &PressureCurve, indent: usize) -> [(&'static str, String); 2] {
    [
        (
            "crank_angle_deg",
            nums(&c.crank_angle_deg, indent, indent + 32),
        ),
        ("bar", nums(&c.pressure_bar, indent, indent + 32)),
    ]
}

fn harmonic(out: &mut String, h: &Harmonic) {
    out.push_str("\n[[harmonic]]\n");
    kv(out, "at", string(&h.at));
    kv(out, "order", num(h.order));
    let amplitude = match &h.amplitude {
        HarmonicAmplitude::Constant(a) => num(*a),
        HarmonicAmplitude::BySpeed {
            speed_rpm,
            amplitude_nm,
        } => inline(&[
            ("rpm", nums(speed_rpm, 0, 20)),
            ("nm", nums(amplitude_nm, 0, 20)),
        ]),
    };
    kv(out, "amplitude", amplitude);
    // Always written: the key is required (no default in `spec/model-format.md`).
    kv(out, "phase_deg", num(h.phase_deg));
}

fn operation(out: &mut String, op: &Operation) {
    if op == &Operation::default() {
        return;
    }
    out.push_str("\n[operation]\n");
    if let Some(r) = &op.speed_range_rpm {
        kv(out, "speed_range_rpm", nums(r, 0, 24));
    }
    if let Some(r) = &op.operating_range_rpm {
        kv(out, "operating_range_rpm", nums(r, 0, 24));
    }
    if let Some(orders) = &op.orders {
        kv(out, "orders", nums(orders, 0, 9));
    }
    if !op.regimes.is_empty() {
        let rows: Vec<String> = op
            .regimes
            .iter()
            .map(|r| {
                let label = toml_edit::Value::from(r.label.as_str()).to_string();
                let mut fields = vec![
                    ("label", label.trim().to_string()),
                    ("speed_rpm", num(r.speed_rpm)),
                ];
                if r.load != 1.0 {
                    fields.push(("load", num(r.load)));
                }
                format!("    {},\n", inline(&fields))
            })
            .collect();
        kv(out, "regimes", format!("[\n{}]", rows.concat()));
    }
}

fn expect(out: &mut String, ex: &Expect) {
    if ex.is_empty() {
        return;
    }
    out.push_str("\n[expect]\n");
    let rows = |rows: Vec<String>| format!("[\n{}]", rows.concat());
    if !ex.mode_hz.is_empty() {
        let list = ex.mode_hz.iter().map(|m| {
            let fields = [
                ("mode", m.mode.to_string()),
                ("min", num(m.min_hz)),
                ("max", num(m.max_hz)),
            ];
            format!("    {},\n", inline(&fields))
        });
        kv(out, "mode_hz", rows(list.collect()));
    }
    if !ex.critical_rpm.is_empty() {
        let list = ex.critical_rpm.iter().map(|c| {
            let fields = [
                ("order", num(c.order)),
                ("min", num(c.min_rpm)),
                ("max", num(c.max_rpm)),
            ];
            format!("    {},\n", inline(&fields))
        });
        kv(out, "critical_rpm", rows(list.collect()));
    }
    if !ex.no_resonance_in_operating_range.is_empty() {
        let orders = nums(&ex.no_resonance_in_operating_range, 0, 34);
        kv(out, "no_resonance_in_operating_range", orders);
    }
    if !ex.within_ratings.is_empty() {
        let names: Vec<String> = ex.within_ratings.iter().map(|n| string(n)).collect();
        kv(out, "within_ratings", array(&names, 0, 5));
    }
}
