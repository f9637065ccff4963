//! Time-domain benchmarks (issue 3): a linear 3-DOF run, 20 s at 10240 Hz output, and the
//! cng-genset preset run up 400 → 2000 rpm in 20 s. Each includes settling at the start
//! speed. `cargo bench --bench transient`.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;
use torsim::model::{parse_model, presets};
use torsim::recording::Run;
use torsim::transient::{RunOptions, simulate};

const LINEAR_3DOF: &str = r#"format = 1
name = "linear three-DOF (seed 001 eq. 6 form, viscous)"
[[inertia]]
name = "engine"
inertia = 0.5
[[inertia]]
name = "hub"
inertia = 0.02
[[inertia]]
name = "flange"
inertia = 0.01
[[connection]]
kind = "shaft"
from = "engine"
to = "hub"
stiffness = 2.0e5
damping = 2.0
[[connection]]
kind = "shaft"
from = "hub"
to = "flange"
stiffness = 1.0e4
damping = 1.5
[[connection]]
kind = "shaft"
from = "flange"
to = "ground"
stiffness = 1.0e4
damping = 1.5
[[harmonic]]
at = "engine"
order = 1.0
amplitude = 100.0
phase_deg = 0.0
[[harmonic]]
at = "engine"
order = 2.0
amplitude = 40.0
phase_deg = 0.0
"#;

fn runs(c: &mut Criterion) {
    let mut group = c.benchmark_group("transient");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(8));
    let linear = parse_model(LINEAR_3DOF, "linear.toml").expect("model");
    group.bench_function("linear_3dof_20s_10240hz", |b| {
        b.iter(|| {
            let kind = Run::steady(3000.0, 20.0);
            black_box(simulate(&linear, kind, RunOptions::default(), &mut |_| true).expect("run"))
        })
    });
    let preset = presets::preset("cng-genset").expect("preset");
    let cng = parse_model(preset.text, "cng-genset.toml").expect("model");
    group.bench_function("cng_genset_runup_400_2000_20s", |b| {
        b.iter(|| {
            let kind = Run::ramp(400.0, 2000.0, 20.0);
            black_box(simulate(&cng, kind, RunOptions::default(), &mut |_| true).expect("run"))
        })
    });
    group.finish();
}

criterion_group!(benches, runs);
criterion_main!(benches);
