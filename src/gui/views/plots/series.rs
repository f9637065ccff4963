//! A plotted series that is drawn and exported from the same numbers, the axis grid, and
//! the hover read-out with units shared by the plots.

use super::PlotData;
use egui::Color32;
use egui_plot::{GridInput, GridMark, HoverPosition, Line, LineStyle, PlotPoints};

/// One line of a plot.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend name (`order 4.5`).
    pub name: String,
    /// CSV column name with its unit (`order 4.5 IAS amplitude [rpm]`).
    pub column: String,
    /// The points, plot units.
    pub points: Vec<[f64; 2]>,
    /// Line colour.
    pub color: Color32,
    /// Line width, points.
    pub width: f32,
    /// Dashed for bounds and references.
    pub dashed: bool,
}

impl Series {
    /// A solid line of width 1.5.
    pub fn new(name: impl Into<String>, column: impl Into<String>, points: Vec<[f64; 2]>) -> Self {
        Self {
            name: name.into(),
            column: column.into(),
            points,
            color: Color32::GRAY,
            width: 1.5,
            dashed: false,
        }
    }

    /// The same with colour `color`.
    pub fn color(mut self, color: Color32) -> Self {
        self.color = color;
        self
    }

    /// The same with width `width`.
    pub fn width(mut self, width: f32) -> Self {
        self.width = width;
        self
    }

    /// The same, dashed.
    pub fn dashed(mut self) -> Self {
        self.dashed = true;
        self
    }

    /// The egui_plot line.
    pub fn line(&self) -> Line<'static> {
        let points: PlotPoints = self.points.iter().copied().collect();
        let line = Line::new(self.name.clone(), points)
            .color(self.color)
            .width(self.width);
        if self.dashed {
            line.style(LineStyle::dashed_loose())
        } else {
            line
        }
    }
}

/// Export data of `series` over `x_label`.
pub fn plot_data(title: impl Into<String>, x_label: &str, series: &[Series]) -> PlotData {
    PlotData {
        title: title.into(),
        x_label: x_label.into(),
        x_names: Vec::new(),
        columns: series
            .iter()
            .map(|s| (s.column.clone(), s.points.clone()))
            .collect(),
    }
}

/// The next step of the 1–2–5 series at or above `step`.
fn nice_step(step: f64) -> f64 {
    let decade = 10f64.powf(step.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|&s| s >= step * (1.0 - 1e-9))
        .unwrap_or(10.0 * decade)
}

/// True when `a` is a whole multiple of `b`.
fn divides(b: f64, a: f64) -> bool {
    let r = a / b;
    (r - r.round()).abs() < 1e-9 * r.max(1.0)
}

/// Grid lines on the 1–2–5 series, nested (each step a multiple of the finer): the
/// finest at egui_plot's minimum spacing, the coarsest (which carries the labels) near
/// ten times it, so that a 400–2000 rpm axis gets a label every 200 or 500 rpm rather than
/// egui_plot's powers of ten (one label).
pub fn grid_125(input: GridInput) -> Vec<GridMark> {
    let base = input.base_step_size.abs();
    if base == 0.0 || !base.is_finite() {
        return Vec::new();
    }
    let fine = nice_step(base);
    let coarse = nice_step(10.0 * base);
    let mut mid = fine;
    let mut s = nice_step(fine * 1.5);
    while s < coarse {
        if divides(fine, s) && divides(s, coarse) {
            mid = s;
        }
        s = nice_step(s * 1.5);
    }
    let steps = [fine, mid, coarse];
    let (lo, hi) = input.bounds;
    let mut marks: Vec<GridMark> = Vec::new();
    for &step in &steps {
        let first = (lo / step).ceil() as i64;
        let last = (hi / step).floor() as i64;
        if last - first > 2000 {
            continue;
        }
        for i in first..=last {
            let value = i as f64 * step;
            match marks
                .iter_mut()
                .find(|m| (m.value - value).abs() < 1e-6 * step)
            {
                Some(m) => m.step_size = m.step_size.max(step),
                None => marks.push(GridMark {
                    value,
                    step_size: step,
                }),
            }
        }
    }
    marks
}

