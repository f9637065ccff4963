//! The shipped presets: the embedded text is the file in `presets/`, each parses,
//! round-trips through the writer, and builds a system with flexible modes.

use torsim::model::{parse_model, presets::PRESETS, to_toml_string};
use torsim::physics::{OperatingPoint, System};

#[test]
fn presets_are_embedded_parse_and_round_trip() {
    for p in PRESETS {
        let path = format!("{}/presets/{}.toml", env!("CARGO_MANIFEST_DIR"), p.name);
        assert_eq!(
            std::fs::read_to_string(&path).unwrap(),
            p.text,
            "{path} differs from the embedded copy"
        );
        let model = parse_model(p.text, &path).unwrap();
        let again = parse_model(&to_toml_string(&model), "written").unwrap();
        assert_eq!(model, again, "{} round trip", p.name);
        let system = System::new(&model, OperatingPoint::default()).unwrap();
        assert!(!torsim::modal::modes(&system).unwrap().is_empty());
        assert!(!model.expect.is_empty(), "{} has [expect] checks", p.name);
    }
}

/// `torsim --help` names every shipped preset, so a preset added to `PRESETS` cannot be
/// left out of the help a user reads (two-inertia, three-inertia and genset-20dof were).
#[test]
fn help_names_every_preset() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_torsim"))
        .arg("--help")
        .output()
        .unwrap();
    let help = String::from_utf8(out.stdout).unwrap();
    for p in PRESETS {
        assert!(
            help.contains(p.name),
            "`torsim --help` omits preset {}",
            p.name
        );
    }
}
