//! Reading model files (`spec/model-format.md`, format 1): TOML text → [`Model`], with
//! errors that name the file, the 1-based line and the key path.
//!
//! The reader checks the shape of the file (known keys, required keys, types); the value
//! checks are [`validate`](super::validate::validate)'s, whose key paths are mapped back to
//! lines here.

use std::path::Path;

use toml_edit::Document;

use super::key_lines::{KeyLines, Lines};
use super::read_sections::{engine, expect, harmonic, load, operation};
use super::spanned::Tab;
use super::{
    AmplitudeForm, AmplitudeSaturation, Connection, ConnectionKind, Expect, Gear, Inertia, Model,
    Operation, Poly, PowerLaw, RubberElements, RubberStage, RubberStiffness, Shaft, Thermal,
    ZenerLaw,
};
use super::{ModelError, validate};

/// Parses and validates a model file's text; `file` names it in errors.
///
/// Errors carry the file, the line (of the offending key, or of the header of the table
/// that lacks a required key) and the key path, e.g. `connection[2].stiffness`.
pub fn parse_model(text: &str, file: &str) -> Result<Model, ModelError> {
    // A UTF-8 byte-order mark (Windows editors write one) is not part of the TOML.
    let text = text.strip_prefix('\u{FEFF}').unwrap_or(text);
    let lines = Lines::new(text);
    let doc = Document::parse(text).map_err(|e| ModelError {
        file: Some(file.to_string()),
        line: e.span().map(|s| lines.line_of(s.start)),
        key: String::new(),
        message: syntax_message(text, &e),
    })?;
    let key_lines = KeyLines::new(doc.as_table(), &lines);
    let locate = |err: ModelError| {
        let line = key_lines.line(&err.key);
        ModelError {
            line,
            ..err.in_file(file)
        }
    };
    let model = model(&Tab::new(doc.as_table(), "")).map_err(locate)?;
    validate::validate(&model).map_err(locate)?;
    Ok(model)
}

/// A TOML syntax error for a person; a duplicate key is named, from the error's span
/// (issue 13: "duplicate key" alone gave the line but not the key).
fn syntax_message(text: &str, e: &toml_edit::TomlError) -> String {
    let message = e.message().trim();
    let spanned = e
        .span()
        .and_then(|s| text.get(s))
        .map(str::trim)
        .filter(|s| !s.is_empty() && !s.contains('\n'));
    match spanned {
        Some(key) if message == "duplicate key" => {
            format!("TOML syntax error: duplicate key `{key}` (a key may be given once per table)")
        }
        _ => format!("TOML syntax error: {message}"),
    }
}

/// Reads, parses and validates a model file.
///
/// Text that is not UTF-8 is refused with the line and byte offset of the first bad
/// byte (issue 13).
pub fn read_model_file(path: &Path) -> Result<Model, ModelError> {
    let file = path.display().to_string();
    let bytes = std::fs::read(path)
        .map_err(|e| ModelError::at("", format!("cannot read: {e}")).in_file(&file))?;
    let text = std::str::from_utf8(&bytes).map_err(|e| {
        let offset = e.valid_up_to();
        let line = 1 + bytes[..offset].iter().filter(|&&b| b == b'\n').count();
        ModelError {
            line: Some(line),
            ..ModelError::at(
                "",
                format!(
                    "not valid UTF-8 at byte offset {offset} (byte 0x{:02X}); save the \
                     model file as UTF-8",
                    bytes[offset]
                ),
            )
            .in_file(&file)
        }
    })?;
    parse_model(text, &file)
}

