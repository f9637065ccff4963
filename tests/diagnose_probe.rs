use std::path::Path;
use torsim::diagnose::{LabelledRecording, forward, observe, residual, sensor, spread};
use torsim::physics::{OperatingPoint, System};

fn load(dir: &str) -> (torsim::model::Model, Vec<LabelledRecording>) {
    let d = Path::new(dir);
    let text = std::fs::read_to_string(d.join("model.toml")).unwrap();
    let model = torsim::model::parse_model(&text, "model.toml").unwrap();
    let mut recs = Vec::new();
    let mut names: Vec<_> = std::fs::read_dir(d)
        .unwrap()
        .filter_map(|e| {
            let p = e.unwrap().path();
            (p.extension().is_some_and(|x| x == "csv")).then_some(p)
        })
        .collect();
    names.sort();
    for p in names {
        let r = torsim::recording::read_recording(
            &p,
            Some(
                &model
                    .inertias
                    .iter()
                    .map(|n| n.name.clone())
                    .collect::<Vec<_>>(),
            ),
        )
        .unwrap();
        let label = r.meta.label.clone().unwrap_or_default();
        recs.push(LabelledRecording {
            label,
            recording: r,
        });
    }
    (model, recs)
}

#[test]
#[ignore]
fn probe() {
    let case = std::env::var("CASE").unwrap_or("none".into());
    let (model, recs) = load(&format!("tests/data/diagnosis/{case}"));
    let t = std::time::Instant::now();
    let obs = observe::observe(&recs, 8.0).unwrap();
    eprintln!(
        "observe {:.2}s, {} obs",
        t.elapsed().as_secs_f64(),
        obs.observations.len()
    );
    let t = std::time::Instant::now();
    let mut pred = forward::predict(&model, &obs, 8.0, 2).unwrap();
    eprintln!("predict {:.2}s", t.elapsed().as_secs_f64());
    let sys = System::new(&model, OperatingPoint::default()).unwrap();
    let ratios: Vec<(String, f64)> = sys
        .node_names
        .iter()
        .cloned()
        .zip(sys.speed_ratio.iter().copied())
        .collect();
    sensor::measure(&obs, &ratios, None, &mut pred);
    let f = spread::spread_factors(&model, &obs);
    for (p, f) in pred.iter_mut().zip(&f) {
        *p *= f;
    }
    let zs = residual::z_scores(&obs, &pred);
    for (r, run) in obs.runs.iter().enumerate() {
        let mut chi = 0.0;
        let mut n = 0;
        let mut worst: Vec<(f64, String)> = Vec::new();
        for ((o, p), z) in obs
            .observations
            .iter()
            .zip(&pred)
            .zip(&zs)
            .filter(|((o, _), _)| o.run == r)
        {
            let z = *z;
            chi += z * z;
            n += 1;
            worst.push((
                z.abs(),
                format!(
                    "{} q{} part{} {:.0}rpm meas {:.4} sim {:.4} sig {:.4} z {:.1}",
                    o.station, o.order, o.part, o.speed_rpm, o.measured_rpm, p, o.sigma_rpm, z
                ),
            ));
        }
        worst.sort_by(|a, b| b.0.total_cmp(&a.0));
        eprintln!(
            "{} {:?}: chi2/N {:.2} (N {})",
            run.label,
            run.regime,
            chi / n.max(1) as f64,
            n
        );
        for w in worst.iter().take(4) {
            eprintln!("    {}", w.1);
        }
    }
}

#[test]
#[ignore]
fn probe_diagnose() {
    let case = std::env::var("CASE").unwrap_or("none".into());
    let (model, recs) = load(&format!("tests/data/diagnosis/{case}"));
    let t = std::time::Instant::now();
    let report = torsim::diagnose::diagnose(&model, &recs, &Default::default(), &mut |f, s| {
        eprintln!("{:5.2} {:.1}s {s}", f, t.elapsed().as_secs_f64());
        true
    })
    .unwrap();
    eprintln!(
        "VERDICT {} {:?} conf {:.2}\n{}",
        report.verdict.effect,
        report.verdict.parameters,
        report.verdict.confidence,
        report.verdict.explanation
    );
    eprintln!(
        "fit before {:.2} after {:.2}",
        report.fit.before, report.fit.after
    );
    for c in &report.candidates {
        if c.effect == "parameter_error" {
            eprintln!("{:?}", c.parameters);
        }
    }
    for c in &report.candidates {
        eprintln!(
            "  {:32} score {:8.3} fit {:8.3} ho {:8.3} {}",
            c.effect, c.score, c.residual_fitted, c.residual_after, c.signature
        );
    }
}
