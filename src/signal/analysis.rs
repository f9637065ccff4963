//! The analysis of a whole recording, as `torsim analyse` prints it and `simulate`
//! computes it: per speed station and per pair of stations (relative speed), the mean
//! speed, RMS, irregularity ratio and order amplitudes; for run-ups the STFT and order
//! tracks against the reference speed.

use std::collections::BTreeMap;

use super::antialias::{self, LowPass};
use super::kernel::HALF_WIDTH;
use super::orders::{self, OrderAmplitude, OrderSpectrum};
use super::resample::{self, AngleGrid, Interpolation};
use super::stft::{self, Frames};
use super::{SignalError, stats};
use crate::recording::{Recording, RunKind};

/// Settings of [`analyse_with`]; [`Default`] gives seed 001's.
#[derive(Debug, Clone, PartialEq)]
pub struct AnalysisOptions {
    /// Angle-domain points per reference revolution (default 256).
    pub samples_per_rev: usize,
    /// Highest order reported (default 24); orders above 0.8 × Nyquist of the samples at
    /// the highest reference speed are left out.
    pub max_order: f64,
    /// Cycles per block of the block-averaged order spectrum (default 20).
    pub block_cycles: usize,
    /// STFT window, s (default 0.1: 10 Hz resolution).
    pub stft_window_s: f64,
    /// STFT overlap, 0 ≤ overlap < 1 (default 0.5).
    pub stft_overlap: f64,
    /// Highest order tracked in a run-up's STFT (default 12).
    pub track_max_order: f64,
    /// Interpolation between samples (default band-limited).
    pub interpolation: Interpolation,
    /// Speed of a node's shaft over the reference shaft's, by node (default 1), used to
    /// refer one station to the other's shaft in the relative speed.
    pub shaft_ratio: BTreeMap<String, f64>,
    /// Station pairs `(a, b)` whose relative speed `n_a − n_b` is reported; `None`: every
    /// pair (a bench usually has two or three stations).
    pub pairs: Option<Vec<(String, String)>>,
    /// Whether a run-up's STFT magnitudes are computed (default `true`); without them
    /// [`StationStft::magnitude_rpm`] is empty and only the order tracks are made (the
    /// diagnosis reads the tracks alone: the magnitudes were an eighth of its analyses'
    /// time on benchtruth seed 2010, `perf`).
    pub spectrogram: bool,
}

impl Default for AnalysisOptions {
    fn default() -> Self {
        Self {
            samples_per_rev: resample::SAMPLES_PER_REV,
            max_order: 24.0,
            block_cycles: 20,
            stft_window_s: 0.1,
            stft_overlap: 0.5,
            track_max_order: 12.0,
            interpolation: Interpolation::BandLimited,
            shaft_ratio: BTreeMap::new(),
            pairs: None,
            spectrogram: true,
        }
    }
}

/// The statistics of one signal: a station's IAS, or the relative speed of two.
#[derive(Debug, Clone, PartialEq)]
pub struct StationAnalysis {
    /// The node, or `"<a>-<b>"` for the relative speed `n_a − n_b`.
    pub name: String,
    /// Time mean, rpm.
    pub mean_speed_rpm: f64,
    /// RMS about the mean, rpm: of the synchronously averaged cycle for a steady run, of
    /// the whole detrended angle-domain signal for a run-up.
    pub rms_rpm: f64,
    /// Peak-to-peak over the mean speed, % (same data as `rms_rpm`; for a relative
    /// speed, over the first station's mean speed).
    pub irregularity_pct: f64,
    /// Order amplitudes (zero-to-peak, rpm) of the synchronously averaged cycle.
    pub orders: Vec<OrderAmplitude>,
    /// The synchronously averaged cycle, rpm (trend removed, mean added back).
    pub average_cycle_rpm: Vec<f64>,
    /// Order spectrum averaged over blocks of `block_cycles` cycles.
    pub spectrum: OrderSpectrum,
    /// Run-ups only: the STFT and the order tracks.
    pub stft: Option<StationStft>,
}

/// A signal's STFT in a run-up.
#[derive(Debug, Clone, PartialEq)]
pub struct StationStft {
    /// Magnitude per window and frequency line, rpm zero-to-peak; empty when
    /// [`AnalysisOptions::spectrogram`] is off.
    pub magnitude_rpm: Vec<Vec<f64>>,
    /// Per order of [`RunUpStft::orders`], the amplitude in each window, rpm.
    pub order_tracks_rpm: Vec<Vec<f64>>,
}

/// The STFT axes of a run-up.
#[derive(Debug, Clone, PartialEq)]
pub struct RunUpStft {
    /// Window centres, s.
    pub times_s: Vec<f64>,
    /// Mean reference speed in each window, rpm.
    pub speeds_rpm: Vec<f64>,
    /// Frequency lines, Hz.
    pub frequencies_hz: Vec<f64>,
    /// Tracked orders.
    pub orders: Vec<f64>,
}

