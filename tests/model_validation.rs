//! Semantic errors from `validate`, located by the reader: key path, line and message.
//! Inputs are small inline models; lines are found by searching the text.

mod common;

use common::{BASE, ENGINE, RUBBER, fails, fails_at, replaced, with};
use torsim::model::{parse_model, validate};

#[test]
fn node_names() {
    let t = replaced(BASE, "name = \"b\"", "name = \"a\"");
    fails_at(&t, "inertia[1].name", 9, "duplicate node name `a`");
    let t = replaced(BASE, "name = \"b\"", "name = \"ground\"");
    fails(&t, "inertia[1].name", "\"ground\"", "`ground` is reserved");
}

#[test]
fn connection_names_and_ends() {
    let t = with("\n[[connection]]\nkind = \"shaft\"\nfrom = \"a\"\nto = \"b\"\nstiffness = 5.0\n");
    fails_at(
        &t,
        "connection[1].name",
        18,
        "duplicate connection name `a-b`",
    );
    let t = replaced(BASE, "to = \"b\"", "to = \"c\"");
    fails(&t, "connection[0].to", "to = \"c\"", "unknown node `c`");
    let t = replaced(BASE, "from = \"a\"", "from = \"x\"");
    fails(&t, "connection[0].from", "from = \"x\"", "unknown node `x`");
    let t = with("\n[[connection]]\nkind = \"shaft\"\nfrom = \"b\"\nto = \"b\"\nstiffness = 5.0\n");
    fails_at(&t, "connection[1].to", 21, "connects node `b` to itself");
}

#[test]
fn connection_ends_in_the_ground() {
    let t = with(
        "\n[[connection]]\nkind = \"shaft\"\nfrom = \"ground\"\nto = \"ground\"\nstiffness = 5.0\n",
    );
    fails(
        &t,
        "connection[1].to",
        "to = \"ground\"",
        "both ends are `ground`",
    );
    let t = with("\n[[connection]]\nkind = \"gear\"\nfrom = \"b\"\nto = \"ground\"\nratio = 2.0\n");
    fails(
        &t,
        "connection[1].to",
        "to = \"ground\"",
        "a gear cannot connect to `ground`",
    );
}

#[test]
fn node_connected_to_nothing() {
    let t = with("\n[[inertia]]\nname = \"lonely\"\ninertia = 1.0\n");
    fails_at(
        &t,
        "inertia[2]",
        18,
        "node `lonely` is connected to nothing",
    );
}

#[test]
fn gear_tree_errors() {
    // A gear loop: a→b directly and through a 2:1 gear gives b two speeds.
    let t = with(
        "\n[[connection]]\nkind = \"gear\"\nname = \"g\"\nfrom = \"a\"\nto = \"b\"\nratio = 2.0\n",
    );
    fails(&t, "connection[1].ratio", "ratio = 2.0", "two speeds");
    // Two separate drivelines: c-d is not reached from a.
    let extra = "\n[[inertia]]\nname = \"c\"\ninertia = 1.0\n\n[[inertia]]\nname = \"d\"\ninertia = 1.0\n\n[[connection]]\nkind = \"shaft\"\nfrom = \"c\"\nto = \"d\"\nstiffness = 5.0\n";
    fails_at(
        &with(extra),
        "inertia[2]",
        18,
        "not connected to the reference node `a`",
    );
}

#[test]
fn unknown_nodes_in_engine_harmonic_and_load() {
    let t = with(&replaced(ENGINE, "at = \"a\"", "at = \"zz\""));
    fails(&t, "engine.at", "\"zz\"", "unknown node `zz`");
    let t = with(&replaced(ENGINE, "at = \"a\"", "at = [\"a\",\n  \"zz\"]"));
    fails(&t, "engine.at[1]", "\"zz\"", "unknown node `zz`");
    let t = with("\n[[harmonic]]\nat = \"q\"\norder = 1\namplitude = 5\nphase_deg = 0\n");
    fails(&t, "harmonic[0].at", "\"q\"", "unknown node `q`");
    let t = with("\n[load]\nat = \"w\"\n");
    fails(&t, "load.at", "\"w\"", "unknown node `w`");
}

