//! What every time plot shares: the linked time axis, the visible range, drawing long
//! series decimated ([`crate::gui::views::decimate`]), the hover read-out with the reference
//! speed, a grid with numbers on short axes, the y-axis width that lines the plots up.

use crate::gui::session::trace_data::TraceLayout;
use crate::gui::views::decimate::{Decimated, decimate};
use egui::{Color32, Id};
use egui_plot::{FilledArea, GridInput, GridMark, HoverPosition, Line, LineStyle, PlotUi};
use std::sync::Arc;

/// The x axes (time) of every time plot move together.
pub fn time_link() -> Id {
    Id::unique("torsim-time-axis")
}

/// The visible time range of a plot (all of it while it follows the data), with a
/// plot width of margin either side.
pub fn visible_range(plot: &PlotUi<'_>) -> [f64; 2] {
    let b = plot.plot_bounds();
    if plot.auto_bounds().x || !b.is_valid_x() {
        return [f64::NEG_INFINITY, f64::INFINITY];
    }
    let w = b.width();
    [b.min()[0] - w, b.max()[0] + w]
}

/// `(time_s + offset_s, values − baseline(time_s + offset_s))` within `range`, decimated
/// to `buckets` ([`decimate`]).
pub fn series(
    time_s: &[f64],
    values: &[f64],
    offset_s: f64,
    baseline: &dyn Fn(f64) -> f64,
    range: [f64; 2],
    buckets: usize,
) -> Decimated {
    let shifted = |t: f64| baseline(t + offset_s);
    let window = [range[0] - offset_s, range[1] - offset_s];
    match decimate(time_s, values, &shifted, window, buckets) {
        Decimated::Points(mut p) => {
            p.iter_mut().for_each(|x| x[0] += offset_s);
            Decimated::Points(p)
        }
        Decimated::Envelope {
            mut time_s,
            min,
            max,
        } => {
            time_s.iter_mut().for_each(|t| *t += offset_s);
            Decimated::Envelope { time_s, min, max }
        }
    }
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Look {
    /// A simulated series: a thin line, or a filled envelope.
    Simulated,
    /// A measured series: a wide dashed line, or the dashed outline of its envelope
    /// (issue 16: solid simulated against dashed measured, not two shades of a colour).
    Measured,
    /// A dashed thin line (for a recording's order tracks).
    Dashed,
}

/// Draws a decimated series named `name` (the legend entry) in `colour`.
pub fn draw(plot: &mut PlotUi<'_>, name: &str, series: Decimated, colour: Color32, look: Look) {
    match (series, look) {
        (Decimated::Points(p), Look::Simulated) => {
            plot.line(Line::new(name, p).color(colour).width(1.2));
        }
        (Decimated::Points(p), Look::Measured) => {
            plot.line(
                Line::new(name, p)
                    .color(colour.gamma_multiply(0.85))
                    .width(2.2)
                    .style(LineStyle::dashed_loose()),
            );
        }
        (Decimated::Points(p), Look::Dashed) => {
            plot.line(
                Line::new(name, p)
                    .color(colour)
                    .style(LineStyle::dashed_dense()),
            );
        }
        (Decimated::Envelope { time_s, min, max }, Look::Simulated) => {
            plot.add(
                FilledArea::new(name, &time_s, &min, &max).fill_color(colour.gamma_multiply(0.8)),
            );
        }
        (Decimated::Envelope { time_s, min, max }, Look::Measured | Look::Dashed) => {
            // The outline of the envelope: two lines of one name, one legend entry.
            for edge in [min, max] {
                let points: Vec<[f64; 2]> = time_s.iter().zip(edge).map(|(&t, v)| [t, v]).collect();
                plot.line(
                    Line::new(name, points)
                        .color(colour.gamma_multiply(0.85))
                        .width(1.5)
                        .style(LineStyle::dashed_loose()),
                );
            }
        }
    }
}

/// Hover read-out: the series, time with the reference speed, and value with unit.
pub fn hover_label(
    layout: Arc<TraceLayout>,
    unit: &'static str,
) -> impl Fn(&HoverPosition<'_>) -> Option<String> {
    move |pos| {
        let (name, p) = match pos {
            HoverPosition::NearDataPoint {
                plot_name,
                position,
                ..
            } => (*plot_name, *position),
            HoverPosition::Elsewhere { position } => ("", *position),
        };
        let head = if name.is_empty() {
            String::new()
        } else {
            format!("{name}\n")
        };
        let speed = layout.speed_at(p.x);
        Some(format!(
            "{head}t = {:.4} s ({speed:.0} rpm)\n{:.3} {unit}",
            p.x, p.y
        ))
    }
}

/// A grid of 1-2-5 steps with labelled lines 32 to 80 points apart, so even a short plot
/// has numbers on its axis (egui_plot's default steps by powers of ten). For y axes:
/// egui_plot labels y marks 20 points apart or more.
pub fn nice_grid() -> impl Fn(GridInput) -> Vec<GridMark> {
    grid_labelled_from(32.0)
}

/// [`nice_grid`] for x axes: labelled lines 80 to 200 points apart, since egui_plot hides
/// x labels closer than 60 points and fades them up to 80 (a 2 s trace 550 points wide
/// was labelled only at 0 and 1 s with the y-axis grid).
pub fn nice_x_grid() -> impl Fn(GridInput) -> Vec<GridMark> {
    grid_labelled_from(80.0)
}

/// 1-2-5 steps whose labelled lines are at least `points` apart.
fn grid_labelled_from(points: f64) -> impl Fn(GridInput) -> Vec<GridMark> {
    egui_plot::uniform_grid_spacer(move |input| {
        // `base_step_size` spans egui_plot's minimal grid spacing, 8 points.
        let main = nice_step(points / 8.0 * input.base_step_size);
        [main / 5.0, main, main * 5.0]
    })
}

/// Width of the y axes of stacked plots, points (equal, so linked time axes line up).
pub const Y_AXIS_W: f32 = 72.0;

/// The 1-2-5 step at least `raw`.
fn nice_step(raw: f64) -> f64 {
    let power = 10f64.powf(raw.max(1e-12).log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * power)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * power)
}

/// Grid marks on a time axis at round reference speeds of a linear ramp
/// `n(t) = from_rpm + rate · t` (rpm, rpm/s), labelled lines 32 to 80 points apart; with
/// no rate, at round times.
pub fn speed_grid(from_rpm: f64, rate: f64) -> impl Fn(GridInput) -> Vec<GridMark> {
    let (n0, r) = if rate.abs() > 1e-9 {
        (from_rpm, rate)
    } else {
        (0.0, 1.0)
    };
    move |input: GridInput| {
        let (a, b) = (n0 + r * input.bounds.0, n0 + r * input.bounds.1);
        let (lo, hi) = (a.min(b), a.max(b));
        // `base_step_size` spans egui_plot's minimal grid spacing, 8 points.
        let main = nice_step(4.0 * input.base_step_size * r.abs());
        let mut marks: Vec<GridMark> = Vec::new();
        for step in [main * 5.0, main, main / 5.0] {
            let first = (lo / step).ceil() as i64;
            let last = ((hi / step).floor() as i64).min(first + 10_000);
            for k in first..=last {
                let t = (k as f64 * step - n0) / r;
                let known = marks
                    .iter()
                    .any(|m| (m.value - t).abs() <= 1e-9 * (1.0 + t.abs()));
                if !known {
                    marks.push(GridMark {
                        value: t,
                        step_size: step / r.abs(),
                    });
                }
            }
        }
        marks
    }
}