/// The analysis of a recording.
#[derive(Debug, Clone, PartialEq)]
pub struct Analysis {
    /// Reference node.
    pub reference: String,
    /// Steady or run-up.
    pub kind: RunKind,
    /// Reference revolutions per working cycle (2 for 4-stroke).
    pub cycle_rev: f64,
    /// Whole cycles averaged.
    pub cycles: usize,
    /// Highest order reported.
    pub max_order: f64,
    /// Speed stations, in column order.
    pub stations: Vec<StationAnalysis>,
    /// Relative speeds of every pair of stations (a before b in column order).
    pub n_rel: Vec<StationAnalysis>,
    /// Run-ups only: STFT axes.
    pub stft: Option<RunUpStft>,
}

/// [`analyse_with`] with the default options.
pub fn analyse(recording: &Recording) -> Result<Analysis, SignalError> {
    analyse_with(recording, &AnalysisOptions::default())
}

struct Context<'a> {
    grid: AngleGrid,
    options: &'a AnalysisOptions,
    kind: RunKind,
    cycle_rev: f64,
    max_order: f64,
    frames: Option<(Frames, Vec<f64>, Vec<f64>)>,
}

/// Analyses every speed station of a recording and every pair of them.
pub fn analyse_with(
    recording: &Recording,
    options: &AnalysisOptions,
) -> Result<Analysis, SignalError> {
    let meta = &recording.meta;
    let reference = recording
        .speed_rpm(&meta.reference)
        .ok_or_else(|| SignalError::MissingReference(meta.reference.clone()))?;
    let cycle_rev = meta.cycle_rev();
    // A steady record sampled faster than the angle grid is low-passed first, so its
    // high orders do not fold onto the low ones ([`super::antialias`]); the grid then
    // keeps the filter's half-width clear of the ends, where it is exact. A record too
    // short for that margin is analysed unfiltered. A run-up's order tracks come from its
    // time samples ([`stft`]).
    let low_pass = match meta.kind {
        RunKind::Steady => resample::uniform_interval(&recording.time_s)
            .ok()
            .and_then(|dt| {
                let low_rpm = reference.iter().fold(f64::INFINITY, |a, &b| a.min(b));
                LowPass::new(
                    antialias::grid_nyquist_hz(options.samples_per_rev, low_rpm),
                    dt,
                )
            }),
        RunKind::RunUp => None,
    };
    let within = |margin: usize| {
        resample::angle_grid_within(
            &recording.time_s,
            reference,
            options.samples_per_rev,
            cycle_rev,
            margin,
        )
    };
    let (grid, low_pass) = match low_pass {
        Some(f) => match within(HALF_WIDTH + f.half_width()) {
            Ok(grid) => (grid, Some(f)),
            Err(_) => (within(HALF_WIDTH)?, None),
        },
        None => (within(HALF_WIDTH)?, None),
    };
    let top_rpm = reference.iter().fold(0.0_f64, |a, &b| a.max(b));
    let step = 1.0 / cycle_rev;
    let measurable = 0.4 / grid.dt_s * 60.0 / top_rpm;
    let max_order = ((options.max_order.min(measurable) / step + 1e-9).floor() * step).max(0.0);
    let mut stft_axes = None;
    let frames = if meta.kind == RunKind::RunUp {
        let frames = Frames::new(
            reference.len(),
            grid.dt_s,
            options.stft_window_s,
            options.stft_overlap,
        )?;
        let speeds = frames.means(reference);
        let count = (options.track_max_order.min(max_order) / step + 1e-9).floor() as usize;
        let track_orders: Vec<f64> = (1..=count).map(|k| k as f64 * step).collect();
        let df = 1.0 / (frames.len as f64 * grid.dt_s);
        stft_axes = Some(RunUpStft {
            times_s: frames.centres_s(grid.t0_s, grid.dt_s),
            speeds_rpm: speeds.clone(),
            frequencies_hz: (0..=frames.len / 2).map(|k| k as f64 * df).collect(),
            orders: track_orders.clone(),
        });
        Some((frames, speeds, track_orders))
    } else {
        None
    };
    let cx = Context {
        grid,
        options,
        kind: meta.kind,
        cycle_rev,
        max_order,
        frames,
    };
    let stations_in = recording.speed_stations();
    let ratio = |node: &str| options.shaft_ratio.get(node).copied().unwrap_or(1.0);
    // Every signal first (stations, then the relative speeds of the pairs wanted), so
    // that the angle grid's interpolation taps are worked out once for all of them.
    let mut signals: Vec<(String, Vec<f64>, f64)> = Vec::new();
    let station_means: Vec<f64> = stations_in.iter().map(|(_, v)| stats::mean(v)).collect();
    for ((node, _), mean) in stations_in.iter().zip(&station_means) {
        // Issue 13: no NaN in a report; say what cannot be computed and why.
        if *mean == 0.0 {
            return Err(SignalError::StandingStation((*node).to_string()));
        }
    }
    for (i, ((a, va), mean_a)) in stations_in.iter().zip(&station_means).enumerate() {
        for (b, vb) in &stations_in[i + 1..] {
            let wanted = options.pairs.as_ref().is_none_or(|pairs| {
                pairs
                    .iter()
                    .any(|(x, y)| (x == a && y == b) || (x == b && y == a))
            });
            if wanted {
                let rel = stats::relative_speed(va, vb, ratio(a) / ratio(b));
                signals.push((format!("{a}-{b}"), rel, *mean_a));
            }
        }
    }
    let all: Vec<&[f64]> = stations_in
        .iter()
        .map(|(_, v)| &v[..])
        .chain(signals.iter().map(|(_, v, _)| &v[..]))
        .collect();
    let filtered: Option<Vec<Vec<f64>>> = low_pass.map(|f| f.apply_all(&all));
    let all: Vec<&[f64]> = match &filtered {
        Some(f) => f.iter().map(Vec::as_slice).collect(),
        None => all,
    };
    let angles = resample::resample_many(&cx.grid, &all, options.interpolation);
    let mut angles = angles.into_iter();
    let mut stations = Vec::with_capacity(stations_in.len());
    for (((node, values), mean), angle) in
        stations_in.iter().zip(&station_means).zip(angles.by_ref())
    {
        stations.push(cx.signal(node, values, angle, *mean)?);
    }
    let mut n_rel = Vec::with_capacity(signals.len());
    for ((name, rel, ir_mean_rpm), angle) in signals.iter().zip(angles) {
        n_rel.push(cx.signal(name, rel, angle, *ir_mean_rpm)?);
    }
    Ok(Analysis {
        reference: meta.reference.clone(),
        kind: meta.kind,
        cycle_rev,
        cycles: cx.grid.cycles,
        max_order,
        stations,
        n_rel,
        stft: stft_axes,
    })
}

