//! The mismatch map of one station as an SVG heatmap: x the mean speed of the reference
//! (rpm), y the engine order, colour `z = (measured − simulated)/σ` clamped at ±10.
//!
//! The steady regimes and the long run share one panel: each recording a column at its
//! speed, side by side where speeds coincide (full and part load at the same speed), a
//! long run's time blocks split across its column in time order; its columns are numbered
//! as in the recordings table. Each run-up has its own panel of speed bins below, on the
//! same speed axis. Every cell has a hover title with its numbers.

use super::super::report::{MapCell, Report};
use super::super::svg::{Frame, colour_bar, diverging, escape, nice_ticks, sig, tenth};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// Colour scale limit of `z`.
pub const Z_LIMIT: f64 = 10.0;

const WIDTH: f64 = 760.0;
const LEFT: f64 = 74.0;
const PLOT_WIDTH: f64 = 640.0;
const SLOT_PX: f64 = 14.0;
const PANEL_GAP: f64 = 22.0;

/// One panel: a title and the cells of its recordings, each with its x extent in px.
struct Panel<'a> {
    title: String,
    /// (cell, left px, width px).
    cells: Vec<(&'a MapCell, f64, f64)>,
    /// Column numbers under the panel: (centre px, text).
    keys: Vec<(f64, String)>,
}

/// The SVG of `station`'s cells; `numbers` gives each recording's number in the
/// recordings table.
pub fn station_map(report: &Report, station: &str, numbers: &BTreeMap<&str, usize>) -> String {
    let cells: Vec<&MapCell> = report
        .mismatch_map
        .iter()
        .filter(|c| c.station == station && c.order.is_finite() && c.speed_rpm.is_finite())
        .collect();
    let mut orders: Vec<f64> = cells.iter().map(|c| c.order).collect();
    orders.sort_by(f64::total_cmp);
    orders.dedup();
    let (lo, hi) = cells
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
            (lo.min(c.speed_rpm), hi.max(c.speed_rpm))
        });
    // The speed axis spans the data and half a run-up bin (up to a tenth of the span)
    // either side; its ticks are the nice ones inside.
    let pad = if hi > lo { 0.05 * (hi - lo) } else { 50.0 };
    let x = [lo - pad, hi + pad];
    let mut ticks = nice_ticks(x[0], x[1], 6);
    ticks.values.retain(|v| (x[0]..=x[1]).contains(v));
    let row_px = (300.0 / orders.len().max(1) as f64).clamp(6.0, 13.0);
    let mut frame = Frame {
        left: LEFT,
        top: 0.0,
        width: PLOT_WIDTH,
        height: row_px * orders.len().max(1) as f64,
        x,
        y: [0.0, 1.0],
    };
    let panels = panels(report, &cells, &frame, numbers);
    let mut out = String::new();
    let mut top = 0.0;
    for panel in &panels {
        top += PANEL_GAP;
        let _ = write!(
            out,
            r##"<text class="panel" x="{LEFT:.1}" y="{:.1}">{}</text>"##,
            top - 6.0,
            escape(&panel.title)
        );
        frame.top = top;
        draw_panel(&mut out, panel, &frame, &orders, row_px, &ticks.values);
        top += frame.height + if panel.keys.is_empty() { 0.0 } else { 14.0 };
    }
    // The speed axis under the last panel (and its column numbers).
    for &v in &ticks.values {
        let _ = write!(
            out,
            r##"<text x="{:.1}" y="{:.1}" text-anchor="middle">{}</text>"##,
            frame.px(v),
            top + 14.0,
            ticks.label(v)
        );
    }
    let _ = write!(
        out,
        r##"<text class="axis" x="{:.1}" y="{:.1}" text-anchor="middle">mean speed of the reference [rpm]</text>"##,
        LEFT + PLOT_WIDTH / 2.0,
        top + 30.0
    );
    colour_bar(
        &mut out,
        LEFT,
        top + 42.0,
        300.0,
        Z_LIMIT,
        "z = (measured − simulated)/σ, clamped at ±10",
    );
    let height = top + 72.0;
    format!(
        r##"<svg class="map" data-station="{}" xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height:.0}" viewBox="0 0 {WIDTH} {height:.0}" role="img"><title>Mismatch map of {}</title>{out}</svg>"##,
        escape(station),
        escape(station)
    )
}

