//! The command line: JSON shapes of `spec/cli.md`, exit codes, errors that name the file.

mod run_cli;
use run_cli::{json, torsim};

use std::path::PathBuf;

const THREE_DOF: &str = "tests/data/spec-examples/three-dof.toml";
const RUBBER: &str = "tests/data/spec-examples/rubber-elements.toml";

#[test]
fn modes_json_shape() {
    let v = json(&["modes", THREE_DOF, "--json"]);
    let modes = v["modes"].as_array().unwrap();
    assert_eq!(
        modes.len(),
        3,
        "grounded 3-DOF: three flexible modes, no rigid one"
    );
    for (i, m) in modes.iter().enumerate() {
        assert_eq!(m["mode"], i + 1);
        assert!(m["frequency_hz"].as_f64().unwrap() > 0.0);
        assert!(m["damping_ratio"].as_f64().unwrap() > 0.0);
        let shape = m["shape"].as_object().unwrap();
        assert_eq!(
            shape.keys().collect::<Vec<_>>(),
            ["engine", "coupling_es", "middle_flange"]
        );
        let peak = shape
            .values()
            .map(|x| x.as_f64().unwrap().abs())
            .fold(0.0, f64::max);
        assert!(
            (peak - 1.0).abs() < 1e-12,
            "shapes scaled to a largest magnitude of 1"
        );
    }
    // A free-free model lists no rigid-body mode.
    let v = json(&["modes", RUBBER, "--json"]);
    assert_eq!(v["modes"].as_array().unwrap().len(), 1);
    assert_eq!(v["rigid_body_modes"], 1);
}

#[test]
fn campbell_json_shape_and_csv() {
    let scratch = tempfile::Builder::new()
        .prefix("torsim-campbell-")
        .tempdir()
        .unwrap();
    let csv = scratch.path().join("campbell.csv");
    let csv_arg = csv.display().to_string();
    let v = json(&[
        "campbell",
        RUBBER,
        "--from-rpm",
        "400",
        "--to-rpm",
        "2000",
        "--step-rpm",
        "10",
        "--json",
        "--csv",
        &csv_arg,
    ]);
    let speeds = v["speeds_rpm"].as_array().unwrap();
    assert_eq!(speeds.len(), 161);
    let modes = v["modes"].as_array().unwrap();
    assert_eq!(modes[0]["mode"], 1);
    assert_eq!(modes[0]["frequency_hz"].as_array().unwrap().len(), 161);
    let crossings = v["crossings"].as_array().unwrap();
    assert!(!crossings.is_empty());
    for c in crossings {
        let (q, rpm, f) = (
            c["order"].as_f64().unwrap(),
            c["rpm"].as_f64().unwrap(),
            c["frequency_hz"].as_f64().unwrap(),
        );
        assert!((q * rpm / 60.0 - f).abs() < 1e-9 * f, "on the order line");
        assert!((400.0..=2000.0).contains(&rpm));
        let mode_f = modes[c["mode"].as_u64().unwrap() as usize - 1]["frequency_hz"][0]
            .as_f64()
            .unwrap();
        assert!((mode_f - f).abs() < 1e-9 * f, "on the mode");
    }
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("speed_rpm,mode_1_hz,order_0.5_hz"));
    assert_eq!(text.lines().count(), 162);
}

#[test]
fn response_json_shape() {
    let v = json(&[
        "response",
        RUBBER,
        "--from-rpm",
        "400",
        "--to-rpm",
        "2000",
        "--step-rpm",
        "100",
        "--json",
    ]);
    let n = v["speeds_rpm"].as_array().unwrap().len();
    assert_eq!(n, 17);
    for node in ["crank", "generator"] {
        let by_order = v["nodes"][node]["ias_amplitude_rpm"].as_object().unwrap();
        assert_eq!(by_order.keys().next().unwrap(), "0.5");
        assert!(
            by_order.contains_key("1")
                && by_order.contains_key("1.5")
                && by_order.contains_key("12")
        );
        assert_eq!(by_order["3"].as_array().unwrap().len(), n);
    }
    let c = &v["connections"]["crank-generator"];
    assert_eq!(c["torque_amplitude_nm"]["3"].as_array().unwrap().len(), n);
    assert_eq!(c["torque_peak_nm"].as_array().unwrap().len(), n);
    let loss = c["power_loss_w"].as_array().unwrap();
    assert!(
        loss.iter().all(|p| p.as_f64().unwrap() > 0.0),
        "a rubber stage always loses power"
    );
    // The peak over a cycle is at least the mean torque.
    let mean = c["torque_mean_nm"].as_f64().unwrap();
    assert!(
        c["torque_peak_nm"]
            .as_array()
            .unwrap()
            .iter()
            .all(|p| p.as_f64().unwrap() >= mean.abs())
    );
}

