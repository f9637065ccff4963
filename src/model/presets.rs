//! Presets shipped inside the binary, so that `torsim` opens and checks them from
//! anywhere. The files in `presets/` are the same text.

/// A preset: its file stem and its model-file text.
#[derive(Debug, Clone, Copy)]
pub struct Preset {
    /// File stem, e.g. `cng-genset`.
    pub name: &'static str,
    /// The model file.
    pub text: &'static str,
}

/// Every shipped preset, the default first.
pub const PRESETS: &[Preset] = &[
    Preset {
        name: "cng-genset",
        text: include_str!("../../presets/cng-genset.toml"),
    },
    Preset {
        name: "diagnosis-bench",
        text: include_str!("../../presets/diagnosis-bench.toml"),
    },
    Preset {
        name: "test-rig-45sh",
        text: include_str!("../../presets/test-rig-45sh.toml"),
    },
    Preset {
        name: "test-rig-60sh",
        text: include_str!("../../presets/test-rig-60sh.toml"),
    },
    Preset {
        name: "test-rig-70sh",
        text: include_str!("../../presets/test-rig-70sh.toml"),
    },
    Preset {
        name: "test-rig-mod1",
        text: include_str!("../../presets/test-rig-mod1.toml"),
    },
    Preset {
        name: "test-rig-mod2",
        text: include_str!("../../presets/test-rig-mod2.toml"),
    },
    Preset {
        name: "test-rig-mod3",
        text: include_str!("../../presets/test-rig-mod3.toml"),
    },
];

/// The preset the GUI opens on.
pub const DEFAULT_PRESET: &str = "cng-genset";

/// The preset of this name, if shipped.
pub fn preset(name: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.name == name)
}
