//! Run-up spectrograms as images, built on the simulation thread from the library's STFT
//! (`torsim::signal`, 0.1 s Hann windows): one colour image per station, amplitude in dB
//! re 1 rpm (zero-to-peak) over a 60 dB range, frequency up, time across; and the colour
//! map its legend uses.

use egui::{Color32, ColorImage};
use torsim::signal::{Analysis, StationAnalysis};

/// Dynamic range of the colour scale, dB.
pub const RANGE_DB: f64 = 60.0;

/// The widest texture built, pixels (windows are merged beyond, keeping their maximum).
const MAX_COLUMNS: usize = 2048;

/// One station's spectrogram.
#[derive(Debug, Clone)]
pub struct Spectrogram {
    /// Node, or `"a-b"` for a relative speed.
    pub station: String,
    /// Rows from the highest frequency (top) down to 0 Hz; one column per window.
    pub image: ColorImage,
    /// Amplitude of each pixel, dB re 1 rpm (row-major like `image`).
    pub db: Vec<f32>,
    /// Colour scale, dB re 1 rpm: `[bottom, top]`.
    pub db_range: [f64; 2],
}

impl Spectrogram {
    /// Amplitude at (`t_s`, `f_hz`) in the image of `set`, dB re 1 rpm, if inside.
    pub fn db_at(&self, set: &SpectrogramSet, t_s: f64, f_hz: f64) -> Option<f32> {
        let [w, h] = self.image.size;
        let [t0, t1] = set.time_range_s;
        let [f0, f1] = set.freq_range_hz;
        let u = (t_s - t0) / (t1 - t0);
        let v = (f1 - f_hz) / (f1 - f0);
        if !((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v)) {
            return None;
        }
        let (c, r) = ((u * w as f64) as usize, (v * h as f64) as usize);
        self.db.get(r * w + c).copied()
    }
}

/// The spectrograms of a run-up and their axes.
#[derive(Debug, Clone)]
pub struct SpectrogramSet {
    /// Window centres, s from the start of the recording.
    pub times_s: Vec<f64>,
    /// Mean reference speed in each window, rpm.
    pub speeds_rpm: Vec<f64>,
    /// Time extent of the images, s (window centres ± half a hop).
    pub time_range_s: [f64; 2],
    /// Frequency extent of the images, Hz (lines ± half a line).
    pub freq_range_hz: [f64; 2],
    /// Tracked orders (the order lines).
    pub orders: Vec<f64>,
    /// One per station, then per relative speed.
    pub stations: Vec<Spectrogram>,
}

impl SpectrogramSet {
    /// The spectrograms of a run-up's analysis (`None` for a steady run). Frequencies
    /// above `max_hz` are left out.
    pub fn new(analysis: &Analysis, t0_s: f64, max_hz: f64) -> Option<Self> {
        let axes = analysis.stft.as_ref()?;
        let df = axes.frequencies_hz.get(1).copied().unwrap_or(1.0);
        let lines = axes
            .frequencies_hz
            .iter()
            .take_while(|&&f| f <= max_hz)
            .count()
            .max(2);
        let hop = match axes.times_s.as_slice() {
            [a, b, ..] => b - a,
            _ => 0.1,
        };
        let times_s: Vec<f64> = axes.times_s.iter().map(|t| t - t0_s).collect();
        let first = times_s.first().copied().unwrap_or(0.0);
        let last = times_s.last().copied().unwrap_or(0.0);
        let stations = analysis
            .stations
            .iter()
            .chain(&analysis.n_rel)
            .filter_map(|s| image_of(s, lines))
            .collect();
        Some(Self {
            times_s,
            speeds_rpm: axes.speeds_rpm.clone(),
            time_range_s: [first - 0.5 * hop, last + 0.5 * hop],
            freq_range_hz: [-0.5 * df, (lines as f64 - 0.5) * df],
            orders: axes.orders.clone(),
            stations,
        })
    }