/// The panels: steady regimes and long runs together, then each run-up.
fn panels<'a>(
    report: &Report,
    cells: &[&'a MapCell],
    frame: &Frame,
    numbers: &BTreeMap<&str, usize>,
) -> Vec<Panel<'a>> {
    let mut labels: Vec<&str> = Vec::new();
    for c in cells {
        if !labels.contains(&c.recording.as_str()) {
            labels.push(&c.recording);
        }
    }
    let of = |label: &str| -> Vec<&'a MapCell> {
        cells
            .iter()
            .copied()
            .filter(|c| c.recording == label)
            .collect()
    };
    let station_span = frame.x[1] - frame.x[0];
    let (sweeps, points): (Vec<&str>, Vec<&str>) =
        labels.iter().partition(|&&label| {
            match report.recordings.iter().find(|r| r.label == label) {
                Some(r) => r.kind == crate::recording::RunKind::RunUp.as_str(),
                None => {
                    let own = of(label);
                    let (lo, hi) = own.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, c| {
                        (a.0.min(c.speed_rpm), a.1.max(c.speed_rpm))
                    });
                    hi - lo > 0.05 * station_span
                }
            }
        });
    let mut panels = Vec::new();
    if !points.is_empty() {
        panels.push(point_panel(&points, &of, frame, numbers));
    }
    for label in sweeps {
        let own = of(label);
        let mut speeds: Vec<f64> = own.iter().map(|c| c.speed_rpm).collect();
        speeds.sort_by(f64::total_cmp);
        speeds.dedup();
        let mut gaps: Vec<f64> = speeds.windows(2).map(|w| w[1] - w[0]).collect();
        gaps.sort_by(f64::total_cmp);
        let bin_rpm = gaps
            .get(gaps.len() / 2)
            .copied()
            .unwrap_or(0.02 * station_span);
        let cells = own
            .iter()
            .map(|&c| {
                let left = frame.px(c.speed_rpm - bin_rpm / 2.0);
                (
                    c,
                    left,
                    (frame.px(c.speed_rpm + bin_rpm / 2.0) - left).max(1.0),
                )
            })
            .collect();
        let number = numbers
            .get(label)
            .map_or(String::new(), |n| format!(" [{n}]"));
        panels.push(Panel {
            title: format!("{label}{number}: speed bins"),
            cells,
            keys: Vec::new(),
        });
    }
    panels
}

