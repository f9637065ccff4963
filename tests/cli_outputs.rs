//! Issue 13, "Outputs can never destroy inputs": every command refuses an output that
//! resolves to one of its inputs (exit 2, naming the flag, the path and the input), writes
//! only after its computation succeeded, and leaves no temporary file on failure or on
//! SIGTERM.

mod run_cli;
mod scratch;
use run_cli::torsim;
use scratch::Scratch;
use std::path::Path;

/// A fresh empty directory, removed when the returned guard is dropped.
fn dir(name: &str) -> Scratch {
    Scratch::new(&format!("torsim-outputs-{name}-"))
}

/// Every file of `dir` with its bytes.
fn snapshot(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            let bytes = std::fs::read(e.path()).unwrap_or_default();
            (e.file_name().to_string_lossy().into_owned(), bytes)
        })
        .collect();
    files.sort();
    files
}

#[test]
fn an_output_that_resolves_to_an_input_is_refused_with_exit_2() {
    let d = dir("guard");
    let model = std::fs::read_to_string("presets/test-rig-mod1.toml").unwrap();
    for name in ["run.toml", "model.toml", "regime-a.toml"] {
        std::fs::write(d.join(name), &model).unwrap();
    }
    std::fs::write(d.join("rec.csv"), "time_s,crank_rpm\n0,1\n").unwrap();
    std::fs::write(d.join("rec.toml"), "format = 1\n").unwrap();
    std::fs::write(
        d.join("truth.toml"),
        "[[run]]\nfile = \"a\"\nkind = \"steady\"\nspeed_rpm = 3960\nduration_s = 0.5\n",
    )
    .unwrap();
    let p = |name: &str| d.join(name).display().to_string();
    let before = snapshot(&d);
    let sim = ["simulate", "--speed-rpm", "1500", "--duration-s", "0.2"];
    let cases: Vec<(Vec<String>, &str)> = vec![
        (
            [&sim[..], &[&p("run.toml"), "--csv", &p("run.csv")]]
                .concat()
                .iter()
                .map(|s| s.to_string())
                .collect(),
            "run.csv: refused: its sidecar",
        ),
        (
            [&sim[..], &["preset:test-rig-mod1", "--csv", &p("out.toml")]]
                .concat()
                .iter()
                .map(|s| s.to_string())
                .collect(),
            "out.toml: refused: a recording's sidecar is its CSV's name with `.toml`, so the CSV would be its own sidecar",
        ),
        (
            [&sim[..], &[&p("model.toml"), "--csv", &p("model.toml")]]
                .concat()
                .iter()
                .map(|s| s.to_string())
                .collect(),
            "model.toml: refused: it would replace the model",
        ),
        (
            ["campbell", &p("model.toml"), "--csv", &p("model.toml")]
                .iter()
                .map(|s| s.to_string())
                .collect(),
            "model.toml: refused: it would replace the model",
        ),
        (
            [
                "diagnose",
                &p("model.toml"),
                &p("rec.csv"),
                "--report",
                &p("rec.csv"),
            ]
            .iter()
            .map(|s| s.to_string())
            .collect(),
            "rec.csv: refused: it would replace the recording",
        ),
        (
            [
                "diagnose",
                &p("model.toml"),
                &p("rec.csv"),
                "--report",
                &p("rec.toml"),
            ]
            .iter()
            .map(|s| s.to_string())
            .collect(),
            "rec.toml: refused: it would replace the sidecar of the recording",
        ),
        (
            [
                "diagnose",
                &p("model.toml"),
                &p("rec.csv"),
                "--report",
                &p("model.toml"),
            ]
            .iter()
            .map(|s| s.to_string())
            .collect(),
            "model.toml: refused: it would replace the model",
        ),
        (
            [
                "synth",
                &p("regime-a.toml"),
                "--effect",
                "none",
                "--out",
                &p(""),
            ]
            .iter()
            .map(|s| s.to_string())
            .collect(),
            "regime-a.toml would replace the model",
        ),
        (
            [
                "synth",
                "preset:test-rig-mod1",
                "--effect",
                "none",
                "--plan",
                &p("truth.toml"),
                "--out",
                &p(""),
            ]
            .iter()
            .map(|s| s.to_string())
            .collect(),
            "truth.toml: refused: it would replace the plan",
        ),
    ];
    for (args, words) in &cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = torsim(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(words), "{args:?}: {stderr}");
        assert_eq!(snapshot(&d), before, "{args:?} changed a file");
    }
}