#[test]
fn coupling_json_shape() {
    let v = json(&[
        "coupling",
        RUBBER,
        "--frequency-hz",
        "100",
        "--temperature-c",
        "40",
        "--twist-deg",
        "1.9098593171027443",
        "--json",
    ]);
    let c = &v["couplings"][0];
    assert_eq!(c["name"], "crank-generator");
    // 1.909…° = 5/150 rad: x = 5 mm, so k = 28 800·1.3965·2.289·0.8032 (seed 000 eq. 13).
    let k = c["stiffness_nm_per_rad"].as_f64().unwrap();
    assert!(
        (k - 28_800.0 * 1.3965 * 2.289 * 0.8032).abs() < 1e-6 * k,
        "{k}"
    );
    assert!((c["psi"].as_f64().unwrap() - 0.8718).abs() < 1e-12);
    assert!((c["loss_factor"].as_f64().unwrap() - 0.8718 / std::f64::consts::TAU).abs() < 1e-12);
}

#[test]
fn check_passes_on_shipped_presets_and_fails_on_a_broken_expectation() {
    let v = json(&["check", "--json"]);
    let presets = v["presets"].as_array().unwrap();
    assert!(presets.len() >= 7);
    for p in presets {
        assert_eq!(p["passed"], true, "{}", p["file"]);
        assert!(
            !p["checks"].as_array().unwrap().is_empty(),
            "{} has checks",
            p["file"]
        );
    }
    // Removed when dropped.
    let broken = tempfile::Builder::new()
        .prefix("torsim-broken-")
        .suffix(".toml")
        .tempfile()
        .unwrap()
        .into_temp_path();
    let text = std::fs::read_to_string(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(THREE_DOF))
        .unwrap()
        + "\n[expect]\nmode_hz = [{ mode = 1, min = 100.0, max = 120.0 }]\n";
    std::fs::write(&broken, text).unwrap();
    let out = torsim(&["check", &broken.display().to_string()]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("FAIL")
            && stdout.contains("mode 1 in 100 … 120 Hz")
            && stdout.contains("computed mode 1 at 15."),
        "{stdout}"
    );
}

#[test]
fn bad_input_names_file_line_and_key_with_exit_2() {
    // Removed when dropped.
    let bad = tempfile::Builder::new()
        .prefix("torsim-bad-")
        .suffix(".toml")
        .tempfile()
        .unwrap()
        .into_temp_path();
    let text = std::fs::read_to_string(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(THREE_DOF))
        .unwrap()
        .replace("stiffness = 2.0e5", "stiffness = -2.0e5");
    std::fs::write(&bad, &text).unwrap();
    let out = torsim(&["modes", &bad.display().to_string()]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    let line = text.lines().position(|l| l.contains("-2.0e5")).unwrap() + 1;
    assert!(
        stderr.contains(&bad.display().to_string())
            && stderr.contains(&format!("line {line}"))
            && stderr.contains("stiffness"),
        "{stderr}"
    );
    assert!(out.stdout.is_empty());

    let out = torsim(&["modes", "no/such/file.toml"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no/such/file.toml"));
    let out = torsim(&["frobnicate"]);
    assert_eq!(out.status.code(), Some(2));
    let out = torsim(&["response", THREE_DOF, "--load", "1.5"]);
    assert_eq!(out.status.code(), Some(2));
    let out = torsim(&["modes", "preset:nonexistent"]);
    assert_eq!(out.status.code(), Some(2));
}

/// Regression: output piped into a reader that has gone (`| head`) ended in a panic.
#[test]
fn closed_stdout_is_not_a_panic() {
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_torsim"))
        .args(["response", "preset:cng-genset"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(out.status.success(), "{stderr}");
}

/// Regression: modes above a rubber stage's measured frequency range were computed with
/// α_f held at its end value without a word.
#[test]
fn frequency_beyond_measured_range_warns() {
    let out = torsim(&["modes", "preset:cng-genset"]);
    assert!(out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("warning: rubber stage `coupling`")
            && stderr.contains("held at its end value"),
        "{stderr}"
    );
}
