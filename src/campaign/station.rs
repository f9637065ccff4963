//! A campaign's measuring stations: a zebra tape or an encoder with N lines per revolution
//! at each measured node (seed 001: optical probes on zebra tapes of 78 and 94 lines). The
//! artifacts such a sensor can have are effects, [`crate::effects::sensor`].

use super::CampaignError;
use crate::effects::sensor::coupling_side;
use crate::model::{Model, graph};

/// How a station's pulses are made.
#[derive(Debug, Clone, PartialEq)]
pub struct Station {
    /// The model node measured (its IAS in its own shaft).
    pub node: String,
    /// `"zebra"` or `"encoder"` (written to the sidecar's `[sensors.<node>]`).
    pub kind: String,
    /// Lines (pulses) per revolution.
    pub lines_per_rev: u32,
}

impl Station {
    /// Parses `NODE[:KIND[:LINES]]` (the CLI's `--station`); kind `zebra` (default 78
    /// lines, seed 001's engine-side tape) or `encoder` (default 360 lines).
    pub fn parse(text: &str) -> Result<Self, CampaignError> {
        let mut parts = text.split(':').map(str::trim);
        let node = parts.next().unwrap_or_default().to_string();
        let kind = parts.next().unwrap_or("zebra").to_string();
        let default_lines = match kind.as_str() {
            "zebra" => 78,
            "encoder" => 360,
            other => {
                return Err(CampaignError::Input(format!(
                    "--station `{text}`: sensor kind `{other}` (expected zebra or encoder)"
                )));
            }
        };
        let lines = match parts.next() {
            None => default_lines,
            Some(n) => n.parse::<u32>().ok().filter(|n| *n >= 4).ok_or_else(|| {
                CampaignError::Input(format!("--station `{text}`: lines `{n}` must be ≥ 4"))
            })?,
        };
        if node.is_empty() || parts.next().is_some() {
            return Err(CampaignError::Input(format!(
                "--station `{text}`: expected NODE[:zebra|encoder[:LINES]]"
            )));
        }
        Ok(Self {
            node,
            kind,
            lines_per_rev: lines,
        })
    }

    /// A bench's usual stations on `model`: the reference node (crank) with a 360-line
    /// encoder, and the engine side of the coupling ([`coupling_side`]) with a 78-line
    /// zebra tape (seed 001's n_c and n_es), when that is another node.
    pub fn defaults(model: &Model) -> Vec<Self> {
        let mut out = Vec::new();
        if let Some(r) = graph::reference_node(model) {
            out.push(Self {
                node: model.inertias[r].name.clone(),
                kind: "encoder".into(),
                lines_per_rev: 360,
            });
        }
        if let Some(node) = coupling_side(model)
            && model.node_index(&node).is_some()
            && out.iter().all(|s| s.node != node)
        {
            out.push(Self {
                node,
                kind: "zebra".into(),
                lines_per_rev: 78,
            });
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stations_parse() {
        let s = Station::parse("coupling_es").unwrap();
        assert_eq!((s.kind.as_str(), s.lines_per_rev), ("zebra", 78));
        let s = Station::parse("engine:encoder:720").unwrap();
        assert_eq!((s.kind.as_str(), s.lines_per_rev), ("encoder", 720));
        assert!(Station::parse("engine:laser").is_err());
        assert!(Station::parse("engine:zebra:2").is_err());
        assert!(Station::parse(":zebra").is_err());
    }
}