fn model(root: &Tab) -> Result<Model, ModelError> {
    root.allow(&[
        "format",
        "name",
        "description",
        "inertia",
        "connection",
        "engine",
        "harmonic",
        "load",
        "modal_damping",
        "operation",
        "expect",
    ])?;
    let format = root.req("format")?;
    match format.as_integer() {
        Some(1) => {}
        Some(n) => {
            return Err(ModelError::at(
                "format",
                format!("model format {n} is not supported (this reader knows format 1)"),
            ));
        }
        None => return Err(super::spanned::wrong_type("format", "an integer", format)),
    }
    Ok(Model {
        name: root.str("name")?,
        description: root.opt_str("description")?.unwrap_or_default(),
        inertias: root
            .list("inertia")?
            .iter()
            .map(inertia)
            .collect::<Result<_, _>>()?,
        connections: root
            .list("connection")?
            .iter()
            .map(connection)
            .collect::<Result<_, _>>()?,
        engine: root.opt_table("engine")?.map(|t| engine(&t)).transpose()?,
        harmonics: root
            .list("harmonic")?
            .iter()
            .map(harmonic)
            .collect::<Result<_, _>>()?,
        load: root.opt_table("load")?.map(|t| load(&t)).transpose()?,
        modal_damping: root
            .opt_table("modal_damping")?
            .map(|t| super::modal_damping::read(&t))
            .transpose()?,
        operation: match root.opt_table("operation")? {
            Some(t) => operation(&t)?,
            None => Operation::default(),
        },
        expect: match root.opt_table("expect")? {
            Some(t) => expect(&t)?,
            None => Expect::default(),
        },
    })
}

fn inertia(t: &Tab) -> Result<Inertia, ModelError> {
    t.allow(&["name", "inertia", "damping"])?;
    Ok(Inertia {
        name: t.str("name")?,
        inertia_kg_m2: t.f64("inertia")?,
        damping_nm_s_per_rad: t.f64_or("damping", 0.0)?,
    })
}

const COMMON: [&str; 4] = ["kind", "name", "from", "to"];
const POLYS: [&str; 4] = [
    "amplitude_poly",
    "frequency_poly",
    "temperature_stiffness_poly",
    "temperature_damping_poly",
];

fn connection(t: &Tab) -> Result<Connection, ModelError> {
    let kind_name = t.str("kind")?;
    let (extra, kind): (&[&str], _) = match kind_name.as_str() {
        "shaft" => (
            &["stiffness", "damping", "inertia", "segments"],
            shaft as fn(&Tab) -> _,
        ),
        "rubber" => (
            &[
                "stiffness",
                "elements",
                "psi",
                "temperature_c",
                "thermal",
                "amplitude_poly",
                "amplitude_poly_range",
                "amplitude_form",
                "amplitude_saturation",
                "frequency_poly",
                "frequency_poly_range",
                "frequency_power_law",
                "frequency_zener",
                "temperature_stiffness_poly",
                "temperature_stiffness_poly_range",
                "temperature_damping_poly",
                "temperature_damping_poly_range",
                "rating",
            ],
            rubber,
        ),
        "gear" => (
            &[
                "ratio",
                "mesh_stiffness",
                "mesh_damping",
                "backlash_deg",
                "backlash_softening_deg",
                "contact_exponent",
                "contact_reference_deg",
            ],
            gear,
        ),
        other => {
            return Err(ModelError::at(
                t.key("kind"),
                format!("unknown connection kind `{other}` (expected shaft, rubber or gear)"),
            ));
        }
    };
    t.allow(&[&COMMON[..], extra].concat())?;
    let from = t.str("from")?;
    let to = t.str("to")?;
    let name = match t.opt_str("name")? {
        Some(name) => name,
        None => Connection::default_name(&from, &to),
    };
    Ok(Connection {
        name,
        from,
        to,
        kind: kind(t)?,
    })
}

fn shaft(t: &Tab) -> Result<ConnectionKind, ModelError> {
    Ok(ConnectionKind::Shaft(Shaft {
        stiffness_nm_per_rad: t.f64("stiffness")?,
        damping_nm_s_per_rad: t.f64_or("damping", 0.0)?,
        inertia_kg_m2: t.f64_or("inertia", 0.0)?,
        segments: t.opt_u32("segments")?,
    }))
}

