//! Order-analysis benchmark: `signal::analyse` of a simulated run-up, the analysis the
//! diagnosis applies to every forward run-up it simulates (a fifth of its time, measured
//! with `perf` on benchtruth seed 2010: the order tracks, the angle resampling and its
//! interpolation taps). The recording, cng-genset run up 400 → 2000 rpm in 20 s (10
//! nodes, 9 connections), is simulated once outside the timing. `cargo bench --bench
//! signal`.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;
use torsim::model::{parse_model, presets};
use torsim::recording::Run;
use torsim::signal::analyse;
use torsim::transient::{RunOptions, simulate, to_recording};

fn analysis(c: &mut Criterion) {
    let preset = presets::preset("cng-genset").expect("preset");
    let model = parse_model(preset.text, "cng-genset.toml").expect("model");
    let run = Run::ramp(400.0, 2000.0, 20.0);
    let sim = simulate(&model, run, RunOptions::default(), &mut |_| true).expect("run");
    let recording = to_recording(&sim, run, 1.0, 4, "cng-genset");
    let mut group = c.benchmark_group("signal");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(8));
    group.bench_function("analyse_cng_genset_runup_20s", |b| {
        b.iter(|| black_box(analyse(&recording).expect("analysis")))
    });
    group.finish();
}

criterion_group!(benches, analysis);
criterion_main!(benches);
