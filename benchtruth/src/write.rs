//! Writes a case as a test engineer hands it over: the user's model (model-format.md),
//! the recordings (recording-format.md: CSV with `time_s` to the microsecond and a TOML
//! sidecar), and `truth.toml`, which only the scorer reads (`model_file.rs` and
//! `truth_file.rs` write those two). TOML is written by hand.

use crate::draw::{Case, stream};
use crate::effects::{Effect, SensorLaw};
use crate::exercise::{Exercise, Meter};
use crate::order_meter::{OrderMeter, meter_for};
use crate::rng::Rng;
use crate::sim;
use crate::visibility::Visibility;
use crate::{model_file, truth_file};
use std::f64::consts::TAU;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// How far, as a fraction of its mean speed, a node's speed may swing before the draw is
/// no bench (0.75: every shaft stays within 25–175 % of its mean speed). Measured IAS
/// swings of running engines are a few per cent to some tens of per cent at idle; a
/// crank that nearly stops once a revolution would stall, and a reader's over-range test
/// (three times the running median over a revolution) would rightly refuse its samples.
pub const MAX_SWING: f64 = 0.75;

/// Errors of the writer.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    #[error("{0}")]
    Draw(String),
    /// The drawn truth is one no bench could run (it diverged, or a node turned
    /// backwards): [`crate::redraw::write_case`] draws the seed again.
    #[error("{0}")]
    Unusable(String),
    #[error("writing {path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}

/// The files of a written case.
#[derive(Debug, Clone)]
pub struct CaseFiles {
    pub model: PathBuf,
    pub recordings: Vec<PathBuf>,
    pub truth: PathBuf,
    /// The truth's class (spec effect name), form and place for scoring.
    pub class: String,
    pub form: String,
    pub place: Option<(String, Vec<String>)>,
    /// What each recording exercised of the effect (file stem, measure), for the classes
    /// [`crate::exercise`] measures.
    pub exercise: Vec<(String, Exercise)>,
    /// Which draw of the seed was written ([`crate::draw::Case::attempt`]).
    pub draw: u64,
    /// How plainly the campaign shows the effect ([`crate::visibility`]); `None` for a
    /// control.
    pub visibility: Option<Visibility>,
}