fn rubber(t: &Tab) -> Result<ConnectionKind, ModelError> {
    let stiffness = match (t.opt_f64("stiffness")?, t.opt_table("elements")?) {
        (Some(k), None) => RubberStiffness::Direct(k),
        (None, Some(e)) => {
            e.allow(&["count", "per_side", "pitch_diameter", "radial_stiffness"])?;
            RubberStiffness::Elements(RubberElements {
                count: e.u32("count")?,
                per_side: e.u32("per_side")?,
                pitch_diameter_m: e.f64("pitch_diameter")?,
                radial_stiffness_n_per_m: e.f64("radial_stiffness")?,
            })
        }
        (Some(_), Some(_)) => {
            return Err(ModelError::at(
                t.key("elements"),
                "give either `stiffness` or `elements`, not both",
            ));
        }
        (None, None) => {
            return Err(ModelError::at(
                t.key("stiffness"),
                "missing required key `stiffness` (or `elements`)",
            ));
        }
    };
    let [amplitude, frequency, temp_k, temp_d] = POLYS.map(|key| poly(t, key));
    let thermal = match t.opt_table("thermal")? {
        None => None,
        Some(h) => {
            h.allow(&["capacity_j_per_k", "conductance_w_per_k", "ambient_c"])?;
            Some(Thermal {
                capacity_j_per_k: h.f64("capacity_j_per_k")?,
                conductance_w_per_k: h.f64("conductance_w_per_k")?,
                ambient_c: h.f64("ambient_c")?,
            })
        }
    };
    let frequency_power_law = match t.opt_table("frequency_power_law")? {
        None => None,
        Some(h) => {
            h.allow(&["exponent", "reference_hz"])?;
            Some(PowerLaw {
                exponent: h.f64("exponent")?,
                reference_hz: h.f64("reference_hz")?,
            })
        }
    };
    let frequency_zener = match t.opt_table("frequency_zener")? {
        None => None,
        Some(h) => {
            h.allow(&["delta", "alpha", "relax_hz", "reference_hz"])?;
            Some(ZenerLaw {
                delta: h.f64("delta")?,
                alpha: h.f64("alpha")?,
                relax_hz: h.f64("relax_hz")?,
                reference_hz: h.f64("reference_hz")?,
            })
        }
    };
    let amplitude_saturation = match t.opt_table("amplitude_saturation")? {
        None => None,
        Some(h) => {
            h.allow(&["stiffening", "deformation_mm"])?;
            Some(AmplitudeSaturation {
                stiffening: h.f64("stiffening")?,
                deformation_mm: h.f64("deformation_mm")?,
            })
        }
    };
    let amplitude_form = match t.opt_str("amplitude_form")? {
        None => AmplitudeForm::default(),
        Some(key) => AmplitudeForm::from_key(&key).ok_or_else(|| {
            ModelError::at(
                t.key("amplitude_form"),
                format!("unknown amplitude_form `{key}` (expected whole or elastic)"),
            )
        })?,
    };
    Ok(ConnectionKind::Rubber(RubberStage {
        stiffness,
        psi: t.f64("psi")?,
        temperature_c: t.f64_or("temperature_c", 25.0)?,
        amplitude_poly: amplitude?,
        amplitude_saturation,
        amplitude_form,
        frequency_poly: frequency?,
        frequency_power_law,
        frequency_zener,
        temperature_stiffness_poly: temp_k?,
        temperature_damping_poly: temp_d?,
        thermal,
        rating: super::rating::read(t)?,
    }))
}

/// `key = [a2, a1, a0]` with an optional `key_range = [lo, hi]`.
fn poly(t: &Tab, key: &str) -> Result<Option<Poly>, ModelError> {
    let range_key = format!("{key}_range");
    let range = t.opt_array::<2>(&range_key)?;
    match t.opt_array::<3>(key)? {
        Some(coeffs) => Ok(Some(Poly { coeffs, range })),
        None if range.is_some() => Err(ModelError::at(
            t.key(&range_key),
            format!("`{range_key}` is given without `{key}`"),
        )),
        None => Ok(None),
    }
}

fn gear(t: &Tab) -> Result<ConnectionKind, ModelError> {
    Ok(ConnectionKind::Gear(Gear {
        ratio: t.f64("ratio")?,
        mesh_stiffness_nm_per_rad: t.opt_f64("mesh_stiffness")?,
        mesh_damping_nm_s_per_rad: t.f64_or("mesh_damping", 0.0)?,
        backlash_deg: t.f64_or("backlash_deg", 0.0)?,
        backlash_softening_deg: t.f64_or("backlash_softening_deg", 0.0)?,
        contact_exponent: t.f64_or("contact_exponent", 1.0)?,
        contact_reference_deg: t.f64_or("contact_reference_deg", 0.0)?,
    }))
}
