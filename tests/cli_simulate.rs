//! `simulate` and `compare` from the command line: JSON shapes of `spec/cli.md`, and
//! `analyse` of a simulated CSV gives back `simulate`'s own numbers.

mod run_cli;
use run_cli::{json, torsim};

/// The analysis `simulate` prints and the analysis of the CSV it wrote agree to the last
/// printed digit: the CSV round-trips the samples exactly.
#[test]
fn analyse_of_simulate_csv_gives_back_its_orders() {
    let scratch = tempfile::Builder::new()
        .prefix("torsim-sim-")
        .tempdir()
        .unwrap();
    let dir = scratch.path();
    let csv = dir.join("rig.csv").display().to_string();
    let sim = json(&[
        "simulate",
        "preset:test-rig-70sh",
        "--speed-rpm",
        "3000",
        "--duration-s",
        "1",
        "--rate-hz",
        "4096",
        "--csv",
        &csv,
        "--json",
    ]);
    for key in ["rms_rpm", "irregularity_pct", "orders"] {
        assert!(
            sim[key]["engine"].is_number() || sim[key]["engine"].is_object(),
            "{key}"
        );
    }
    assert!(
        sim["orders"]["middle_flange"]["1"].as_f64().unwrap() > 0.1,
        "order 1 near Regime A's resonance"
    );
    assert!(sim["power_loss_w"]["b"].as_f64().unwrap() > 0.0);
    let analysed = json(&["analyse", &csv, "--json"]);
    for node in ["engine", "coupling_es", "middle_flange"] {
        for q in ["0.5", "1", "2", "4"] {
            let (a, b) = (
                sim["orders"][node][q].as_f64().unwrap(),
                analysed["orders"][node][q].as_f64().unwrap(),
            );
            assert!(
                (a - b).abs() <= 1e-9 * a.abs().max(1e-9),
                "{node} order {q}: {a} vs {b}"
            );
        }
        let (a, b) = (
            sim["irregularity_pct"][node].as_f64().unwrap(),
            analysed["irregularity_pct"][node].as_f64().unwrap(),
        );
        assert!((a - b).abs() <= 1e-9 * a.abs(), "{node} IR");
    }
    let sidecar = std::fs::read_to_string(dir.join("rig.toml")).unwrap();
    assert!(sidecar.contains("kind = \"steady\"") && sidecar.contains("reference = \"engine\""));
}

#[test]
fn run_up_and_errors() {
    let v = json(&[
        "simulate",
        "preset:test-rig-70sh",
        "--run-up",
        "2500:3500",
        "--duration-s",
        "2",
        "--rate-hz",
        "4096",
        "--json",
    ]);
    assert!(v["rms_rpm"]["middle_flange"].as_f64().unwrap() > 0.0);
    assert!(v["stft"].is_object(), "a run-up has its STFT");
    let out = torsim(&[
        "simulate",
        "preset:test-rig-70sh",
        "--run-up",
        "2500-3500",
        "--duration-s",
        "2",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("FROM:TO"));
    let out = torsim(&["simulate", "preset:test-rig-70sh"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn compare_json_shape() {
    let v = json(&[
        "compare",
        "preset:test-rig-mod2",
        "preset:test-rig-mod3",
        "--speeds-rpm",
        "3000,4440",
        "--duration-s",
        "0.5",
        "--json",
    ]);
    let variants = v["variants"].as_array().unwrap();
    assert_eq!(variants.len(), 2);
    for variant in variants {
        assert_eq!(
            variant["irregularity_pct"]["middle_flange"]
                .as_array()
                .unwrap()
                .len(),
            2
        );
        assert_eq!(variant["power_loss_w"]["b"].as_array().unwrap().len(), 2);
        assert_eq!(variant["speeds_rpm"][1].as_f64(), Some(4440.0));
    }
    let out = torsim(&["compare", "tests/data/spec-examples/three-dof.toml"]);
    assert_eq!(out.status.code(), Some(2), "no regimes and no --speeds-rpm");
}

/// The coupling ratings in `response`, `simulate` (steady and run-up) and `compare`
/// (issue 16): the
/// genset's rated coupling is judged at every limit on a steady run, at T_Kmax on a
/// run-up, and at each regime of a comparison; the JSON carries the same table as
/// `response`'s.
#[test]
fn simulate_and_compare_check_the_ratings() {
    let steady = json(&[
        "simulate",
        "preset:cng-genset",
        "--speed-rpm",
        "1500",
        "--duration-s",
        "0.5",
        "--json",
    ]);
    let stage = &steady["ratings"][0];
    assert_eq!(stage["connection"], "coupling");
    let limits: Vec<&str> = stage["worst"]
        .as_array()
        .expect("worst checks")
        .iter()
        .map(|c| c["limit"].as_str().expect("limit name"))
        .collect();
    assert_eq!(limits, ["T_KN", "T_Kmax", "T_KW", "P_KV"]);
    for c in stage["worst"].as_array().expect("worst checks") {
        let u = c["utilisation"].as_f64().expect("utilisation");
        assert!(u > 0.05 && u < 1.0, "{c}: the preset is rated for 1500 rpm");
        assert_eq!(c["speed_rpm"].as_f64(), Some(1500.0));
    }

    let run_up = json(&[
        "simulate",
        "preset:cng-genset",
        "--run-up",
        "1000:2000",
        "--duration-s",
        "2",
        "--json",
    ]);
    let worst = &run_up["ratings"][0]["worst"];
    assert_eq!(worst.as_array().map(Vec::len), Some(1), "{worst}");
    assert_eq!(worst[0]["limit"], "T_Kmax");
    let at = worst[0]["speed_rpm"].as_f64().expect("speed");
    assert!((1000.0..=2000.0).contains(&at), "peak at {at} rpm");

    // `response --json` on a rated preset (it printed nothing while `order` was null).
    let response = json(&[
        "response",
        "preset:cng-genset",
        "--from-rpm",
        "1000",
        "--to-rpm",
        "2000",
        "--json",
    ]);
    let worst = response["ratings"][0]["worst"].as_array().expect("worst");
    assert_eq!(worst.len(), 4);
    assert!(worst[2]["order"].as_f64().is_some(), "T_KW names its order");
    assert!(worst[0].get("order").is_none(), "T_KN has no order");

    let compared = json(&[
        "compare",
        "preset:cng-genset",
        "--speeds-rpm",
        "1200,1800",
        "--duration-s",
        "0.5",
        "--json",
    ]);
    let by_speed = &compared["variants"][0]["ratings"][0]["utilisation_by_speed"];
    assert_eq!(
        by_speed["T_KW"].as_array().map(Vec::len),
        Some(2),
        "{by_speed}"
    );
    let text = String::from_utf8(
        torsim(&[
            "compare",
            "preset:cng-genset",
            "--speeds-rpm",
            "1500",
            "--duration-s",
            "0.5",
        ])
        .stdout,
    )
    .expect("UTF-8");
    assert!(text.contains("Coupling ratings (DIN 740-2"), "{text}");
}