/// A hover read-out: the nearest series' name and its point in units, or the pointer's
/// coordinates elsewhere.
pub fn hover_label(
    x_unit: &'static str,
    y_unit: &'static str,
) -> impl Fn(&HoverPosition<'_>) -> Option<String> {
    move |pos| {
        Some(match pos {
            HoverPosition::NearDataPoint {
                plot_name,
                position,
                ..
            } => format!(
                "{plot_name}\n{} {x_unit}\n{} {y_unit}",
                fmt(position.x),
                fmt(position.y)
            ),
            HoverPosition::Elsewhere { position } => {
                format!("{} {x_unit}\n{} {y_unit}", fmt(position.x), fmt(position.y))
            }
        })
    }
}

/// An axis tick's text with as many decimals as its grid step needs (issue 16: with
/// egui_plot's default an order axis read "1, 0, 0" for 0.5, 1, 1.5): none for steps of 1
/// or more, one for 0.5 or 0.1, two for 0.05, …; large and tiny values in engineering
/// form. Used by every plot with numeric axes.
pub fn tick_label(mark: egui_plot::GridMark, _range: &std::ops::RangeInclusive<f64>) -> String {
    let (v, step) = (mark.value, mark.step_size.abs());
    if v == 0.0 {
        return "0".into();
    }
    if v.abs() >= 1e6 || (v.abs() < 1e-4) {
        return format!("{v:.2e}");
    }
    // The fewest decimals that write the step exactly: 0.5 → 1, 0.25 → 2, 5 → 0.
    let decimals = (0..=6)
        .find(|&d| {
            let scaled = step * 10f64.powi(d);
            (scaled - scaled.round()).abs() <= 1e-6 * scaled.max(1.0)
        })
        .unwrap_or(6) as usize;
    format!("{v:.decimals$}")
}

/// Four significant digits, no exponent for everyday magnitudes.
pub fn fmt(v: f64) -> String {
    let a = v.abs();
    if a != 0.0 && !(1e-3..1e6).contains(&a) {
        format!("{v:.3e}")
    } else if a >= 100.0 {
        format!("{v:.1}")
    } else if a >= 1.0 {
        format!("{v:.3}")
    } else {
        format!("{v:.4}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Ticks carry the decimals their step needs.
    #[test]
    fn tick_labels_have_the_decimals_of_their_step() {
        let t =
            |value: f64, step_size: f64| tick_label(GridMark { value, step_size }, &(0.0..=1.0));
        assert_eq!(t(0.5, 0.5), "0.5");
        assert_eq!(t(1.0, 0.5), "1.0");
        assert_eq!(t(1.25, 0.25), "1.25");
        assert_eq!(t(2000.0, 500.0), "2000");
        assert_eq!(t(0.3, 0.1), "0.3");
        assert_eq!(t(0.0, 0.1), "0");
    }

    /// Steps on the 1–2–5 series, nested; on a 400–2000 rpm axis with a 30 rpm minimum
    /// step: 50, 100 (not 200: 500 is no multiple of it) and 500 rpm, the labelled one;
    /// a mark on two steps keeps the coarser.
    #[test]
    fn grid_steps_are_nested_1_2_5() {
        assert_eq!(nice_step(30.0), 50.0);
        assert_eq!(nice_step(50.0), 50.0);
        assert_eq!(nice_step(0.13), 0.2);
        let marks = grid_125(GridInput {
            bounds: (400.0, 2000.0),
            base_step_size: 30.0,
        });
        let labelled: Vec<f64> = marks
            .iter()
            .filter(|m| m.step_size >= 500.0)
            .map(|m| m.value)
            .collect();
        assert_eq!(labelled, vec![500.0, 1000.0, 1500.0, 2000.0]);
        assert_eq!(marks.len(), 33, "every 50 rpm from 400 to 2000");
        let medium = marks.iter().filter(|m| m.step_size == 100.0).count();
        assert_eq!(
            medium,
            17 - 4,
            "every 100 rpm from 400 to 2000 but the 500s"
        );
    }
}
