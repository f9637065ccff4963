//! `torsim analyse`: the JSON shape of spec/cli.md on recordings written by the library,
//! and exit code 2 with `file:line: reason` on a bad recording.

mod run_cli;
use run_cli::{json, torsim};

mod synth;

use synth::{generate, generate_with_angle, put, recording, temp_dir};
use torsim::recording::{RunKind, write_recording};

#[test]
fn analyse_json_shape_steady() {
    let (t, es, theta) = generate_with_angle(
        &|_| 1500.0,
        &[(0.5, 4.0, 0.0), (1.0, 6.0, 1.0)],
        2048.0,
        2.0,
    );
    let bs = theta.iter().map(|th| 1500.0 + 2.0 * th.cos()).collect();
    let es_mean_rpm = es.iter().sum::<f64>() / es.len() as f64;
    let dir = temp_dir("cli-steady");
    let path = dir.join("regime-a.csv");
    write_recording(
        &recording(RunKind::Steady, t, vec![("es", es), ("bs", bs)]),
        &path,
    )
    .expect("write");
    let path = path.to_string_lossy().into_owned();
    let v = json(&["analyse", &path, "--json"]);
    for key in ["rms_rpm", "irregularity_pct", "mean_speed_rpm"] {
        let per = v[key].as_object().unwrap_or_else(|| panic!("{key}"));
        assert_eq!(per.keys().collect::<Vec<_>>(), ["es", "bs"], "{key}");
        assert!(per.values().all(|x| x.as_f64().is_some()));
    }
    let orders = v["orders"]["es"].as_object().expect("orders.es");
    assert_eq!(
        orders.keys().take(4).collect::<Vec<_>>(),
        ["0.5", "1", "1.5", "2"]
    );
    assert!((orders["0.5"].as_f64().unwrap() - 4.0).abs() < 1e-3);
    assert!((orders["1"].as_f64().unwrap() - 6.0).abs() < 1e-3);
    // n_rel = es − bs: order 1 is 6 cos(θ + 1) − 2 cos θ, amplitude |6e^i − 2| = 5.2 rpm.
    let rel = (36.0_f64 + 4.0 - 24.0 * 1.0_f64.cos()).sqrt();
    let got = v["n_rel"]["orders"]["es-bs"]["1"]
        .as_f64()
        .expect("n_rel order 1");
    assert!((got - rel).abs() < 1e-3, "{got} vs {rel}");
    assert!(v["n_rel"]["rms_rpm"]["es-bs"].as_f64().is_some());
    assert!(v.get("stft").is_none(), "a steady run has no STFT");
    // The run by the one classifier: steady at the mean of the reference's column (no
    // `speed_rpm` in the sidecar; printed to 1e-6 rpm, hence 1e-5), 4096 samples at
    // 2048 Hz = 2 s.
    assert_eq!(v["run"]["shape"], "steady");
    let speeds = v["run"]["speeds_rpm"].as_array().expect("speeds_rpm");
    assert!(
        speeds
            .iter()
            .all(|s| (s.as_f64().unwrap() - es_mean_rpm).abs() < 1e-5),
        "{speeds:?} vs {es_mean_rpm}"
    );
    assert!((v["run"]["duration_s"].as_f64().unwrap() - 2.0).abs() < 1e-9);
    // The human table names the stations.
    let out = torsim(&["analyse", &path]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success() && text.contains("es-bs") && text.contains("IR [%]"),
        "{text}"
    );
}

#[test]
fn analyse_json_run_up_has_stft() {
    let (t, n) = generate(&|t| 1000.0 + 500.0 * t, &[(1.0, 5.0, 0.0)], 2048.0, 2.0);
    let dir = temp_dir("cli-runup");
    let path = dir.join("run-up.csv");
    write_recording(&recording(RunKind::RunUp, t, vec![("crank", n)]), &path).expect("write");
    let v = json(&["analyse", &path.to_string_lossy(), "--json"]);
    // A ramp by the one classifier: the least-squares line through 1000 + 500 t rpm and a
    // 5 rpm order 1 (whose bias on the line's ends is well below 3 rpm).
    assert_eq!(v["run"]["shape"], "run-up");
    let ends: Vec<f64> = v["run"]["speeds_rpm"]
        .as_array()
        .expect("speeds_rpm")
        .iter()
        .filter_map(|s| s.as_f64())
        .collect();
    assert!(
        (ends[0] - 1000.0).abs() < 3.0 && (ends[1] - 2000.0).abs() < 3.0,
        "{ends:?}"
    );
    let stft = &v["stft"];
    let times = stft["times_s"].as_array().expect("times_s");
    assert_eq!(
        stft["speeds_rpm"].as_array().map(Vec::len),
        Some(times.len())
    );
    assert!(
        stft["frequencies_hz"]
            .as_array()
            .is_some_and(|f| f.len() > 10)
    );
    let track = stft["stations"]["crank"]["order_tracks_rpm"]["1"]
        .as_array()
        .expect("order 1 track");
    assert_eq!(track.len(), times.len());
    assert!(
        track
            .iter()
            .all(|a| (a.as_f64().unwrap() - 5.0).abs() < 0.15),
        "{track:?}"
    );
    assert!(v["rms_rpm"]["crank"].as_f64().is_some());
}

#[test]
fn analyse_bad_recording_exits_2_naming_file_and_line() {
    let dir = temp_dir("cli-bad");
    let mut csv = String::from("time_s,crank_rpm\n");
    for k in 0..400 {
        let n = if k == 7 {
            "fast".to_string()
        } else {
            "1500".to_string()
        };
        csv += &format!("{},{n}\n", k as f64 / 1000.0);
    }
    let path = put(&dir, "bad.csv", &csv);
    put(
        &dir,
        "bad.toml",
        "format = 1\nkind = \"steady\"\nreference = \"crank\"\n",
    );
    let out = torsim(&["analyse", &path.to_string_lossy(), "--json"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("bad.csv:9: `crank_rpm`: `fast` is not a number"),
        "{err}"
    );
}

/// Issue 13: `analyse nope.csv` says the CSV does not exist (not that its sidecar is
/// missing); an over-range marker is refused by default with column and line, and
/// `--bad-samples interpolate` analyses it with a note on stderr.
#[test]
fn missing_csv_and_bad_samples() {
    let dir = temp_dir("cli-bad-samples");
    let nope = dir.join("nope.csv").to_string_lossy().into_owned();
    let out = torsim(&["analyse", &nope]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("nope.csv: no such recording") && !err.contains(".toml"),
        "{err}"
    );
    let (t, es) = generate(&|_| 1500.0, &[(0.5, 4.0, 0.0)], 2048.0, 1.0);
    let mut es = es;
    es[1000] = 1e300;
    let mut text = String::from("time_s,es_rpm\n");
    for (t, n) in t.iter().zip(&es) {
        text += &format!("{t},{n}\n");
    }
    let path = put(&dir, "spike.csv", &text);
    put(
        &dir,
        "spike.toml",
        "format = 1\nkind = \"steady\"\nreference = \"es\"\n",
    );
    let path = path.to_string_lossy().into_owned();
    let out = torsim(&["analyse", &path]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("spike.csv:1002: `es_rpm`: 1 bad sample"),
        "{err}"
    );
    let v = json(&["analyse", &path, "--bad-samples", "interpolate", "--json"]);
    let half = v["orders"]["es"]["0.5"]
        .as_f64()
        .expect("order 0.5 reported");
    // One interpolated sample of 2048 changes order 0.5 by far less than 1 %.
    assert!((half - 4.0).abs() < 0.04, "{half}");
}
