//! Reader errors (syntax, unknown and missing keys, types, value ranges) name the key
//! path, the line and what is wrong. Inputs are small inline models.

mod common;

use common::{BASE, ENGINE, RUBBER, error, fails, fails_at, replaced, with};
use torsim::model::parse_model;

#[test]
fn base_models_are_valid() {
    parse_model(BASE, "t").expect("base");
    parse_model(&with(ENGINE), "t").expect("engine");
    parse_model(&with(RUBBER), "t").expect("rubber");
}

#[test]
fn toml_syntax_error_reports_its_line() {
    let text = replaced(BASE, "inertia = 2.0", "inertia = = 2.0");
    let e = error(&text);
    assert_eq!(e.line, Some(10), "{e}");
    assert_eq!(e.key, "");
    assert!(e.message.contains("TOML syntax error"), "{e}");
    assert!(
        e.to_string()
            .starts_with("test.toml:line 10: TOML syntax error"),
        "{e}"
    );
}

#[test]
fn duplicate_toml_key_is_a_syntax_error_with_line() {
    let text = replaced(BASE, "inertia = 2.0", "inertia = 2.0\ninertia = 3.0");
    let e = error(&text);
    assert_eq!(e.line, Some(11), "{e}");
}

#[test]
fn unknown_keys_in_every_table() {
    let t = replaced(BASE, "inertia = 2.0", "inertia = 2.0\ninertai = 2.0");
    fails(&t, "inertia[1].inertai", "inertai", "unknown key `inertai`");
    let t = replaced(BASE, "stiffness = 1000.0", "stiffness = 1000.0\nstiff = 1");
    fails(&t, "connection[0].stiff", "stiff =", "unknown key `stiff`");
    let t = replaced(BASE, "name = \"t\"", "name = \"t\"\nversion = 2");
    fails(&t, "version", "version", "unknown key `version`");
    let t = with(&replaced(
        RUBBER,
        "per_side = 4,",
        "per_side = 4, pitch = 1,",
    ));
    fails(
        &t,
        "connection[1].elements.pitch",
        "pitch = 1",
        "unknown key `pitch`",
    );
    let t = with(&format!(
        "{RUBBER}thermal = {{ capacity_j_per_k = 1, conductance_w_per_k = 1, ambient = 20 }}\n"
    ));
    fails(
        &t,
        "connection[1].thermal.ambient",
        "thermal",
        "unknown key `ambient`",
    );
    let t = with(&replaced(ENGINE, "bar = [", "pa = [1], bar = ["));
    fails(&t, "engine.pressure.pa", "pa = [1]", "unknown key `pa`");
    let by_load = "pressure_by_load = [\n  { load = 1, crank_angle_deg = [0, 90], bar = [1, 2], rpm = 3 },\n]";
    let t = with(&replaced(
        ENGINE,
        "pressure = { crank_angle_deg = [0, 90, 180], bar = [50, 10, 0] }",
        by_load,
    ));
    fails(
        &t,
        "engine.pressure_by_load[0].rpm",
        "rpm = 3",
        "unknown key `rpm`",
    );
    let t = with("\n[operation]\nspeed_range = [1, 2]\n");
    fails(
        &t,
        "operation.speed_range",
        "speed_range",
        "unknown key `speed_range`",
    );
    let t = with("\n[expect]\nmode_hz = [\n  { mode = 1, min = 1, max = 2, tol = 1 },\n]\n");
    fails(&t, "expect.mode_hz[0].tol", "tol = 1", "unknown key `tol`");
    let t = with("\n[load]\nat = \"b\"\ndampnig = 1\n");
    fails(&t, "load.dampnig", "dampnig", "unknown key `dampnig`");
}

#[test]
fn missing_required_key_points_at_the_table_header() {
    let t = replaced(BASE, "inertia = 2.0\n", "");
    fails_at(
        &t,
        "inertia[1].inertia",
        8,
        "missing required key `inertia`",
    );
    let t = replaced(BASE, "stiffness = 1000.0\n", "");
    fails_at(
        &t,
        "connection[0].stiffness",
        12,
        "missing required key `stiffness`",
    );
    let t = with(&replaced(ENGINE, "bore = 0.1\n", ""));
    fails(&t, "engine.bore", "[engine]", "missing required key `bore`");
    let t = with(&replaced(RUBBER, "psi = 1.0\n", ""));
    fails_at(&t, "connection[1].psi", 18, "missing required key `psi`");
    let t = replaced(BASE, "format = 1\n", "");
    assert_eq!(error(&t).key, "format");
}

