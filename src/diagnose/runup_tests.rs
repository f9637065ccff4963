//! The segmented run-up forward model against one unsegmented time-domain run of the
//! whole ramp, on a driveline whose first mode is damped at 0.7 % of critical and is
//! crossed by order 2 just before the segments' boundary (issue 14, item 5).

use super::LabelledRecording;
use super::forward::predict;
use super::forward_runup::{observation_rpm, predict_segment, segments};
use super::observe::{Observed, RunShape, observe};
use super::settling::slowest_decay_s;
use crate::modal::{damped_modes, modes};
use crate::model::{Model, parse_model};
use crate::physics::{OperatingPoint, System};
use crate::recording::{Channel, ChannelKind, Recording, RecordingMeta, RunKind as RecKind};
use crate::transient::{RunOptions, simulate};

/// Load of the run-up: part load keeps the 0.7 % resonance's swing moderate.
const LOAD: f64 = 0.3;
/// Recorded rate, Hz.
const RATE_HZ: f64 = 2048.0;

/// The diagnosis bench with its rubber coupling replaced by a shaft of the coupling's
/// static stiffness and a light damper, and the brake's damping lowered: the first mode
/// (engine against brake, ~36 Hz) is then damped at about 0.7 %.
fn light_bench() -> Model {
    let text = include_str!("../../tests/data/diagnosis/none/model.toml");
    let start = text.find("[[connection]]\nkind = \"rubber\"").unwrap_or(0);
    let end = text[start..]
        .find("[engine]")
        .map_or(text.len(), |e| start + e);
    let shaft = "[[connection]]\nkind = \"shaft\"\nname = \"coupling\"\nfrom = \"coupling_es\"\n\
                 to = \"brake\"\nstiffness = 63400.0\ndamping = 4.7\n\n";
    let text = format!("{}{shaft}{}", &text[..start], &text[end..])
        .replace("damping = 5.0", "damping = 0.3")
        .replace(
            "inertia = 0.2\ndamping = 0.2",
            "inertia = 0.2\ndamping = 0.0",
        );
    parse_model(&text, "light.toml").unwrap()
}

/// The first mode's frequency (Hz) and damping ratio at [`LOAD`].
fn first_mode(model: &Model) -> (f64, f64) {
    let point = OperatingPoint {
        load: LOAD,
        temperature_c: None,
    };
    let system = System::new(model, point).unwrap();
    let m = damped_modes(&system, &modes(&system).unwrap())[0];
    (m.frequency_hz, m.damping_ratio)
}

/// One run of the whole ramp (settled at `from_rpm` first) as the bench's recording.
fn truth(model: &Model, from_rpm: f64, to_rpm: f64, duration_s: f64) -> LabelledRecording {
    let run_spec = crate::recording::Run::ramp(from_rpm, to_rpm, duration_s);
    let options = RunOptions {
        load: LOAD,
        rate_hz: RATE_HZ,
        ..RunOptions::default()
    };
    let sim = simulate(model, run_spec, options, &mut |_| true).unwrap();
    assert!(sim.settling.converged, "{:?}", sim.settling);
    let mut meta = RecordingMeta::new(RecKind::RunUp, "engine");
    meta.load = LOAD;
    let channels = ["engine", "coupling_es"]
        .iter()
        .map(|node| {
            let i = sim.node_names.iter().position(|n| n == node).unwrap();
            Channel {
                column: format!("{node}_rpm"),
                kind: ChannelKind::SpeedRpm {
                    node: (*node).into(),
                },
                values: sim.speed_rpm[i].clone(),
            }
        })
        .collect();
    LabelledRecording {
        label: "run-up".into(),
        recording: Recording {
            time_s: sim.time_s.clone(),
            channels,
            meta,
        },
    }
}

/// Largest difference between simulated and measured over the bins of `order` at the
/// crank, relative to the track's peak; and that peak.
fn worst(observed: &Observed, simulated: &[f64], order: f64) -> (f64, f64) {
    let track: Vec<(f64, f64)> = observed
        .observations
        .iter()
        .zip(simulated)
        .filter(|(o, _)| o.station == "engine" && (o.order - order).abs() < 1e-9)
        .map(|(o, s)| (o.measured_rpm, *s))
        .collect();
    let peak = track.iter().fold(0.0_f64, |m, (a, _)| m.max(*a));
    let diff = track.iter().fold(0.0_f64, |m, (a, s)| m.max((a - s).abs()));
    (diff / peak, peak)
}