    /// Reference speed at `t_s`, rpm, interpolated between window centres (extended
    /// linearly beyond the first and last).
    pub fn speed_at(&self, t_s: f64) -> f64 {
        interpolate(&self.times_s, &self.speeds_rpm, t_s)
    }
}

/// Linear interpolation in `(x, y)` (`x` increasing), extended along the end segments.
pub fn interpolate(x: &[f64], y: &[f64], at: f64) -> f64 {
    let n = x.len().min(y.len());
    match n {
        0 => 0.0,
        1 => y[0],
        _ => {
            let i = x[..n].partition_point(|&v| v < at).clamp(1, n - 1);
            let u = (at - x[i - 1]) / (x[i] - x[i - 1]);
            y[i - 1] + u * (y[i] - y[i - 1])
        }
    }
}

/// The image of one station's STFT, or `None` if it has none.
fn image_of(s: &StationAnalysis, lines: usize) -> Option<Spectrogram> {
    let magnitude = &s.stft.as_ref()?.magnitude_rpm;
    let windows = magnitude.len();
    let per_column = windows.div_ceil(MAX_COLUMNS).max(1);
    let columns = windows.div_ceil(per_column);
    let db = |rpm: f64| 20.0 * rpm.max(1e-12).log10();
    let peak = magnitude
        .iter()
        .flat_map(|w| w.iter().take(lines).skip(1))
        .fold(1e-12_f64, |m, &v| m.max(v));
    let top = (db(peak) / 10.0).ceil() * 10.0;
    let bottom = top - RANGE_DB;
    let mut pixels = vec![Color32::BLACK; columns * lines];
    let mut levels = vec![0.0_f32; columns * lines];
    for c in 0..columns {
        let group = &magnitude[c * per_column..((c + 1) * per_column).min(windows)];
        for line in 0..lines {
            let v = group
                .iter()
                .map(|w| w.get(line).copied().unwrap_or(0.0))
                .fold(0.0, f64::max);
            let row = lines - 1 - line;
            pixels[row * columns + c] = colour((db(v) - bottom) / RANGE_DB);
            levels[row * columns + c] = db(v) as f32;
        }
    }
    Some(Spectrogram {
        station: s.name.clone(),
        image: ColorImage::new([columns, lines], pixels),
        db: levels,
        db_range: [bottom, top],
    })
}

/// Stops of the colour map (viridis), from low to high.
const STOPS: [(u8, u8, u8); 5] = [
    (68, 1, 84),
    (59, 82, 139),
    (33, 145, 140),
    (94, 201, 98),
    (253, 231, 37),
];

/// The colour of `u` in 0..1 (clamped) on the map.
pub fn colour(u: f64) -> Color32 {
    let x = u.clamp(0.0, 1.0) * (STOPS.len() - 1) as f64;
    let i = (x.floor() as usize).min(STOPS.len() - 2);
    let f = x - i as f64;
    let mix = |a: u8, b: u8| (f64::from(a) + f * (f64::from(b) - f64::from(a))).round() as u8;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    Color32::from_rgb(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colour_map_ends_and_interpolation() {
        assert_eq!(colour(-1.0), Color32::from_rgb(68, 1, 84));
        assert_eq!(colour(1.0), Color32::from_rgb(253, 231, 37));
        // Halfway between the 2nd and 3rd stops.
        assert_eq!(colour(0.375), Color32::from_rgb(46, 114, 140));
        assert_eq!(interpolate(&[0.0, 1.0], &[10.0, 20.0], 0.25), 12.5);
        assert_eq!(interpolate(&[0.0, 1.0], &[10.0, 20.0], 3.0), 40.0);
        assert_eq!(interpolate(&[1.0, 2.0, 4.0], &[10.0, 20.0, 20.0], 0.5), 5.0);
        assert_eq!(interpolate(&[1.0], &[7.0], 9.0), 7.0);
    }
}