#[test]
fn engine_checks() {
    let e = |from: &str, to: &str| with(&replaced(ENGINE, from, to));
    fails(
        &e("cylinders = 2", "cylinders = 0"),
        "engine.cylinders",
        "cylinders",
        "at least 1",
    );
    fails(
        &e("cylinders = 2", "cylinders = 2\nstrokes = 3"),
        "engine.strokes",
        "strokes",
        "must be 2 or 4",
    );
    let t = e("cylinders = 2", "cylinders = 3");
    let t = replaced(&t, "at = \"a\"", "at = [\"a\", \"b\"]");
    fails(&t, "engine.at", "at = [", "lists 2 nodes");
    let t = e(
        "cylinders = 2",
        "cylinders = 2\nfiring_angles_deg = [0, 120, 240]",
    );
    fails(
        &t,
        "engine.firing_angles_deg",
        "firing_angles_deg",
        "has 3 angles but the engine has 2",
    );
    let t = e("conrod_length = 0.2", "conrod_length = 0.05");
    fails(
        &t,
        "engine.conrod_length",
        "conrod_length",
        "longer than crank_radius",
    );
    let t = e("cylinders = 2", "cylinders = -1");
    fails(&t, "engine.cylinders", "cylinders", "non-negative integer");
}

#[test]
fn pressure_table_checks() {
    let p = |table: &str| {
        with(&replaced(
            ENGINE,
            "pressure = { crank_angle_deg = [0, 90, 180], bar = [50, 10, 0] }",
            &format!("pressure = {table}"),
        ))
    };
    let key = "engine.pressure.crank_angle_deg";
    let t = p("{ crank_angle_deg = [0, 90, 180], bar = [50, 10] }");
    fails(
        &t,
        "engine.pressure.bar",
        "pressure",
        "has 2 values but crank_angle_deg has 3",
    );
    fails(
        &p("{ crank_angle_deg = [0], bar = [50] }"),
        key,
        "pressure",
        "at least 2 points",
    );
    let t = p("{ crank_angle_deg = [0, 90, 90], bar = [50, 10, 0] }");
    fails(
        &t,
        "engine.pressure.crank_angle_deg[2]",
        "pressure",
        "strictly increasing",
    );
    let t = p("{ crank_angle_deg = [-360, 0, 361], bar = [0, 50, 0] }");
    fails(&t, key, "pressure", "more than one cycle (720°)");
    let t = p("{ crank_angle_deg = [-360, 0, 360], bar = [0, 50, 1] }");
    fails(&t, key, "pressure", "equal first and last pressures");
    parse_model(
        &p("{ crank_angle_deg = [-360, 0, 360], bar = [0, 50, 0] }"),
        "t",
    )
    .expect("closed");
    let t = replaced(
        &p("{ crank_angle_deg = [-180, 0, 180], bar = [0, 50, 1] }"),
        "cylinders = 2",
        "cylinders = 2\nstrokes = 2",
    );
    fails(&t, key, "pressure", "(360°)");
    let t = p("{ crank_angle_deg = [0, 90, 180], bar = [50, nan, 0] }");
    fails(&t, "engine.pressure.bar[1]", "pressure", "finite");
}

#[test]
fn pressure_by_load_checks() {
    let p = |l0: &str, l1: &str| {
        let table = format!(
            "pressure_by_load = [\n  {{ load = {l0}, crank_angle_deg = [0, 90], bar = [1, 2] }},\n  {{ load = {l1}, crank_angle_deg = [0, 90], bar = [3, 4] }},\n]"
        );
        with(&replaced(
            ENGINE,
            "pressure = { crank_angle_deg = [0, 90, 180], bar = [50, 10, 0] }",
            &table,
        ))
    };
    parse_model(&p("0.5", "1.0"), "t").expect("by load");
    fails(
        &p("0.5", "1.5"),
        "engine.pressure_by_load[1].load",
        "load = 1.5",
        "must be in [0, 1]",
    );
    fails(
        &p("0.5", "0.5"),
        "engine.pressure_by_load[1].load",
        "bar = [3, 4]",
        "strictly increasing",
    );
}

#[test]
fn rubber_checks() {
    let r = |from: &str, to: &str| with(&replaced(RUBBER, from, to));
    let t = r("count = 8, per_side = 4", "count = 1, per_side = 4");
    fails(&t, "connection[1].elements.count", "elements", "at least 2");
    let t = r("per_side = 4", "per_side = 0");
    fails(
        &t,
        "connection[1].elements.per_side",
        "elements",
        "0 < per_side < count (8)",
    );
    let t = r("per_side = 4", "per_side = 8");
    fails(&t, "connection[1].elements.per_side", "elements", "found 8");
    let t = r("pitch_diameter = 0.3", "pitch_diameter = -0.3");
    fails(
        &t,
        "connection[1].elements.pitch_diameter",
        "elements",
        "positive",
    );
    let t = r("radial_stiffness = 6.4e5", "radial_stiffness = 0");
    fails(
        &t,
        "connection[1].elements.radial_stiffness",
        "elements",
        "positive",
    );
    let direct = r(
        "elements = { count = 8, per_side = 4, pitch_diameter = 0.3, radial_stiffness = 6.4e5 }",
        "stiffness = 1e4",
    );
    let t = replaced(
        &direct,
        "psi = 1.0",
        "psi = 1.0\namplitude_poly = [0.0152, 0.0033, 1.0]",
    );
    fails(
        &t,
        "connection[1].amplitude_poly",
        "amplitude_poly",
        "needs `elements`",
    );
    let t = replaced(
        &direct,
        "stiffness = 1e4",
        "stiffness = 1e4\nelements = { count = 8, per_side = 4, pitch_diameter = 0.3, radial_stiffness = 1 }",
    );
    fails(&t, "connection[1].elements", "elements", "not both");
}

