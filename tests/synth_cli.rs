//! `torsim synth` on the command line: a small campaign writes the user's model, the
//! recordings and the truth; bad input exits 2 with a message naming what is wrong.

mod run_cli;
mod synth_support;

use run_cli::torsim;
use synth_support::temp_dir;
use torsim::recording::read_recording;

const PLAN: &str = r#"
[[run]]
file = "c-part"
label = "Regime C, 30 % load"
kind = "steady"
speed_rpm = 3960
load = 0.3
duration_s = 0.5

[[run]]
file = "up"
kind = "run-up"
from_rpm = 3000
to_rpm = 3500
duration_s = 1
rate_hz = 1000
"#;

#[test]
fn writes_model_recordings_and_truth() {
    let dir = temp_dir("cli");
    let plan = dir.join("plan.toml");
    std::fs::write(&plan, PLAN).unwrap();
    let out = dir.join("case");
    let out_arg = out.display().to_string();
    let plan_arg = plan.display().to_string();
    let args = [
        "synth",
        "preset:diagnosis-bench",
        "--effect",
        "gear_backlash",
        "--param",
        "backlash_deg=0.1",
        "--param-error-pct",
        "5",
        "--seed",
        "4",
        "--plan",
        &plan_arg,
        "--out",
        &out_arg,
    ];
    let run = torsim(&args);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(stdout.contains("wrote 2 recordings"), "{stdout}");
    for f in [
        "model.toml",
        "truth.toml",
        "truth-model.toml",
        "c-part.csv",
        "up.toml",
    ] {
        assert!(out.join(f).exists(), "{f}");
    }
    let model = torsim::model::read_model_file(&out.join("model.toml")).unwrap();
    assert_eq!(model.name.split(':').next(), Some("Diagnosis bench"));
    let r = read_recording(&out.join("up.csv"), None).unwrap();
    assert_eq!(r.time_s.len(), 1000);
    assert_eq!(r.meta.label.as_deref(), Some("up"));
    let truth = std::fs::read_to_string(out.join("truth.toml")).unwrap();
    assert!(truth.contains("name = \"gear_backlash\"") && truth.contains("--seed 4"));
    // The same command again makes the same files.
    let first = std::fs::read_to_string(out.join("c-part.csv")).unwrap();
    assert!(torsim(&args).status.success());
    assert_eq!(
        std::fs::read_to_string(out.join("c-part.csv")).unwrap(),
        first
    );
}

#[test]
fn bad_input_exits_2_and_says_why() {
    let dir = temp_dir("cli-bad");
    let out = dir.join("x").display().to_string();
    let bad_plan = dir.join("bad.toml");
    std::fs::write(
        &bad_plan,
        "[[run]]\nfile = \"a\"\nkind = \"steady\"\nduration_s = 1\n",
    )
    .unwrap();
    let plan_arg = bad_plan.display().to_string();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--effect", "backlash"], "unknown effect `backlash`"),
        (
            vec!["--effect", "gear_backlash", "--param", "slack=1"],
            "no parameter `slack`",
        ),
        (
            vec!["--effect", "none", "--param-error-pct", "5"],
            "parameter_error",
        ),
        (
            vec!["--effect", "none", "--station", "nowhere"],
            "station `nowhere`",
        ),
        (
            vec!["--effect", "none", "--plan", &plan_arg],
            "run[0].speed_rpm",
        ),
        (
            vec!["--effect", "none", "--sensor-artifact", "tape_joint:engine"],
            "--sensor-artifact",
        ),
    ];
    for (extra, needle) in cases {
        let mut args = vec!["synth", "preset:diagnosis-bench", "--out", &out];
        args.extend(extra.iter().copied());
        let run = torsim(&args);
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(needle), "{args:?}: {stderr}");
    }
    assert!(!dir.join("x").exists(), "nothing written on bad input");
}
