//! A before/after overlay as an SVG line plot: the measured order amplitude as points with
//! ±σ error bars, the user's model dashed, the verdict's model solid, on nice-number axes.
//! Values that are not finite are left out (a line breaks there); series of unequal length
//! are drawn as far as each has an x.

use super::super::report::Overlay;
use super::super::svg::{Frame, escape, nice_ticks, path_data, sig};
use std::fmt::Write as _;

const WIDTH: f64 = 540.0;
const HEIGHT: f64 = 300.0;
const BEFORE: &str = "#d95f02";
const AFTER: &str = "#1f78b4";

/// The SVG of one overlay; `after_legend` is the legend of the verdict's model.
pub fn overlay_svg(o: &Overlay, after_legend: &str) -> String {
    let at = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(f64::NAN);
    let n = o.x.len();
    let sigma = |i: usize| {
        let s = at(&o.sigma, i);
        if s.is_finite() { s.abs() } else { 0.0 }
    };
    let (mut xs, mut ys) = (Vec::new(), Vec::new());
    for i in 0..n {
        let x = o.x[i];
        if !x.is_finite() {
            continue;
        }
        let m = at(&o.measured, i);
        let candidates = [
            m - sigma(i),
            m + sigma(i),
            at(&o.before, i),
            at(&o.after, i),
        ];
        let finite: Vec<f64> = candidates.into_iter().filter(|v| v.is_finite()).collect();
        if !finite.is_empty() {
            xs.push(x);
            ys.extend(finite);
        }
    }
    let range = |v: &[f64]| {
        v.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
                (lo.min(x), hi.max(x))
            })
    };
    let (x_lo, x_hi) = range(&xs);
    let (y_lo, y_hi) = range(&ys);
    let x_ticks = nice_ticks(x_lo, x_hi, 6);
    let y_ticks = nice_ticks(y_lo, y_hi, 5);
    let frame = Frame {
        left: 64.0,
        top: 30.0,
        width: WIDTH - 64.0 - 16.0,
        height: HEIGHT - 30.0 - 46.0,
        x: x_ticks.range(),
        y: y_ticks.range(),
    };
    let mut out = String::new();
    let y_label = format!("order {} amplitude [rpm]", o.order);
    frame.axes(&mut out, &x_ticks, &y_ticks, &o.x_label, &y_label);
    if xs.is_empty() {
        let _ = write!(
            out,
            r##"<text class="empty" x="{:.1}" y="{:.1}" text-anchor="middle">no data</text>"##,
            frame.left + frame.width / 2.0,
            frame.top + frame.height / 2.0
        );
    }
    for (series, colour, dash) in [
        (&o.before, BEFORE, " stroke-dasharray=\"6 4\""),
        (&o.after, AFTER, ""),
    ] {
        let d = path_data((0..n).map(|i| (frame.px(o.x[i]), frame.py(at(series, i)))));
        if !d.is_empty() {
            let _ = write!(
                out,
                r##"<path class="line" d="{d}" stroke="{colour}"{dash}/>"##
            );
        }
    }
    for i in 0..n {
        let (x, m) = (o.x[i], at(&o.measured, i));
        if !(x.is_finite() && m.is_finite()) {
            continue;
        }
        let (px, py) = (frame.px(x), frame.py(m));
        let s = sigma(i);
        let (top, bottom) = (frame.py(m + s), frame.py(m - s));
        let _ = write!(
            out,
            r##"<g class="measured"><title>{} = {}: measured {} ± {} rpm, before {} rpm, after {} rpm</title><line x1="{px:.1}" y1="{top:.1}" x2="{px:.1}" y2="{bottom:.1}"/><line x1="{:.1}" y1="{top:.1}" x2="{:.1}" y2="{top:.1}"/><line x1="{:.1}" y1="{bottom:.1}" x2="{:.1}" y2="{bottom:.1}"/><circle cx="{px:.1}" cy="{py:.1}" r="2.6"/></g>"##,
            escape(&o.x_label),
            sig(x, 5),
            sig(m, 4),
            sig(s, 2),
            sig(at(&o.before, i), 4),
            sig(at(&o.after, i), 4),
            px - 3.0,
            px + 3.0,
            px - 3.0,
            px + 3.0,
        );
    }
    legend(&mut out, frame.left, after_legend);
    format!(
        r##"<svg class="overlay" xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" viewBox="0 0 {WIDTH} {HEIGHT}" role="img"><title>{} · {} · order {}</title>{out}</svg>"##,
        escape(&o.recording),
        escape(&o.station),
        escape(&o.order)
    )
}

/// The legend above the plot area.
fn legend(out: &mut String, left: f64, after_legend: &str) {
    let y = 14.0;
    let _ = write!(
        out,
        r##"<g class="measured"><line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}"/><circle cx="{:.1}" cy="{y:.1}" r="2.6"/></g><text x="{:.1}" y="{:.1}">measured ± σ</text>"##,
        left + 6.0,
        y - 5.0,
        left + 6.0,
        y + 5.0,
        left + 6.0,
        left + 14.0,
        y + 4.0
    );
    let items = [
        (
            BEFORE,
            " stroke-dasharray=\"6 4\"",
            "before: your model".to_string(),
        ),
        (AFTER, "", after_legend.to_string()),
    ];
    let mut x = left + 110.0;
    for (colour, dash, text) in items {
        let _ = write!(
            out,
            r##"<line class="line" x1="{x:.1}" y1="{y:.1}" x2="{:.1}" y2="{y:.1}" stroke="{colour}"{dash}/><text x="{:.1}" y="{:.1}">{}</text>"##,
            x + 24.0,
            x + 30.0,
            y + 4.0,
            escape(&text)
        );
        x += 30.0 + 6.2 * text.chars().count() as f64 + 18.0;
    }
}