/// Steady regimes and long runs: a column per recording at its mean speed, side by side
/// where they would overlap.
fn point_panel<'a>(
    points: &[&str],
    of: &dyn Fn(&str) -> Vec<&'a MapCell>,
    frame: &Frame,
    numbers: &BTreeMap<&str, usize>,
) -> Panel<'a> {
    let mut columns: Vec<(f64, &str)> = points
        .iter()
        .map(|&label| {
            let own = of(label);
            let mean = own.iter().map(|c| c.speed_rpm).sum::<f64>() / own.len().max(1) as f64;
            (frame.px(mean), label)
        })
        .collect();
    columns.sort_by(|a, b| a.0.total_cmp(&b.0));
    // Clusters of columns laid side by side about their mean centre; merged until none
    // overlaps the next.
    let mut clusters: Vec<(f64, Vec<&str>)> =
        columns.iter().map(|&(px, l)| (px, vec![l])).collect();
    loop {
        let overlap = clusters.windows(2).position(|w| {
            let right = w[0].0 + w[0].1.len() as f64 * SLOT_PX / 2.0;
            let left = w[1].0 - w[1].1.len() as f64 * SLOT_PX / 2.0;
            right > left - 2.0
        });
        let Some(i) = overlap else { break };
        let (px_b, b) = clusters.remove(i + 1);
        let (px_a, a) = &mut clusters[i];
        let n = (a.len() + b.len()) as f64;
        *px_a = (*px_a * a.len() as f64 + px_b * b.len() as f64) / n;
        a.extend(b);
    }
    let mut cells = Vec::new();
    let mut keys = Vec::new();
    for (centre, labels) in &clusters {
        let start = centre - labels.len() as f64 * SLOT_PX / 2.0;
        for (i, &label) in labels.iter().enumerate() {
            let left = start + i as f64 * SLOT_PX;
            let own = of(label);
            let mut by_order: BTreeMap<u64, Vec<&MapCell>> = BTreeMap::new();
            for c in own {
                by_order.entry(c.order.to_bits()).or_default().push(c);
            }
            for group in by_order.values() {
                let w = (SLOT_PX - 1.0) / group.len() as f64;
                for (k, &c) in group.iter().enumerate() {
                    cells.push((c, left + 0.5 + k as f64 * w, w));
                }
            }
            let key = numbers.get(label).map_or("?".into(), |n| n.to_string());
            keys.push((left + SLOT_PX / 2.0, key));
        }
    }
    Panel {
        title: "steady regimes and long runs (columns numbered as in the recordings table)".into(),
        cells,
        keys,
    }
}

/// Draws a panel's order rows, cells and column numbers into `frame`.
fn draw_panel(
    out: &mut String,
    panel: &Panel,
    frame: &Frame,
    orders: &[f64],
    row_px: f64,
    speed_ticks: &[f64],
) {
    let row_of = |order: f64| orders.iter().position(|&q| q == order).unwrap_or(0);
    let label_every = if row_px >= 10.0 { 1 } else { 2 };
    for (i, q) in orders.iter().enumerate() {
        let y = frame.top + frame.height - (i as f64 + 0.5) * row_px;
        if i % label_every == 0 {
            let _ = write!(
                out,
                r##"<text x="{:.1}" y="{:.1}" text-anchor="end">{q}</text>"##,
                frame.left - 5.0,
                y + 3.5
            );
        }
    }
    let _ = write!(
        out,
        r##"<rect class="lane" x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}"/>"##,
        frame.left, frame.top, frame.width, frame.height
    );
    let bottom = frame.top + frame.height;
    for &v in speed_ticks {
        let px = frame.px(v);
        let _ = write!(
            out,
            r##"<line class="grid" x1="{px:.1}" y1="{:.1}" x2="{px:.1}" y2="{bottom:.1}"/><line class="tick" x1="{px:.1}" y1="{bottom:.1}" x2="{px:.1}" y2="{:.1}"/>"##,
            frame.top,
            bottom + 3.0
        );
    }
    for &(c, left, width) in &panel.cells {
        let top = frame.top + frame.height - (row_of(c.order) as f64 + 1.0) * row_px;
        let _ = write!(
            out,
            r##"<rect class="cell" x="{left:.2}" y="{top:.2}" width="{width:.2}" height="{:.2}" fill="{}"><title>{} · {} · order {} · {} rpm · {} Hz · z = {}</title></rect>"##,
            row_px - 0.5,
            diverging(c.z, Z_LIMIT),
            escape(&c.recording),
            escape(&c.station),
            c.order,
            tenth(c.speed_rpm),
            sig(c.order * c.speed_rpm / 60.0, 4),
            sig(c.z, 3)
        );
    }
    for (x, key) in &panel.keys {
        let _ = write!(
            out,
            r##"<text class="key" x="{x:.1}" y="{:.1}" text-anchor="middle">{}</text>"##,
            frame.top + frame.height + 11.0,
            escape(key)
        );
    }
    let _ = write!(
        out,
        r##"<text class="axis" transform="translate({:.1},{:.1}) rotate(-90)" text-anchor="middle">order</text>"##,
        frame.left - 34.0,
        frame.top + frame.height / 2.0
    );
}
