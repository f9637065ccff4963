//! The artifacts of a bench's sensors (a zebra tape or an encoder with N lines per
//! revolution at each measured station, seed 001: optical probes on zebra tapes of 78 and
//! 94 lines): the ones a real one has — the butt joint of a zebra tape (one line interval too long
//! or short, compensated on real benches by Janssens et al.'s algorithm, seed 001 ref.
//! [10]) and a once-per-revolution pitch error (an eccentric tape or encoder disc).

use super::EffectError;
use super::effect::{EffectSpec, Params};
use super::truth::Applied;
use crate::model::{Model, graph};
use std::f64::consts::TAU;

/// The engine-side node of the coupling: the `from` node of the first rubber stage, or of
/// the softest shaft when there is none (a coupling modelled as spring and damper).
pub fn coupling_side(model: &Model) -> Option<String> {
    use crate::model::ConnectionKind;
    let rubber = model
        .connections
        .iter()
        .find(|c| matches!(c.kind, ConnectionKind::Rubber(_)));
    let softest = || {
        model
            .connections
            .iter()
            .filter_map(|c| match &c.kind {
                ConnectionKind::Shaft(s) => Some((c, s.stiffness_nm_per_rad)),
                _ => None,
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(c, _)| c)
    };
    rubber
        .or_else(softest)
        .map(|c| c.from.clone())
        .filter(|n| model.node_index(n).is_some())
}

/// A sensor artifact at one station.
#[derive(Debug, Clone, PartialEq)]
pub enum SensorArtifact {
    /// The zebra tape's butt joint: the line interval across the joint is
    /// `(1 + joint_fraction)` nominal pitches, the others share the rest evenly; the IAS
    /// processing assumes equal pitches, so the speed reads low across the joint once per
    /// revolution (all integer orders of that shaft, amplitude ∝ speed).
    TapeJoint {
        /// Node of the station.
        station: String,
        /// Excess length of the joint interval, in pitches (−0.9 … 5).
        joint_fraction: f64,
    },
    /// Line `k` sits at `k·2π/N + ε·sin(k·2π/N)`: an eccentric tape or disc, order 1 of
    /// that shaft with amplitude `ε·n`.
    PitchError {
        /// Node of the station.
        station: String,
        /// ε, degrees.
        error_deg: f64,
    },
}

impl SensorArtifact {
    /// The node of the station it sits on.
    pub fn station(&self) -> &str {
        match self {
            Self::TapeJoint { station, .. } | Self::PitchError { station, .. } => station,
        }
    }

    /// Parses `tape_joint:NODE:FRACTION` or `pitch_error:NODE:DEG` (the CLI's
    /// `--sensor-artifact`).
    pub fn parse(text: &str) -> Result<Self, EffectError> {
        let parts: Vec<&str> = text.split(':').map(str::trim).collect();
        let bad = |m: &str| EffectError::Input(format!("--sensor-artifact `{text}`: {m}"));
        let [kind, station, size] = parts.as_slice() else {
            return Err(bad(
                "expected tape_joint:NODE:FRACTION or pitch_error:NODE:DEG",
            ));
        };
        let size: f64 = size.parse().map_err(|_| bad("the size is not a number"))?;
        let artifact = match *kind {
            "tape_joint" => Self::TapeJoint {
                station: station.to_string(),
                joint_fraction: size,
            },
            "pitch_error" => Self::PitchError {
                station: station.to_string(),
                error_deg: size,
            },
            _ => return Err(bad("kind must be tape_joint or pitch_error")),
        };
        artifact.check().map_err(|m| bad(&m))?;
        Ok(artifact)
    }

    fn check(&self) -> Result<(), String> {
        match self {
            Self::TapeJoint { joint_fraction, .. } if !(-0.9..=5.0).contains(joint_fraction) => {
                Err(format!(
                    "joint fraction {joint_fraction} is outside −0.9 … 5"
                ))
            }
            Self::PitchError { error_deg, .. } if !(-5.0..=5.0).contains(error_deg) => {
                Err(format!("pitch error {error_deg}° is outside ±5°"))
            }
            _ => Ok(()),
        }
    }

    /// Effect `sensor_artifact`: `kind` (`tape_joint`, default, or `pitch_error`),
    /// `station` (default the engine side of the coupling, where a campaign's default stations puts
    /// a zebra tape; else the reference node) and `joint_fraction` (default 0.2) or
    /// `error_deg` (default 0.05).
    pub(crate) fn from_spec(
        spec: &EffectSpec,
        user: &Model,
    ) -> Result<(Self, Applied), EffectError> {
        let mut p = Params::new(spec, &["kind", "station", "joint_fraction", "error_deg"])?;
        let kind = p.text("kind", Some("tape_joint".into()))?;
        let reference = graph::reference_node(user).map(|r| user.inertias[r].name.clone());
        let station = p.text("station", coupling_side(user).or(reference))?;
        if user.node_index(&station).is_none() {
            return Err(p.bad("station", format!("`{station}` is no node of the model")));
        }
        let (artifact, summary) = match kind.as_str() {
            "tape_joint" => {
                if spec.params.contains_key("error_deg") {
                    return Err(p.bad("error_deg", "belongs to kind pitch_error"));
                }
                let f = p.number("joint_fraction", 0.2, -0.9, 5.0)?;
                (
                    Self::TapeJoint {
                        station: station.clone(),
                        joint_fraction: f,
                    },
                    format!(
                        "the zebra tape at `{station}` has a butt joint {:+.1} % of a line \
                         pitch off: the IAS there dips once per revolution",
                        100.0 * f
                    ),
                )
            }
            "pitch_error" => {
                if spec.params.contains_key("joint_fraction") {
                    return Err(p.bad("joint_fraction", "belongs to kind tape_joint"));
                }
                let e = p.number("error_deg", 0.05, -5.0, 5.0)?;
                (
                    Self::PitchError {
                        station: station.clone(),
                        error_deg: e,
                    },
                    format!(
                        "the lines at `{station}` are off by {e}°·sin(angle) (eccentric tape \
                         or disc): order 1 of that shaft, ∝ speed"
                    ),
                )
            }
            other => {
                return Err(p.bad(
                    "kind",
                    format!("`{other}`: expected tape_joint or pitch_error"),
                ));
            }
        };
        Ok((artifact, (p.resolved, summary)))
    }
}

/// The angles of the `lines` lines of one revolution (rad, line 0 at 0, increasing,
/// below 2π) with `artifacts` (those of this station) applied.
pub fn line_angles(lines: u32, artifacts: &[&SensorArtifact]) -> Vec<f64> {
    let n = lines as usize;
    let pitch = TAU / n as f64;
    let mut angles: Vec<f64> = (0..n).map(|k| k as f64 * pitch).collect();
    for a in artifacts {
        match a {
            SensorArtifact::TapeJoint { joint_fraction, .. } => {
                let others = (TAU - pitch * (1.0 + joint_fraction)) / (n - 1) as f64;
                for (k, x) in angles.iter_mut().enumerate() {
                    *x = k as f64 * others;
                }
            }
            SensorArtifact::PitchError { error_deg, .. } => {
                let e = error_deg.to_radians();
                for (k, x) in angles.iter_mut().enumerate() {
                    *x += e * (k as f64 * pitch).sin();
                }
            }
        }
    }
    angles
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tape_joint_keeps_one_revolution() {
        let a = SensorArtifact::parse("tape_joint:x:0.5").unwrap();
        let angles = line_angles(10, &[&a]);
        let pitch = TAU / 10.0;
        // The joint interval (last line to the next revolution's first) is 1.5 pitches.
        assert!((TAU - angles[9] - 1.5 * pitch).abs() < 1e-12);
        let others = angles[1] - angles[0];
        assert!((9.0 * others + 1.5 * pitch - TAU).abs() < 1e-12);
        assert!(SensorArtifact::parse("tape_joint:x").is_err());
        assert!(SensorArtifact::parse("tape_joint:x:9").is_err());
        assert!(SensorArtifact::parse("wobble:x:1").is_err());
    }
}