/// The forward model of `observed`'s run-up (run 0) in one segment, not cut.
fn one_segment(model: &Model, observed: &Observed) -> Vec<f64> {
    let decay = slowest_decay_s(model, LOAD);
    let whole = segments(observed, 0, 1, decay);
    assert_eq!(whole.len(), 1);
    let sums = predict_segment(model, observed, whole[0], 8.0).unwrap();
    observed
        .observations
        .iter()
        .map(|o| observation_rpm(&sums, o))
        .collect()
}

/// The run-up is cut into two segments (on two threads); the second starts 0.5 s after
/// order 2 crossed the 0.7 % mode. Its lead-in (5.3 decay times, 3.4 s) starts it below
/// the crossing, so it passes the resonance transiently like the whole run: every bin of
/// order 2 at the crank agrees with the unsegmented run within 2 % of the track's peak
/// (measured: 1.5 %), and with the forward model run as one segment within 1 % (measured:
/// 0.4 %). Tolerances: the forward model's integration tolerance is 10 times looser
/// (1e-4) than the truth's, and its ramp is the straight line fitted to the measured
/// window speeds (a few rpm off), which moves a 0.7 % resonance's steep flank between
/// bins; segmented and whole share both, so only the cut is left between them.
#[test]
fn segmented_run_up_passes_a_light_mode_like_one_run() {
    let model = light_bench();
    let (f1, zeta) = first_mode(&model);
    assert!(
        (0.005..0.01).contains(&zeta),
        "first mode {f1} Hz, ζ {zeta}"
    );
    assert!(slowest_decay_s(&model, LOAD).is_some());
    let crossing_rpm = 60.0 * f1 / 2.0;
    let (from, to, duration) = (0.7 * crossing_rpm, 1.36 * crossing_rpm, 12.0);
    let rec = truth(&model, from, to, duration);
    let observed = observe(&[rec], 8.0).unwrap();
    assert!(matches!(observed.runs[0].regime, RunShape::Ramp { .. }));
    // The run's own speed loop lags through the resonance, 1.5 % from its line: below
    // `FOLLOW_ABOVE`, so the forward model runs the line (followed, it lags twice).
    let r = &observed.runs[0];
    let m = crate::transient::MeasuredSpeed::from_windows(&r.window_times_s, &r.window_speeds_rpm)
        .expect("12 s of windows");
    assert!((0.01..0.02).contains(&m.departure_from_line()) && !m.departs());
    let simulated = predict(&model, &observed, 8.0, 2, None).unwrap();
    let (diff, peak) = worst(&observed, &simulated, 2.0);
    assert!(peak > 10.0, "the crossing must show: peak {peak} rpm");
    assert!(diff < 0.02, "order 2: worst bin off by {diff} of the peak");
    // The same numbers on one thread or three, bit for bit: the cut is the forward
    // model's, and the segments' sums add up in one order.
    for threads in [1, 3] {
        assert_eq!(
            predict(&model, &observed, 8.0, threads, None).unwrap(),
            simulated
        );
    }
    // Against the same forward model in one segment: only the cut differs.
    let whole = one_segment(&model, &observed);
    let cut = simulated
        .iter()
        .zip(&whole)
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(cut < 0.01 * peak, "segmented vs whole: {cut} rpm");
    // The first bin carries no start transient: the truth was settled at its start speed
    // (converged to 1e-4), and the forward model's first bin (order 2, crank, 1.39 rpm)
    // agrees with it within 4 % of its own value. The bin lies on the flank of the
    // crank's order-2 antiresonance near 800 rpm (`response`: 2.87 rpm at 752 rpm, 0.37
    // at 800), where the amplitude falls by ~3.8 % per rpm, so the fitted ramp's offset of
    // under 1 rpm moves it by that much (measured 2.5 %); a start transient of the 0.7 %
    // damped mode would be tens of percent. (Before the governor stopped damping the
    // vibration, that flank was flattened: 3.05 against 3.07 rpm.)
    let first = observed
        .observations
        .iter()
        .position(|o| o.station == "engine" && o.order == 2.0 && o.part == 0)
        .unwrap();
    let (m, s) = (observed.observations[first].measured_rpm, simulated[first]);
    assert!(
        (m - s).abs() < 0.04 * m,
        "first bin: {m} measured, {s} simulated"
    );
}
