//! Presets shipped inside the binary, so that `torsim` opens and checks them from
//! anywhere. The files in `presets/` are the same text.

/// A preset: its file stem, what it is for in one line, and its model-file text.
#[derive(Debug, Clone, Copy)]
pub struct Preset {
    /// File stem, e.g. `cng-genset`.
    pub name: &'static str,
    /// What it is, for a menu's hover text (the file's `description` says more).
    pub summary: &'static str,
    /// The model file.
    pub text: &'static str,
}

/// Every shipped preset, the default first.
pub const PRESETS: &[Preset] = &[
    Preset {
        name: "cng-genset",
        summary: "seed 000's six-cylinder CNG genset with its eight-element rubber coupling",
        text: include_str!("../../presets/cng-genset.toml"),
    },
    Preset {
        name: "diagnosis-bench",
        summary: "four-cylinder bench with a two-stage coupling, gearbox and brake: the diagnosis' reference",
        text: include_str!("../../presets/diagnosis-bench.toml"),
    },
    Preset {
        name: "test-rig-45sh",
        summary: "seed 001's test rig with the 45 Sh coupling",
        text: include_str!("../../presets/test-rig-45sh.toml"),
    },
    Preset {
        name: "test-rig-60sh",
        summary: "seed 001's test rig with the 60 Sh coupling",
        text: include_str!("../../presets/test-rig-60sh.toml"),
    },
    Preset {
        name: "test-rig-70sh",
        summary: "seed 001's test rig with the 70 Sh coupling, calibrated to its Tables 8(c) and 9",
        text: include_str!("../../presets/test-rig-70sh.toml"),
    },
    Preset {
        name: "test-rig-mod1",
        summary: "seed 001's MOD 1 (§3.4) of the 70 Sh rig",
        text: include_str!("../../presets/test-rig-mod1.toml"),
    },
    Preset {
        name: "test-rig-mod2",
        summary: "seed 001's MOD 2 (§3.4) of the 70 Sh rig",
        text: include_str!("../../presets/test-rig-mod2.toml"),
    },
    Preset {
        name: "test-rig-mod3",
        summary: "seed 001's MOD 3 (§3.4) of the 70 Sh rig",
        text: include_str!("../../presets/test-rig-mod3.toml"),
    },
    Preset {
        name: "genset-20dof",
        summary: "20 inertias: six-cylinder crank with damper, two-stage coupling, gearbox, generator",
        text: include_str!("../../presets/genset-20dof.toml"),
    },
    Preset {
        name: "two-inertia",
        summary: "teaching: two inertias on a shaft, one mode in closed form (File → New starts here)",
        text: include_str!("../../presets/two-inertia.toml"),
    },
    Preset {
        name: "three-inertia",
        summary: "teaching: engine, flywheel and load, two modes in closed form",
        text: include_str!("../../presets/three-inertia.toml"),
    },
];

/// The preset the GUI opens on.
pub const DEFAULT_PRESET: &str = "cng-genset";

/// The preset of this name, if shipped.
pub fn preset(name: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.name == name)
}