impl Context<'_> {
    /// The statistics of one signal (`values`: time samples of the recording; `angle`:
    /// the same on the angle grid); `ir_mean_rpm` is the speed the irregularity ratio is
    /// referred to.
    fn signal(
        &self,
        name: &str,
        values: &[f64],
        angle: Vec<f64>,
        ir_mean_rpm: f64,
    ) -> Result<StationAnalysis, SignalError> {
        let spc = self.grid.samples_per_cycle;
        let (detrended, means) = orders::remove_trend(&angle, spc);
        let mean_speed_rpm = stats::mean(values);
        let cycle = orders::synchronous_average(&detrended, spc);
        let (rms_rpm, irregularity_pct) = match self.kind {
            RunKind::Steady => (
                stats::rms_about_mean(&cycle),
                stats::irregularity_pct(&cycle, ir_mean_rpm),
            ),
            RunKind::RunUp => (
                stats::rms_about_mean(&detrended),
                stats::irregularity_pct(&detrended, ir_mean_rpm),
            ),
        };
        let orders = orders::cycle_orders(&cycle, self.cycle_rev, self.max_order)?;
        let spectrum = orders::block_order_spectrum(
            &detrended,
            spc,
            self.cycle_rev,
            self.options.block_cycles,
            self.max_order,
        )?;
        let stft = match &self.frames {
            None => None,
            Some((frames, speeds, track_orders)) => {
                // The run-up's slow trend, mapped back to time, so the sweep itself does
                // not smear into the lowest lines.
                let values: Vec<f64> = values
                    .iter()
                    .zip(self.grid.sample_cycles())
                    .map(|(v, x)| v - orders::trend_at(&means, x))
                    .collect();
                let magnitude = match self.options.spectrogram {
                    true => stft::stft(&values, self.grid.t0_s, self.grid.dt_s, frames)?.magnitude,
                    false => Vec::new(),
                };
                let order_tracks_rpm =
                    stft::order_tracks(&values, self.grid.dt_s, frames, speeds, track_orders);
                Some(StationStft {
                    magnitude_rpm: magnitude,
                    order_tracks_rpm,
                })
            }
        };
        let cycle_mean = stats::mean(&cycle);
        Ok(StationAnalysis {
            name: name.to_string(),
            mean_speed_rpm,
            rms_rpm,
            irregularity_pct,
            orders,
            average_cycle_rpm: cycle
                .iter()
                .map(|x| x - cycle_mean + mean_speed_rpm)
                .collect(),
            spectrum,
            stft,
        })
    }
}