#[test]
fn wrong_type_is_reported() {
    let t = replaced(BASE, "inertia = 2.0", "inertia = \"2.0\"");
    fails(
        &t,
        "inertia[1].inertia",
        "\"2.0\"",
        "expected a number, found a string",
    );
    let t = replaced(BASE, "name = \"a\"", "name = 3");
    fails(
        &t,
        "inertia[0].name",
        "name = 3",
        "expected a string, found an integer",
    );
    let t = with(&replaced(ENGINE, "cylinders = 2", "cylinders = 2.0"));
    fails(
        &t,
        "engine.cylinders",
        "cylinders",
        "expected an integer, found a float",
    );
    let t = with(&replaced(
        ENGINE,
        "bar = [50, 10, 0]",
        "bar = [50, \"x\", 0]",
    ));
    fails(
        &t,
        "engine.pressure.bar[1]",
        "bar = [",
        "expected a number, found a string",
    );
}

#[test]
fn integers_are_accepted_where_floats_are_expected() {
    let t = replaced(BASE, "inertia = 2.0", "inertia = 2");
    let model = parse_model(&t, "t").expect("integer inertia");
    assert_eq!(model.inertias[1].inertia_kg_m2, 2.0);
}

#[test]
fn format_other_than_1_is_rejected() {
    let t = replaced(BASE, "format = 1", "format = 2");
    fails_at(&t, "format", 1, "model format 2 is not supported");
}

#[test]
fn values_that_must_be_positive() {
    let cases = [
        (
            BASE.to_string(),
            "inertia = 2.0",
            "inertia = 0.0",
            "inertia[1].inertia",
        ),
        (
            BASE.to_string(),
            "inertia = 2.0",
            "inertia = nan",
            "inertia[1].inertia",
        ),
        (
            BASE.to_string(),
            "stiffness = 1000.0",
            "stiffness = -1.0",
            "connection[0].stiffness",
        ),
        (
            BASE.to_string(),
            "stiffness = 1000.0",
            "stiffness = inf",
            "connection[0].stiffness",
        ),
        (with(RUBBER), "psi = 1.0", "psi = 0", "connection[1].psi"),
        (with(ENGINE), "bore = 0.1", "bore = 0", "engine.bore"),
        (
            with(ENGINE),
            "crank_radius = 0.05",
            "crank_radius = -0.05",
            "engine.crank_radius",
        ),
        (
            with(ENGINE),
            "conrod_length = 0.2",
            "conrod_length = 0",
            "engine.conrod_length",
        ),
        (
            with(RUBBER),
            "psi = 1.0",
            "psi = 1.0\nthermal = { capacity_j_per_k = 0, conductance_w_per_k = 1, ambient_c = 20 }",
            "connection[1].thermal.capacity_j_per_k",
        ),
    ];
    for (text, from, to, key) in cases {
        let t = replaced(&text, from, to);
        let needle = to.lines().last().unwrap_or(to);
        fails(&t, key, needle, "must be a positive finite number");
    }
    let gear = "kind = \"gear\"\nfrom = \"a\"\nto = \"b\"\nratio = 0.0";
    let t = replaced(
        BASE,
        "kind = \"shaft\"\nfrom = \"a\"\nto = \"b\"\nstiffness = 1000.0",
        gear,
    );
    fails(
        &t,
        "connection[0].ratio",
        "ratio",
        "must be finite and non-zero",
    );
    let t = replaced(&t, "ratio = 0.0", "ratio = 2.0\nmesh_stiffness = 0");
    fails(
        &t,
        "connection[0].mesh_stiffness",
        "mesh_stiffness",
        "must be a positive finite",
    );
}

