//! One run vocabulary (issue 14, item 1): the GUI (which shows
//! [`torsim::recording::classify`] for an open recording and for the diagnosis list) and
//! the diagnosis ([`torsim::diagnose::observe::observe`]) classify every shipped
//! recording alike — the same shape, at speeds that agree.

use std::path::{Path, PathBuf};
use torsim::diagnose::LabelledRecording;
use torsim::diagnose::observe::observe;
use torsim::recording::{RunShape, classify, read_recording};

/// The recordings of every shipped diagnosis case, by case.
fn cases() -> Vec<(String, Vec<PathBuf>)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/diagnosis");
    let mut out = Vec::new();
    for entry in std::fs::read_dir(&root).expect("tests/data/diagnosis") {
        let dir = entry.expect("an entry").path();
        if !dir.is_dir() {
            continue;
        }
        let mut csvs: Vec<PathBuf> = std::fs::read_dir(&dir)
            .expect("a case directory")
            .map(|e| e.expect("an entry").path())
            .filter(|p| p.extension().is_some_and(|e| e == "csv"))
            .collect();
        csvs.sort();
        out.push((dir.display().to_string(), csvs));
    }
    out.sort();
    out
}

#[test]
fn the_gui_and_the_diagnosis_classify_every_shipped_recording_alike() {
    let cases = cases();
    assert!(cases.len() >= 7, "{} cases", cases.len());
    let (mut steady, mut long, mut ramp) = (0, 0, 0);
    for (case, csvs) in cases {
        let recordings: Vec<LabelledRecording> = csvs
            .iter()
            .map(|p| LabelledRecording {
                label: p.display().to_string(),
                recording: read_recording(p, None).expect("a shipped recording reads"),
            })
            .collect();
        let observed = observe(&recordings, 12.0).expect("the diagnosis observes it");
        for (lr, run) in recordings.iter().zip(&observed.runs) {
            let gui = classify(&lr.recording);
            let diagnosis = run.regime;
            assert_eq!(
                std::mem::discriminant(&gui),
                std::mem::discriminant(&diagnosis),
                "{case}: {}: GUI {gui:?}, diagnosis {diagnosis:?}",
                lr.label
            );
            assert_eq!(gui.label(), diagnosis.label());
            // The speeds are measured two ways (the GUI: the sidecar's nominal speed or a
            // line through the trace; the diagnosis: the order analysis's mean speed or
            // the STFT windows' ramp), so they agree only to the bench's slow wobble of
            // the mean speed and the line fit's ends: within 1 %.
            for (g, d) in gui.speeds_rpm().iter().zip(diagnosis.speeds_rpm()) {
                assert!(
                    (g - d).abs() <= 0.01 * d.abs(),
                    "{case}: {}: GUI {gui:?}, diagnosis {diagnosis:?}",
                    lr.label
                );
            }
            match gui {
                RunShape::Steady { .. } => steady += 1,
                RunShape::LongRun { .. } => long += 1,
                RunShape::Ramp { .. } => ramp += 1,
            }
        }
    }
    // Every shape is exercised by the shipped cases.
    assert!(steady > 0 && long > 0 && ramp > 0, "{steady} {long} {ramp}");
}
