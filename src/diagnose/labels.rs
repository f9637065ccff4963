//! How a recording is named in a diagnosis: one rule for the CLI and the GUI, so the
//! same files give the same labels (and so the same report) in both.
//!
//! - A recording's label is its sidecar's `label` (`spec/recording-format.md`), else its
//!   file stem.
//! - A label that several recordings share names none of them: each gets its file name
//!   added, `"Regime A (a-1.csv)"`. Every copy is renamed, not only the later ones, so the
//!   labels do not depend on the order the files were given or added in (the verdict
//!   does not either: the diagnosis sorts its recordings by label).

use crate::recording::Recording;
use std::path::Path;

/// The label of `recording` read from `path`: its sidecar label, else the file stem.
pub fn label_of(path: &Path, recording: &Recording) -> String {
    recording.meta.label.clone().unwrap_or_else(|| {
        path.file_stem().map_or_else(
            || path.display().to_string(),
            |s| s.to_string_lossy().into_owned(),
        )
    })
}

/// The labels to show for recordings whose own labels are `labels`, read from `paths`
/// (same order and length): a label shared by several gets each one's file name added.
pub fn unique_labels(labels: &[String], paths: &[&Path]) -> Vec<String> {
    labels
        .iter()
        .zip(paths)
        .map(|(label, path)| {
            if labels.iter().filter(|l| *l == label).count() > 1 {
                let name = path.file_name().map_or_else(
                    || path.display().to_string(),
                    |n| n.to_string_lossy().into_owned(),
                );
                format!("{label} ({name})")
            } else {
                label.clone()
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every copy of a shared label is renamed; a label used once stays; the result does
    /// not depend on the order (the GUI adds files one by one, the CLI takes them all).
    #[test]
    fn shared_labels_take_their_file_names_in_any_order() {
        let labels = ["Regime A", "Regime B", "Regime A"]
            .map(String::from)
            .to_vec();
        let paths = [
            Path::new("d/a-1.csv"),
            Path::new("d/b.csv"),
            Path::new("e/a-2.csv"),
        ];
        let out = unique_labels(&labels, &paths);
        assert_eq!(
            out,
            ["Regime A (a-1.csv)", "Regime B", "Regime A (a-2.csv)"]
        );
        let reversed: Vec<String> = labels.iter().rev().cloned().collect();
        let rpaths: Vec<&Path> = paths.iter().rev().copied().collect();
        let mut back = unique_labels(&reversed, &rpaths);
        back.reverse();
        assert_eq!(back, out);
    }

    /// Without a sidecar label the file stem names the recording.
    #[test]
    fn the_file_stem_names_a_recording_without_a_label() {
        let mut rec = Recording {
            time_s: Vec::new(),
            channels: Vec::new(),
            meta: crate::recording::RecordingMeta::new(crate::recording::RunKind::Steady, "crank"),
        };
        assert_eq!(label_of(Path::new("x/regime-c.csv"), &rec), "regime-c");
        rec.meta.label = Some("Regime C".into());
        assert_eq!(label_of(Path::new("x/regime-c.csv"), &rec), "Regime C");
    }
}