#[test]
fn rubber_polynomial_checks() {
    let r = |extra: &str| with(&format!("{RUBBER}{extra}\n"));
    // 1 − 0.02·T crosses zero at 50 °C.
    let poly = "temperature_stiffness_poly = [0.0, -0.02, 1.0]";
    parse_model(&r(poly), "t").expect("factor 0.5 at 25 °C");
    let t = r(&format!("temperature_c = 60.0\n{poly}"));
    fails(
        &t,
        "connection[1].temperature_stiffness_poly",
        "temperature_stiffness_poly",
        "at temperature_c = 60",
    );
    let t = r(&format!(
        "thermal = {{ capacity_j_per_k = 1, conductance_w_per_k = 1, ambient_c = 50 }}\n{}",
        poly.replace("stiffness", "damping")
    ));
    fails(
        &t,
        "connection[1].temperature_damping_poly",
        "temperature_damping_poly",
        "at thermal.ambient_c = 50",
    );
    let t = r("frequency_poly = [0.0, 0.01, 1.0]\nfrequency_poly_range = [300.0, 0.0]");
    fails(
        &t,
        "connection[1].frequency_poly_range",
        "frequency_poly_range",
        "lo < hi",
    );
    let t = r("frequency_poly_range = [0.0, 300.0]");
    fails(
        &t,
        "connection[1].frequency_poly_range",
        "frequency_poly_range",
        "without `frequency_poly`",
    );
    let t = r("frequency_poly = [0.0, 1.0]");
    fails(
        &t,
        "connection[1].frequency_poly",
        "frequency_poly",
        "list of 3 numbers, found 2",
    );
}

#[test]
fn harmonic_checks() {
    let h = |body: &str| {
        with(&format!(
            "\n[[harmonic]]\nat = \"a\"\nphase_deg = 0\n{body}\n"
        ))
    };
    fails(
        &h("order = 0\namplitude = 5"),
        "harmonic[0].order",
        "order",
        "positive",
    );
    fails(
        &h("order = 1\namplitude = -5"),
        "harmonic[0].amplitude",
        "amplitude",
        "≥ 0",
    );
    fails(
        &h("order = 1\namplitude = inf"),
        "harmonic[0].amplitude",
        "amplitude",
        "finite",
    );
    let t = h("order = 1\namplitude = { rpm = [100, 100], nm = [1, 2] }");
    fails(
        &t,
        "harmonic[0].amplitude.rpm[1]",
        "amplitude",
        "strictly increasing",
    );
    let t = h("order = 1\namplitude = { rpm = [100, 200], nm = [1] }");
    fails(
        &t,
        "harmonic[0].amplitude.nm",
        "amplitude",
        "has 1 values but rpm has 2",
    );
    let t = h("order = 1\namplitude = { rpm = [100, 200], nm = [1, 2], x = 1 }");
    fails(
        &t,
        "harmonic[0].amplitude.x",
        "amplitude",
        "unknown key `x`",
    );
}

#[test]
fn operation_checks() {
    let o = |body: &str| with(&format!("\n[operation]\n{body}\n"));
    let t = o("speed_range_rpm = [-1, 100]");
    fails(
        &t,
        "operation.speed_range_rpm",
        "speed_range_rpm",
        "0 ≤ min < max",
    );
    let t = o("operating_range_rpm = [100, 100]");
    fails(
        &t,
        "operation.operating_range_rpm",
        "operating_range_rpm",
        "0 ≤ min < max",
    );
    fails(
        &o("orders = [1, 0]"),
        "operation.orders[1]",
        "orders",
        "positive",
    );
    let t = o("speed_range_rpm = [1, 2, 3]");
    fails(
        &t,
        "operation.speed_range_rpm",
        "speed_range_rpm",
        "list of 2 numbers, found 3",
    );
}