fn put(path: &Path, text: &str) -> Result<(), WriteError> {
    std::fs::write(path, text).map_err(|source| WriteError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// The IAS a station reads: the shaft speed times the sensor's angle-error slope.
fn measured_rpm(law: Option<&SensorLaw>, theta: f64, omega: f64, sample_s: f64) -> f64 {
    let rpm = omega * 60.0 / TAU;
    let pulse = |fraction: f64, lines: u32, at: f64| {
        // One pitch reads `fraction` long: spread over max(pitch, one sample's angle),
        // the other pitches compressed so the mean speed stays right.
        let pitch = TAU / lines as f64;
        let width = pitch.max(omega.abs() * sample_s);
        let a = (theta - at).rem_euclid(TAU);
        let extra = fraction * pitch;
        if a < width {
            1.0 / (1.0 + extra / width)
        } else {
            1.0 + extra / TAU
        }
    };
    let factor = match law {
        None => 1.0,
        Some(SensorLaw::Eccentricity { e_rad, phase_rad }) => {
            1.0 + e_rad * (theta + phase_rad).cos()
        }
        Some(SensorLaw::TapeJoint {
            fraction,
            lines,
            angle_rad,
        }) => pulse(*fraction, *lines, *angle_rad),
        Some(SensorLaw::MissingTooth {
            fraction,
            lines,
            angle_rad,
        }) => pulse(*fraction, *lines, *angle_rad),
    };
    rpm * factor
}

/// One recording simulated, not yet written: CSV and sidecar texts, and what it
/// exercised of the effect.
pub(crate) struct Simulated {
    stem: String,
    csv: String,
    sidecar: String,
    exercise: Option<Exercise>,
    /// The noise-free order sums of the recording ([`crate::visibility`]).
    pub(crate) orders: OrderMeter,
}

/// Simulates one recording (CSV + sidecar text); nothing is written, so a case that fails
/// in any recording leaves its directory as it was.
fn simulate_recording(case: &Case, idx: usize) -> Result<Simulated, WriteError> {
    let rec = &case.campaign.recordings[idx];
    let c = &case.campaign;
    let plant = sim::plant_for(case, rec);
    let mut rng = Rng::new(case.seed, stream(100 + idx as u64, case.attempt));
    let artifact = match &case.effect {
        Effect::SensorArtifact { station, law } => Some((*station, *law)),
        _ => None,
    };
    let names: Vec<&str> = c
        .stations
        .iter()
        .map(|s| case.truth.nodes[s.node].name.as_str())
        .collect();
    let mut csv = String::from("time_s");
    for n in &names {
        let _ = write!(csv, ",{n}_rpm");
    }
    csv.push('\n');
    let sample_s = 1.0 / c.rate_hz;
    let n_nodes = plant.n;
    // The first time at which the truth is no longer finite: a bench never writes NaN
    // (a diverged truth is the bench's failure, reported as such, not torsim's).
    let mut diverged_s: Option<f64> = None;
    // The first time a node's speed leaves 1 ± MAX_SWING of its mean: an engine stalls
    // or races there, and a shaft that nearly stops or reverses within a revolution
    // through a resonance is no bench either (seed 100585's run-up reached −56 rpm at
    // the crank; development seed 2117's brake went below 0 rpm; published 101326's crank
    // swung between 1.6 and 1770 rpm at a mean of 900 rpm in its run-up).
    let mut reversed: Option<(f64, usize, f64)> = None;
    let ratios = case.truth.speed_ratios();
    let mut meter = Meter::for_case(case);
    let mut orders = meter_for(case, idx);
    let mut clean = vec![0.0; c.stations.len()];
    let crank = case.truth.engine.node;
    sim::run(&case.truth, &plant, c.rate_hz, |t, y| {
        if let Some(m) = meter.as_mut() {
            m.add(&y[..n_nodes]);
        }
        if reversed.is_none() {
            let (mean_rad_s, _) = plant.profile.at(plant.profile.settle_s + t);
            reversed = (0..n_nodes)
                .map(|i| (i, y[n_nodes + i] / (mean_rad_s * ratios[i])))
                .find(|(_, f)| (*f - 1.0).abs() > MAX_SWING)
                .map(|(i, f)| (t, i, f));
        }
        let _ = write!(csv, "{:.6}", c.clock_start_s + t);
        for (k, s) in c.stations.iter().enumerate() {
            let law = artifact.as_ref().filter(|(st, _)| *st == k).map(|(_, l)| l);
            clean[k] = measured_rpm(law, y[s.node], y[n_nodes + s.node], sample_s);
            let v = clean[k] + c.noise_rpm * rng.normal();
            if !v.is_finite() && diverged_s.is_none() {
                diverged_s = Some(t);
            }
            let _ = write!(csv, ",{v:.3}");
        }
        csv.push('\n');
        orders.add(y[crank], &clean);
    });
    if let Some(t) = diverged_s {
        return Err(WriteError::Unusable(format!(
            "seed {} draw {}: the bench's truth diverged in `{}` at {t:.4} s ({} form)",
            case.seed, case.attempt, rec.stem, case.form
        )));
    }
    if let Some((t, i, f)) = reversed {
        let what = if f <= 0.0 {
            "turns backwards"
        } else if f < 1.0 {
            "nearly stops"
        } else {
            "races"
        };
        return Err(WriteError::Unusable(format!(
            "seed {} draw {}: node `{}` {what} in `{}` at {t:.4} s ({f:.2} of its mean \
             speed, outside 1 ± {MAX_SWING}): no running bench does that (an engine would \
             stall or race)",
            case.seed, case.attempt, case.truth.nodes[i].name, rec.stem
        )));
    }
    let mut side = format!(
        "format = 1\nkind = \"{}\"\nreference = \"{}\"\nload = {}\nlabel = \"{}\"\n",
        if rec.run_up { "run-up" } else { "steady" },
        case.truth.nodes[case.truth.engine.node].name,
        rec.load,
        rec.label
    );
    if !rec.run_up {
        let _ = writeln!(side, "speed_rpm = {}", rec.from_rpm);
    }
    for s in &c.stations {
        let _ = write!(
            side,
            "\n[sensors.{}]\nkind = \"{}\"\nlines_per_rev = {}\n",
            case.truth.nodes[s.node].name, s.kind, s.lines
        );
    }
    Ok(Simulated {
        stem: rec.stem.clone(),
        csv,
        sidecar: side,
        exercise: meter.and_then(|m| m.result()),
        orders,
    })
}

/// Simulates every recording of `case`, in parallel; nothing is written.
pub(crate) fn simulate_case(case: &Case) -> Result<Vec<Simulated>, WriteError> {
    let results: Vec<Result<Simulated, WriteError>> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..case.campaign.recordings.len())
            .map(|i| s.spawn(move || simulate_recording(case, i)))
            .collect();
        handles
            .into_iter()
            .map(|h| {
                h.join().unwrap_or_else(|_| {
                    Err(WriteError::Draw("a simulation thread panicked".into()))
                })
            })
            .collect()
    });
    results.into_iter().collect()
}

/// Writes a case whose every recording simulated; `unusable` are the earlier draws of its
/// seed that no bench could run, kept in `truth.toml`.
pub(crate) fn write_simulated(
    case: &Case,
    simulated: Vec<Simulated>,
    visibility: Option<Visibility>,
    unusable: &[String],
    dir: &Path,
) -> Result<CaseFiles, WriteError> {
    std::fs::create_dir_all(dir).map_err(|source| WriteError::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    // The range the bench's rubber fits take their band from (`sim::band`).
    let (lo, hi) = crate::fitpoints::speed_range_rpm(&case.campaign);
    let model = dir.join("model.toml");
    put(&model, &model_file::model_toml(&case.user, lo, hi))?;
    let mut recordings = Vec::new();
    let mut exercise: Vec<(String, Exercise)> = Vec::new();
    for r in simulated {
        let csv_path = dir.join(format!("{}.csv", r.stem));
        put(&csv_path, &r.csv)?;
        put(&dir.join(format!("{}.toml", r.stem)), &r.sidecar)?;
        recordings.push(csv_path);
        if let Some(e) = r.exercise {
            exercise.push((r.stem, e));
        }
    }
    let truth = dir.join("truth.toml");
    put(
        &truth,
        &truth_file::truth_toml(case, &exercise, visibility.as_ref(), unusable),
    )?;
    Ok(CaseFiles {
        model,
        recordings,
        truth,
        class: case.class.clone(),
        form: case.form.clone(),
        place: case.place.clone(),
        exercise,
        draw: case.attempt,
        visibility,
    })
}