#[test]
fn a_simulate_that_fails_leaves_its_outputs_untouched() {
    let d = dir("failed");
    std::fs::write(d.join("x.csv"), "old csv").unwrap();
    std::fs::write(d.join("x.toml"), "old toml").unwrap();
    let before = snapshot(&d);
    let csv = d.join("x.csv").display().to_string();
    let args = [
        "simulate",
        "--speed-rpm",
        "300",
        "--duration-s",
        "1",
        "--csv",
        &csv,
        "preset:test-rig-mod1",
    ];
    let out = torsim(&args);
    assert_eq!(
        out.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(snapshot(&d), before);
}

#[test]
fn a_sidecar_that_cannot_be_written_leaves_the_csv_untouched() {
    let d = dir("sidecar");
    std::fs::write(d.join("x.csv"), "old csv").unwrap();
    std::fs::create_dir_all(d.join("x.toml/inner")).unwrap();
    let csv = d.join("x.csv").display().to_string();
    let args = [
        "simulate",
        "preset:test-rig-70sh",
        "--speed-rpm",
        "3000",
        "--duration-s",
        "0.5",
        "--csv",
        &csv,
    ];
    let out = torsim(&args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("x.toml: cannot write: is a folder"),
        "{stderr}"
    );
    assert_eq!(std::fs::read_to_string(d.join("x.csv")).unwrap(), "old csv");
    assert_eq!(
        std::fs::read_dir(&d).unwrap().count(),
        2,
        "no temporary left"
    );
}

#[test]
fn a_csv_changed_after_its_sidecar_is_refused() {
    let d = dir("changed");
    let csv = d.join("r.csv").display().to_string();
    let args = [
        "simulate",
        "preset:test-rig-70sh",
        "--speed-rpm",
        "3000",
        "--duration-s",
        "0.5",
        "--csv",
        &csv,
    ];
    assert!(torsim(&args).status.success());
    assert!(torsim(&["analyse", &csv]).status.success());
    let text = std::fs::read_to_string(&csv).unwrap();
    let cut: Vec<&str> = text.lines().collect();
    std::fs::write(&csv, cut[..cut.len() - 1].join("\n") + "\n").unwrap();
    let out = torsim(&["analyse", &csv]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains(
            "the CSV was changed after its sidecar was written, or the write was interrupted"
        ),
        "{stderr}"
    );
}

/// SIGTERM at any moment of a large write: the process ends with 143 (or finished before
/// the signal), leaves no `.tmp` file, and the target is either the old file or the whole
/// new one.
#[cfg(unix)]
#[test]
fn sigterm_during_a_write_leaves_no_temporary_and_an_intact_target() {
    use std::process::{Command, Stdio};
    use std::time::{Duration, Instant};
    let d = dir("sigterm");
    let csv = d.join("big.csv");
    // Moments: early (simulating), and as soon as a temporary file appears (writing).
    for wait_for_tmp in [false, true] {
        std::fs::write(&csv, "old csv").unwrap();
        std::fs::write(d.join("big.toml"), "old toml").unwrap();
        let mut child = Command::new(env!("CARGO_BIN_EXE_torsim"))
            .args([
                "simulate",
                "preset:test-rig-70sh",
                "--speed-rpm",
                "3000",
                "--duration-s",
                "20",
                "--rate-hz",
                "20000",
                "--csv",
            ])
            .arg(&csv)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let start = Instant::now();
        let tmp_seen = || {
            std::fs::read_dir(&d)
                .unwrap()
                .any(|e| e.unwrap().file_name().to_string_lossy().ends_with(".tmp"))
        };
        if wait_for_tmp {
            while !tmp_seen() && start.elapsed() < Duration::from_secs(120) {
                if child.try_wait().unwrap().is_some() {
                    break;
                }
                std::thread::sleep(Duration::from_millis(1));
            }
        } else {
            std::thread::sleep(Duration::from_millis(300));
        }
        let killed = Command::new("kill")
            .args(["-TERM", &child.id().to_string()])
            .status()
            .unwrap();
        assert!(killed.success() || child.try_wait().unwrap().is_some());
        let status = child.wait().unwrap();
        assert!(matches!(status.code(), Some(143) | Some(0)), "{status:?}");
        assert!(!tmp_seen(), "a temporary file is left (exit {status:?})");
        let text = std::fs::read_to_string(&csv).unwrap();
        assert!(
            text == "old csv" || (text.starts_with("time_s,") && text.ends_with('\n')),
            "the target is old or whole"
        );
    }
}