#[test]
fn expect_checks() {
    let x = |body: &str| {
        with(&format!(
            "\n[operation]\noperating_range_rpm = [1, 2]\n\n[expect]\n{body}\n"
        ))
    };
    let t = x("mode_hz = [\n  { mode = 0, min = 1, max = 2 },\n]");
    fails(&t, "expect.mode_hz[0].mode", "mode = 0", "counted from 1");
    let t = x("mode_hz = [\n  { mode = 1, min = 3, max = 2 },\n]");
    fails(
        &t,
        "expect.mode_hz[0].max",
        "mode = 1",
        "max (2) is below min (3)",
    );
    let t = x("critical_rpm = [\n  { order = -1, min = 1, max = 2 },\n]");
    fails(&t, "expect.critical_rpm[0].order", "order = -1", "positive");
    let t = x("critical_rpm = [\n  { order = 1, min = 10, max = 2 },\n]");
    fails(&t, "expect.critical_rpm[0].max", "order = 1", "below min");
    let t = x("no_resonance_in_operating_range = [1, -2]");
    fails(
        &t,
        "expect.no_resonance_in_operating_range[1]",
        "no_resonance",
        "positive",
    );
    let t = with("\n[expect]\nno_resonance_in_operating_range = [1]\n");
    fails(
        &t,
        "expect.no_resonance_in_operating_range",
        "no_resonance",
        "needs `operating_range_rpm`",
    );
}

#[test]
fn validate_in_memory_has_key_paths_but_no_file_or_line() {
    let mut model = parse_model(BASE, "t").expect("base");
    model.inertias[1].name = "a".into();
    let e = validate(&model).expect_err("duplicate");
    assert_eq!(
        (e.file, e.line, e.key.as_str()),
        (None, None, "inertia[1].name")
    );
    assert!(e.message.contains("duplicate node name"));
}

#[test]
fn connection_name_defaults_to_from_to() {
    let model = parse_model(BASE, "t").expect("base");
    assert_eq!(model.connections[0].name, "a-b");
}

/// A gear's mesh damping is ≥ 0 and needs an elastic mesh: a rigid gear has no twist.
#[test]
fn gear_mesh_damping_checks() {
    let gear = |keys: &str| {
        replaced(
            BASE,
            "kind = \"shaft\"\nfrom = \"a\"\nto = \"b\"\nstiffness = 1000.0",
            &format!("kind = \"gear\"\nfrom = \"a\"\nto = \"b\"\nratio = 2.0\n{keys}"),
        )
    };
    fails(
        &gear("mesh_damping = 5.0"),
        "connection[0].mesh_damping",
        "mesh_damping = 5.0",
        "needs `mesh_stiffness`",
    );
    fails(
        &gear("mesh_stiffness = 1.0e5\nmesh_damping = -1.0"),
        "connection[0].mesh_damping",
        "mesh_damping = -1.0",
        "must be a finite number ≥ 0, found -1",
    );
    let ok = gear("mesh_stiffness = 1.0e5\nmesh_damping = 5.0");
    let model = parse_model(&ok, "ok.toml").unwrap();
    assert!(validate(&model).is_ok());
}

#[test]
fn amplitude_saturation_checks() {
    let sat = "psi = 1.0\namplitude_saturation = { stiffening = 0.3, deformation_mm = 0.5 }";
    let good = with(&replaced(RUBBER, "psi = 1.0", sat));
    let m = parse_model(&good, "test.toml").expect("a saturating stage reads");
    let stage = m
        .connections
        .iter()
        .find(|c| c.name == "r")
        .expect("stage r");
    let torsim::model::ConnectionKind::Rubber(r) = &stage.kind else {
        panic!("a rubber stage");
    };
    let law = r.amplitude_saturation.expect("the law");
    assert_eq!((law.stiffening, law.deformation_mm), (0.3, 0.5));
    // Written and read back, the same model.
    let again = torsim::model::to_toml_string(&m);
    assert_eq!(parse_model(&again, "again.toml").expect("reads back"), m);
    let bad = replaced(&good, "deformation_mm = 0.5", "deformation_mm = 0");
    fails(
        &bad,
        "connection[1].amplitude_saturation.deformation_mm",
        "amplitude_saturation",
        "deformation_mm 0 must be > 0",
    );
    let both = replaced(
        &good,
        "psi = 1.0",
        "psi = 1.0\namplitude_poly = [0.0152, 0.0033, 1.0]",
    );
    fails(
        &both,
        "connection[1].amplitude_saturation",
        "amplitude_saturation",
        "not both",
    );
    let direct = replaced(
        &good,
        "elements = { count = 8, per_side = 4, pitch_diameter = 0.3, radial_stiffness = 6.4e5 }",
        "stiffness = 1e4",
    );
    fails(
        &direct,
        "connection[1].amplitude_saturation",
        "amplitude_saturation",
        "needs `elements`",
    );
    let unknown = replaced(&good, "deformation_mm", "deformation");
    let e = common::error(&unknown);
    assert!(e.to_string().contains("deformation"), "{e}");
}
