//! A simulation as a recording (`spec/recording-format.md`), so that `analyse` and the
//! diagnosis read simulated and measured data alike.

use super::run::Simulation;
use crate::recording::{Channel, ChannelKind, Recording, RecordingMeta, Run, RunShape};

/// The recording of `sim`: IAS of every node and the torque of every connection with an
/// element, in their own shafts; the sidecar says what was run.
pub fn to_recording(
    sim: &Simulation,
    run: Run,
    load: f64,
    strokes: u32,
    model_name: &str,
) -> Recording {
    let reference = sim.node_names[sim.reference_node].clone();
    let (speed_rpm, label) = match run.shape {
        RunShape::Steady { speed_rpm } | RunShape::LongRun { speed_rpm } => (
            Some(speed_rpm),
            format!("{model_name}: simulated steady run at {speed_rpm} rpm"),
        ),
        RunShape::Ramp { from_rpm, to_rpm } => (
            None,
            format!(
                "{model_name}: simulated ramp {from_rpm} → {to_rpm} rpm in {} s",
                run.duration_s
            ),
        ),
    };
    let mut meta = RecordingMeta::new(run.shape.sidecar_kind(), reference);
    meta.speed_rpm = speed_rpm;
    meta.load = load;
    meta.strokes = strokes;
    meta.label = Some(label);
    let mut channels: Vec<Channel> = sim
        .node_names
        .iter()
        .zip(&sim.speed_rpm)
        .map(|(node, values)| {
            Channel::new(ChannelKind::SpeedRpm { node: node.clone() }, values.clone())
        })
        .collect();
    channels.extend(sim.torque_nm.iter().map(|(c, values)| {
        Channel::new(
            ChannelKind::TorqueNm {
                connection: sim.connection_names[*c].clone(),
            },
            values.clone(),
        )
    }));
    Recording {
        time_s: sim.time_s.clone(),
        channels,
        meta,
    }
}
