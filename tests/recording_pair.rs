//! Issue 13: a recording's CSV + sidecar pair killed between its two renames is refused by
//! the reader; a finished pair reads back identical. The writer is stopped between the
//! stages in this process, and, for real, in a child process that aborts between them.

mod scratch;

use scratch::Scratch;
use std::path::Path;
use torsim::recording::{
    Channel, ChannelKind, Recording, RecordingMeta, RunKind, prepare_recording, read_recording,
    write_recording,
};

/// A steady 1500 rpm recording of `seconds` at 1 kHz, the speed offset by `offset_rpm`.
fn recording(seconds: f64, offset_rpm: f64) -> Recording {
    let n = (seconds * 1000.0) as usize;
    let time_s: Vec<f64> = (0..n).map(|i| i as f64 / 1000.0).collect();
    let values = time_s
        .iter()
        .map(|t| 1500.0 + offset_rpm + 3.0 * (2.0 * std::f64::consts::PI * 50.0 * t).sin())
        .collect();
    let mut meta = RecordingMeta::new(RunKind::Steady, "crank");
    meta.speed_rpm = Some(1500.0);
    Recording {
        time_s,
        channels: vec![Channel {
            column: "crank_rpm".into(),
            kind: ChannelKind::from_column("crank_rpm").unwrap(),
            values,
        }],
        meta,
    }
}

/// A fresh empty directory, removed when the returned guard is dropped.
fn dir(name: &str) -> Scratch {
    Scratch::new(&format!("torsim-pair-{name}-"))
}

fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Both outcomes of a writer stopped between the renames, over a pair written before.
fn check_both_outcomes(dir: &Path, csv: &Path) {
    let e = read_recording(csv, None).unwrap_err().to_string();
    assert!(
        e.contains(
            "the CSV was changed after its sidecar was written, or the write was interrupted"
        ),
        "{e}"
    );
    assert!(
        e.contains("run.csv") && e.contains("run.toml"),
        "names both files: {e}"
    );
    assert_eq!(names(dir), ["run.csv", "run.toml"], "no temporary left");
    // Finished: the pair reads back identical.
    let new = recording(2.0, 100.0);
    write_recording(&new, csv).unwrap();
    let back = read_recording(csv, None).unwrap();
    assert_eq!(back.time_s, new.time_s);
    assert_eq!(back.channels, new.channels);
}

#[test]
fn a_writer_stopped_between_the_renames_leaves_a_pair_the_reader_refuses() {
    let dir = dir("staged");
    let csv = dir.join("run.csv");
    write_recording(&recording(2.0, 0.0), &csv).unwrap();
    let pending = prepare_recording(&recording(2.0, 100.0), &csv).unwrap();
    let first = pending.commit_first().unwrap();
    drop(first); // "killed": the sidecar's temporary goes, the old sidecar stays.
    check_both_outcomes(&dir, &csv);
}

/// In the child: writes the pair's first stage and aborts (no destructors, no cleanup).
#[test]
fn child_aborting_between_renames() {
    let Ok(csv) = std::env::var("TORSIM_PAIR_CHILD_CSV") else {
        return;
    };
    let pending = prepare_recording(&recording(2.0, 100.0), Path::new(&csv)).unwrap();
    let _first = pending.commit_first().unwrap();
    std::process::abort();
}

#[test]
fn a_child_process_killed_between_the_renames_leaves_a_pair_the_reader_refuses() {
    let dir = dir("child");
    let csv = dir.join("run.csv");
    write_recording(&recording(2.0, 0.0), &csv).unwrap();
    let status = std::process::Command::new(std::env::current_exe().unwrap())
        .args(["--exact", "child_aborting_between_renames", "--nocapture"])
        .env("TORSIM_PAIR_CHILD_CSV", &csv)
        .stderr(std::process::Stdio::null())
        .status()
        .unwrap();
    assert!(!status.success(), "the child aborted");
    // An aborted process runs no cleanup: its sidecar temporary is still there.
    let left: Vec<String> = names(&dir)
        .into_iter()
        .filter(|n| n.ends_with(".tmp"))
        .collect();
    assert_eq!(left.len(), 1, "{left:?}");
    std::fs::remove_file(dir.join(&left[0])).unwrap();
    check_both_outcomes(&dir, &csv);
}

#[test]
fn a_sidecar_without_the_fingerprint_is_accepted_and_a_bad_one_is_located() {
    let dir = dir("bench");
    let csv = dir.join("run.csv");
    write_recording(&recording(2.0, 0.0), &csv).unwrap();
    let sidecar = dir.join("run.toml");
    let text = std::fs::read_to_string(&sidecar).unwrap();
    let bench: String = text
        .lines()
        .filter(|l| !l.starts_with("csv_"))
        .map(|l| format!("{l}\n"))
        .collect();
    std::fs::write(&sidecar, &bench).unwrap();
    // A bench's own sidecar: no fingerprint, so an edited CSV is taken as it is.
    let mut csv_text = std::fs::read_to_string(&csv).unwrap();
    csv_text.push_str("# a comment added by hand\n");
    std::fs::write(&csv, &csv_text).unwrap();
    assert!(read_recording(&csv, None).is_ok());
    std::fs::write(
        &sidecar,
        format!("{bench}csv_sha256 = \"xyz\"\ncsv_rows = 1\n"),
    )
    .unwrap();
    let e = read_recording(&csv, None).unwrap_err().to_string();
    assert!(
        e.contains("run.toml:") && e.contains("`csv_sha256`: expected 64 hex digits"),
        "{e}"
    );
}