#[test]
fn values_that_must_not_be_negative() {
    let t = replaced(BASE, "inertia = 2.0", "inertia = 2.0\ndamping = -1");
    fails(
        &t,
        "inertia[1].damping",
        "damping",
        "must be a finite number ≥ 0",
    );
    let t = replaced(
        BASE,
        "stiffness = 1000.0",
        "stiffness = 1000.0\ndamping = -0.5",
    );
    fails(
        &t,
        "connection[0].damping",
        "damping",
        "must be a finite number ≥ 0",
    );
    let t = with(&replaced(
        ENGINE,
        "bore = 0.1",
        "bore = 0.1\nreciprocating_mass = -3",
    ));
    fails(&t, "engine.reciprocating_mass", "reciprocating_mass", "≥ 0");
    let gear = "kind = \"gear\"\nfrom = \"a\"\nto = \"b\"\nratio = 2.0\nbacklash_deg = -0.1";
    let t = replaced(
        BASE,
        "kind = \"shaft\"\nfrom = \"a\"\nto = \"b\"\nstiffness = 1000.0",
        gear,
    );
    fails(&t, "connection[0].backlash_deg", "backlash_deg", "≥ 0");
}

// ---- issue 13: names, limits, required keys, located messages ----

#[test]
fn node_and_connection_names_every_format_can_carry() {
    let node = |name: &str| {
        let t = replaced(BASE, "name = \"b\"", &format!("name = {name}"));
        replaced(&t, "to = \"b\"", &format!("to = {name}"))
    };
    for (toml_name, says) in [
        (r#""b,c""#, "contains a comma"),
        (r#""b\nc""#, "U+000A"),
        (r#""b\u0007""#, "U+0007"),
        (r#""   ""#, "has only spaces"),
        (r#"" b""#, "starts or ends with a space"),
        (r#""b ""#, "starts or ends with a space"),
        (r#""b\"c""#, "double quote"),
        (r#""b\uFEFF""#, "U+FEFF"),
    ] {
        let t = node(toml_name);
        fails_at(&t, "inertia[1].name", 9, says);
        assert!(error(&t).message.contains("every output format"), "{t}");
    }
    let t = replaced(BASE, "name = \"b\"", "name = \"\"");
    fails_at(&t, "inertia[1].name", 9, "is empty");
    // Interior spaces and other printable Unicode read back from a CSV header.
    parse_model(&node("\"Kurbel welle Ü\""), "t").expect("printable name");
    let t = replaced(BASE, "kind = \"shaft\"", "kind = \"shaft\"\nname = \"s,1\"");
    fails(
        &t,
        "connection[0].name",
        "s,1",
        "connection name \"s,1\" contains a comma",
    );
}

#[test]
fn cylinders_above_the_limit_are_refused() {
    let t = with(&replaced(ENGINE, "cylinders = 2", "cylinders = 65"));
    fails(&t, "engine.cylinders", "cylinders", "limit of 64");
    assert!(error(&t).message.contains("--max-cylinders"));
    let at = (0..64).map(|_| "\"a\"").collect::<Vec<_>>().join(", ");
    let t = with(&replaced(
        ENGINE,
        "cylinders = 2",
        &format!(
            "cylinders = 64\nfiring_angles_deg = [{}]",
            at.replace("\"a\"", "0")
        ),
    ));
    parse_model(&t, "t").expect("64 cylinders is within the limit");
}

#[test]
fn operation_orders_empty_or_out_of_range_are_refused() {
    let t = with("\n[operation]\norders = []\n");
    fails(&t, "operation.orders", "orders", "is empty");
    let t = with("\n[operation]\norders = [1, 100.5]\n");
    fails(
        &t,
        "operation.orders[1]",
        "orders",
        "above the limit max_order = 100",
    );
    let t = with("\n[operation]\norders = [0.5, 100]\n");
    parse_model(&t, "t").expect("order 100 is within the limit");
    let t = with("\n[[harmonic]]\nat = \"a\"\norder = 1e9\namplitude = 1\nphase_deg = 0\n");
    fails(&t, "harmonic[0].order", "order", "max_order");
}

#[test]
fn harmonic_phase_is_required() {
    let t = with("\n[[harmonic]]\nat = \"a\"\norder = 1\namplitude = 5\n");
    fails(
        &t,
        "harmonic[0].phase_deg",
        "[[harmonic]]",
        "missing required key `phase_deg`",
    );
}

#[test]
fn duplicate_key_is_named() {
    let text = replaced(BASE, "inertia = 2.0", "inertia = 2.0\ninertia = 3.0");
    let e = error(&text);
    assert!(e.message.contains("duplicate key `inertia`"), "{e}");
}

#[test]
fn a_model_without_nodes_names_the_file() {
    let e = error("format = 1\nname = \"t\"\n");
    assert_eq!(e.key, "inertia", "{e}");
    assert!(
        e.to_string()
            .starts_with("test.toml: key `inertia`: the model has no `[[inertia]]` nodes"),
        "{e}"
    );
}

#[test]
fn model_files_not_utf8_name_line_and_offset_and_bom_crlf_are_accepted() {
    let scratch = tempfile::Builder::new()
        .prefix("torsim-model-utf8-")
        .tempdir()
        .unwrap();
    let dir = scratch.path();
    let bad = dir.join("latin1.toml");
    let mut bytes = BASE
        .replace("name = \"b\"", "name = \"b\u{e9}\"")
        .into_bytes();
    let at = bytes.iter().position(|&b| b == 0xC3).unwrap();
    bytes.splice(at..at + 2, [0xE9]);
    std::fs::write(&bad, &bytes).unwrap();
    let e = torsim::model::read_model_file(&bad).unwrap_err();
    assert_eq!(e.line, Some(9), "{e}");
    assert!(e.message.contains(&format!("byte offset {at}")), "{e}");
    assert!(e.message.contains("not valid UTF-8"), "{e}");
    let bom = dir.join("bom.toml");
    let crlf = format!("\u{FEFF}{}", BASE.replace('\n', "\r\n"));
    std::fs::write(&bom, crlf).unwrap();
    let model = torsim::model::read_model_file(&bom).expect("BOM and CRLF");
    assert_eq!(model.inertias.len(), 2);
}

#[test]
fn rubber_temperatures_outside_the_law_are_refused() {
    let t = with(&format!("{RUBBER}temperature_c = -300.0\n"));
    fails(
        &t,
        "connection[1].temperature_c",
        "temperature_c",
        "-300 °C is outside",
    );
    assert!(error(&t).message.contains("-100 … 300 °C"));
    let t = with(&format!(
        "{RUBBER}thermal = {{ capacity_j_per_k = 1, conductance_w_per_k = 1, ambient_c = 400 }}\n"
    ));
    fails(
        &t,
        "connection[1].thermal.ambient_c",
        "thermal",
        "400 °C is outside",
    );
    parse_model(&with(&format!("{RUBBER}temperature_c = -40.0\n")), "t").expect("−40 °C");
}

/// `a —gear— g —shaft— b`: the gear's ratio and the shaft's stiffness in round-off.
const GEARED: &str = r#"format = 1
name = "t"
[[inertia]]
name = "a"
inertia = 1.0
[[inertia]]
name = "g"
inertia = 1.0
[[inertia]]
name = "b"
inertia = 2.0
[[connection]]
kind = "gear"
from = "a"
to = "g"
ratio = 0.5
mesh_stiffness = 1e6
[[connection]]
kind = "shaft"
from = "g"
to = "b"
stiffness = 1000.0
"#;

#[test]
fn magnitudes_that_make_the_system_singular_are_refused_at_their_key() {
    parse_model(GEARED, "t").expect("valid");
    for ratio in ["1e-300", "1e-5", "2e4", "-1e5"] {
        let t = replaced(GEARED, "ratio = 0.5", &format!("ratio = {ratio}"));
        fails(
            &t,
            "connection[0].ratio",
            "ratio",
            "magnitude from 1e-4 to 1e4 (one gear",
        );
    }
    parse_model(&replaced(GEARED, "ratio = 0.5", "ratio = -1e4"), "t").expect("1:10 000");
    let t = replaced(GEARED, "stiffness = 1000.0", "stiffness = 1e-308");
    fails(
        &t,
        "connection[1].stiffness",
        "stiffness = 1e-308",
        "below 1e-12 of the largest, connection `a-g`'s",
    );
    // Referred (× 0.25 both): 1e-3 N·m/rad is 4e-9 of the mesh's 1e6, above round-off.
    let t = replaced(GEARED, "stiffness = 1000.0", "stiffness = 1e-3");
    parse_model(&t, "t").expect("4e-9 of the mesh");
    let t = replaced(GEARED, "inertia = 2.0", "inertia = 1e-20");
    fails(&t, "inertia[2].inertia", "1e-20", "inertia of node `b`");
}
