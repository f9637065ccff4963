//! The observed run: its chunks, concatenated, are the final simulation sample for sample
//! (bit for bit, not within a tolerance: they are copies of the same numbers), the
//! instantaneous power averages to the reported power loss, and `false` cancels.

use torsim::model::{ConnectionKind, Thermal, parse_model, presets};
use torsim::recording::Run;
use torsim::transient::{Chunk, Event, RunOptions, TransientError, simulate, simulate_observed};

/// The 70 Sh test rig with self-heating on its rubber stages, so every output (speeds,
/// torques, power, temperatures) is in the chunks.
fn rig_with_thermal_rubber() -> torsim::model::Model {
    let p = presets::preset("test-rig-70sh").expect("preset");
    let mut model = parse_model(p.text, "test-rig-70sh").expect("model");
    for c in &mut model.connections {
        if let ConnectionKind::Rubber(r) = &mut c.kind {
            r.thermal = Some(Thermal {
                capacity_j_per_k: 40.0,
                conductance_w_per_k: 8.0,
                ambient_c: 25.0,
            });
        }
    }
    model
}

const RAMP: Run = Run::ramp(1500.0, 3000.0, 0.5);

fn options() -> RunOptions {
    RunOptions {
        rate_hz: 4096.0,
        max_settle_s: 1.0,
        ..RunOptions::default()
    }
}

/// Appends `b` to `a`, series by series.
fn append(a: &mut [(usize, Vec<f64>)], b: &[(usize, Vec<f64>)]) {
    assert_eq!(a.len(), b.len());
    for ((ca, va), (cb, vb)) in a.iter_mut().zip(b) {
        assert_eq!(ca, cb, "same connection order in every chunk");
        va.extend_from_slice(vb);
    }
}

#[test]
fn chunks_concatenate_to_the_final_simulation() {
    let model = rig_with_thermal_rubber();
    let mut chunks: Vec<Chunk> = Vec::new();
    let mut progress = Vec::new();
    let sim = simulate_observed(&model, RAMP, options(), &mut |event| {
        match event {
            Event::Progress(f) => progress.push(f),
            Event::Chunk(c) => chunks.push(c),
        }
        true
    })
    .expect("run");
    // 0.5 s at 4096 Hz: 2048 samples, reported every 0.5 % (10 or 11 samples).
    assert_eq!(sim.time_s.len(), 2048);
    assert!(chunks.len() >= 150, "{} chunks", chunks.len());
    assert!(progress.windows(2).all(|w| w[1] >= w[0]));
    assert_eq!(progress.last().copied(), Some(1.0));
    let first = chunks[0].clone();
    assert_eq!(first.first_sample, 0);
    let mut whole = first;
    for c in &chunks[1..] {
        assert_eq!(c.first_sample, whole.len(), "chunks are consecutive");
        assert_eq!(c.total_samples, 2048);
        assert!(!c.is_empty());
        whole.time_s.extend_from_slice(&c.time_s);
        for (a, b) in whole.speed_rpm.iter_mut().zip(&c.speed_rpm) {
            a.extend_from_slice(b);
        }
        append(&mut whole.torque_nm, &c.torque_nm);
        append(&mut whole.power_w, &c.power_w);
        append(&mut whole.temperature_c, &c.temperature_c);
    }
    assert_eq!(whole.time_s, sim.time_s);
    assert_eq!(whole.speed_rpm, sim.speed_rpm);
    assert_eq!(whole.torque_nm, sim.torque_nm);
    assert_eq!(whole.temperature_c, sim.temperature_c);
    assert_eq!(
        whole.temperature_c.len(),
        2,
        "two rubber stages with thermal"
    );
    // The power loss is the mean of the instantaneous power, summed in the same order.
    for ((c, series), (c_sim, mean)) in whole.power_w.iter().zip(&sim.power_loss_w) {
        assert_eq!(c, c_sim);
        let n = series.len() as f64;
        let sum = series.iter().fold(0.0, |s, p| s + p / n);
        assert_eq!(sum, *mean, "connection {c}");
    }
    assert!(sim.power_loss_w.iter().any(|(_, w)| *w > 0.0));
    // `simulate` is the same run without the chunks.
    let plain = simulate(&model, RAMP, options(), &mut |_| true).expect("run");
    assert_eq!(plain.speed_rpm, sim.speed_rpm);
    assert_eq!(plain.power_loss_w, sim.power_loss_w);
}

#[test]
fn refusing_a_chunk_cancels_the_run() {
    let model = rig_with_thermal_rubber();
    let mut chunks = 0;
    let result = simulate_observed(&model, RAMP, options(), &mut |event| match event {
        Event::Progress(_) => true,
        Event::Chunk(_) => {
            chunks += 1;
            chunks < 3
        }
    });
    assert!(
        matches!(result, Err(TransientError::Cancelled { .. })),
        "{result:?}"
    );
    assert_eq!(chunks, 3, "nothing is reported after the refusal");
}
