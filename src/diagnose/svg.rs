//! Small helpers for the diagnosis page ([`super::html`]): escaping text for HTML and SVG,
//! numbers for a person, nice axis ticks, a plot frame with its axes, lines that break at
//! gaps, and the diverging colour scale of the mismatch map.

use std::fmt::Write as _;

/// `text` safe inside HTML and SVG, in element content and in quoted attributes.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// `value` with `digits` significant digits in plain decimal notation (scientific below
/// 1e-4 and from 1e7 on); `—` when it is not finite.
pub fn sig(value: f64, digits: usize) -> String {
    if !value.is_finite() {
        return "—".into();
    }
    if value == 0.0 {
        return "0".into();
    }
    let magnitude = value.abs().log10().floor();
    if !(-4.0..7.0).contains(&magnitude) {
        return format!("{:.*e}", digits.saturating_sub(1), value);
    }
    let decimals = (digits as f64 - 1.0 - magnitude).max(0.0) as usize;
    clean_zero(format!("{value:.decimals$}"))
}

/// `value` to 0.1 (a speed in rpm, a load in %), without the `.0` when whole; `—` when
/// not finite.
pub fn tenth(value: f64) -> String {
    if !value.is_finite() {
        "—".into()
    } else if (value - value.round()).abs() < 0.05 {
        clean_zero(format!("{value:.0}"))
    } else {
        clean_zero(format!("{value:.1}"))
    }
}

/// `"-0"`, `"-0.00"` → `"0"`, `"0.00"`.
fn clean_zero(text: String) -> String {
    match text.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => text,
    }
}

/// Axis ticks: multiples of a step of 1, 2 or 5 × 10ⁿ, the first at or below the data,
/// the last at or above.
#[derive(Debug, Clone, PartialEq)]
pub struct Ticks {
    /// Tick values, increasing.
    pub values: Vec<f64>,
    /// Their spacing.
    pub step: f64,
}

impl Ticks {
    /// The range the ticks span: `[first, last]`.
    pub fn range(&self) -> [f64; 2] {
        [
            self.values.first().copied().unwrap_or(0.0),
            self.values.last().copied().unwrap_or(1.0),
        ]
    }

    /// A tick's label with as many decimals as the step needs.
    pub fn label(&self, value: f64) -> String {
        let decimals = (-self.step.log10().floor()).max(0.0) as usize;
        clean_zero(format!("{value:.decimals$}"))
    }
}

/// Ticks covering `lo … hi` with about `target` intervals (3 to 2.5 × `target` + 1 ticks).
/// A range of zero width is widened by 10 % of its value (by 1 at 0); non-finite bounds
/// give `0 … 1`.
pub fn nice_ticks(lo: f64, hi: f64, target: usize) -> Ticks {
    let (mut lo, mut hi) = if lo.is_finite() && hi.is_finite() {
        (lo.min(hi), lo.max(hi))
    } else {
        (0.0, 1.0)
    };
    let size = lo.abs().max(hi.abs());
    if hi - lo <= 1e-9 * size || hi == lo {
        let pad = if size == 0.0 { 1.0 } else { 0.1 * size };
        lo -= pad;
        hi += pad;
    }
    let raw = (hi - lo) / target.max(1) as f64;
    let magnitude = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * magnitude)
        .find(|&s| s >= raw * (1.0 - 1e-12))
        .unwrap_or(10.0 * magnitude);
    let decimals = (-step.log10().floor()).max(0.0) as i32;
    let scale = 10f64.powi(decimals.min(15));
    let at = |k: f64| (k * step * scale).round() / scale;
    let mut first = (lo / step).floor();
    if at(first) > lo {
        first -= 1.0;
    }
    let mut last = (hi / step).ceil();
    if at(last) < hi {
        last += 1.0;
    }
    let values = (0..=(last - first) as usize)
        .map(|i| at(first + i as f64))
        .collect();
    Ticks { values, step }
}

/// A plot area in pixels and the data ranges it shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Left edge, px.
    pub left: f64,
    /// Top edge, px.
    pub top: f64,
    /// Width, px.
    pub width: f64,
    /// Height, px.
    pub height: f64,
    /// x at the left and right edges.
    pub x: [f64; 2],
    /// y at the bottom and top edges.
    pub y: [f64; 2],
}

impl Frame {
    /// Pixel column of `x`.
    pub fn px(&self, x: f64) -> f64 {
        self.left + (x - self.x[0]) / (self.x[1] - self.x[0]) * self.width
    }

    /// Pixel row of `y` (up is larger y).
    pub fn py(&self, y: f64) -> f64 {
        self.top + self.height - (y - self.y[0]) / (self.y[1] - self.y[0]) * self.height
    }

    /// Draws the box, grid lines and tick labels of both axes and the axis labels.
    pub fn axes(&self, out: &mut String, x: &Ticks, y: &Ticks, x_label: &str, y_label: &str) {
        let (right, bottom) = (self.left + self.width, self.top + self.height);
        for &v in &x.values {
            let px = self.px(v);
            let _ = write!(
                out,
                r##"<line class="grid" x1="{px:.1}" y1="{:.1}" x2="{px:.1}" y2="{bottom:.1}"/><text x="{px:.1}" y="{:.1}" text-anchor="middle">{}</text>"##,
                self.top,
                bottom + 14.0,
                escape(&x.label(v))
            );
        }
        for &v in &y.values {
            let py = self.py(v);
            let _ = write!(
                out,
                r##"<line class="grid" x1="{:.1}" y1="{py:.1}" x2="{right:.1}" y2="{py:.1}"/><text x="{:.1}" y="{:.1}" text-anchor="end">{}</text>"##,
                self.left,
                self.left - 5.0,
                py + 4.0,
                escape(&y.label(v))
            );
        }
        self.frame_and_labels(out, x_label, y_label);
    }

    /// Draws the box and the axis labels only.
    pub fn frame_and_labels(&self, out: &mut String, x_label: &str, y_label: &str) {
        let bottom = self.top + self.height;
        let mid_y = self.top + self.height / 2.0;
        let _ = write!(
            out,
            r##"<rect class="frame" x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}"/><text class="axis" x="{:.1}" y="{:.1}" text-anchor="middle">{}</text><text class="axis" transform="translate({:.1},{mid_y:.1}) rotate(-90)" text-anchor="middle">{}</text>"##,
            self.left,
            self.top,
            self.width,
            self.height,
            self.left + self.width / 2.0,
            bottom + 32.0,
            escape(x_label),
            self.left - 44.0,
            escape(y_label)
        );
    }
}

/// An SVG path through the points in pixels, broken where a point is not finite; empty
/// when nothing is drawable.
pub fn path_data(points: impl Iterator<Item = (f64, f64)>) -> String {
    let mut d = String::new();
    let mut pen_down = false;
    for (x, y) in points {
        if x.is_finite() && y.is_finite() {
            let _ = write!(d, "{}{x:.1},{y:.1}", if pen_down { " L" } else { " M" });
            pen_down = true;
        } else {
            pen_down = false;
        }
    }
    d.trim_start().to_string()
}

/// ColorBrewer's RdBu (11 classes), blue (negative) to red (positive).
const RDBU: [[u8; 3]; 11] = [
    [0x05, 0x30, 0x61],
    [0x21, 0x66, 0xac],
    [0x43, 0x93, 0xc3],
    [0x92, 0xc5, 0xde],
    [0xd1, 0xe5, 0xf0],
    [0xf7, 0xf7, 0xf7],
    [0xfd, 0xdb, 0xc7],
    [0xf4, 0xa5, 0x82],
    [0xd6, 0x60, 0x4d],
    [0xb2, 0x18, 0x2b],
    [0x67, 0x00, 0x1f],
];

/// Colour of a value not finite.
pub const NO_COLOUR: &str = "#9e9e9e";

/// `#rrggbb` of `value` on a diverging scale clamped at `±limit`: blue below 0, white
/// at 0, red above.
pub fn diverging(value: f64, limit: f64) -> String {
    if !value.is_finite() {
        return NO_COLOUR.into();
    }
    let t = ((value / limit).clamp(-1.0, 1.0) + 1.0) * 5.0;
    let i = (t.floor() as usize).min(9);
    let f = t - i as f64;
    let channel = |c: usize| {
        let (a, b) = (f64::from(RDBU[i][c]), f64::from(RDBU[i + 1][c]));
        (a + (b - a) * f).round() as u8
    };
    format!("#{:02x}{:02x}{:02x}", channel(0), channel(1), channel(2))
}

/// Draws a horizontal colour bar for [`diverging`] at (`left`, `top`), `width` px wide,
/// with ticks at every `tick` from `−limit` to `limit` and `label` under it.
pub fn colour_bar(out: &mut String, left: f64, top: f64, width: f64, limit: f64, label: &str) {
    const STEPS: usize = 40;
    let w = width / STEPS as f64;
    for i in 0..STEPS {
        let value = -limit + (i as f64 + 0.5) / STEPS as f64 * 2.0 * limit;
        let _ = write!(
            out,
            r##"<rect class="bar" x="{:.1}" y="{top:.1}" width="{:.2}" height="10" fill="{}"/>"##,
            left + i as f64 * w,
            w + 0.3,
            diverging(value, limit)
        );
    }
    let ticks = nice_ticks(-limit, limit, 4);
    for &v in ticks.values.iter().filter(|v| v.abs() <= limit) {
        let x = left + (v + limit) / (2.0 * limit) * width;
        let sign = if v > 0.0 { "+" } else { "" };
        let _ = write!(
            out,
            r##"<line class="tick" x1="{x:.1}" y1="{:.1}" x2="{x:.1}" y2="{:.1}"/><text x="{x:.1}" y="{:.1}" text-anchor="middle">{sign}{}</text>"##,
            top + 10.0,
            top + 13.0,
            top + 24.0,
            ticks.label(v)
        );
    }
    let _ = write!(
        out,
        r##"<text x="{:.1}" y="{:.1}">{}</text>"##,
        left + width + 10.0,
        top + 9.0,
        escape(label)
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes_markup() {
        assert_eq!(
            escape(r#"<a & "b">'"#),
            "&lt;a &amp; &quot;b&quot;&gt;&#39;"
        );
    }

    #[test]
    fn ticks_are_nice_and_cover_the_data() {
        let ranges = [
            (0.0, 1.0),
            (1000.0, 6000.0),
            (3.2, 3.27),
            (-0.4, 12.3),
            (5.0, 5.0),
            (0.0, 0.0),
            (0.001, 0.0013),
            (2987.5, 3012.5),
            (-7.0, -6.5),
            (1.0e-6, 3.0e-6),
        ];
        for (lo, hi) in ranges {
            let t = nice_ticks(lo, hi, 5);
            let [first, last] = t.range();
            assert!(first <= lo && last >= hi, "{lo} … {hi}: {:?}", t.values);
            assert!(last > first, "{lo} … {hi}: {:?}", t.values);
            let mantissa = t.step / 10f64.powf(t.step.log10().floor());
            assert!(
                [1.0, 2.0, 5.0].iter().any(|m| (mantissa - m).abs() < 1e-9),
                "{lo} … {hi}: step {}",
                t.step
            );
            for v in &t.values {
                let k = v / t.step;
                assert!(
                    (k - k.round()).abs() < 1e-6,
                    "{v} is not a multiple of {}",
                    t.step
                );
            }
            assert!((3..=13).contains(&t.values.len()), "{:?}", t.values);
            // Less than one tick interval beyond the data on each side (a range of zero
            // width is widened first).
            if hi > lo {
                assert!(first > lo - t.step && last < hi + t.step, "{:?}", t.values);
            }
        }
        let t = nice_ticks(1000.0, 6000.0, 5);
        assert_eq!(t.values, [1000.0, 2000.0, 3000.0, 4000.0, 5000.0, 6000.0]);
        assert_eq!(t.label(3000.0), "3000");
        let t = nice_ticks(3.2, 3.27, 5);
        assert_eq!(t.step, 0.02);
        assert_eq!(t.label(3.24), "3.24");
        let t = nice_ticks(f64::NAN, 3.0, 5);
        assert_eq!(t.range(), [0.0, 1.0]);
    }

    #[test]
    fn numbers_for_a_person() {
        assert_eq!(sig(12.345, 3), "12.3");
        assert_eq!(sig(0.041_23, 2), "0.041");
        assert_eq!(sig(3000.0, 4), "3000");
        assert_eq!(sig(-0.0001, 2), "-0.00010");
        assert_eq!(sig(f64::NAN, 3), "—");
        assert_eq!(sig(2.5e-7, 2), "2.5e-7");
        assert_eq!(sig(-0.0004, 1), "-0.0004");
        assert_eq!(tenth(2999.98), "3000");
        assert_eq!(tenth(1234.56), "1234.6");
        assert_eq!(tenth(-0.01), "0");
    }

    #[test]
    fn diverging_scale_is_white_at_zero_and_clamped() {
        assert_eq!(diverging(0.0, 10.0), "#f7f7f7");
        assert_eq!(diverging(10.0, 10.0), "#67001f");
        assert_eq!(diverging(55.0, 10.0), "#67001f");
        assert_eq!(diverging(-10.0, 10.0), "#053061");
        assert_eq!(diverging(f64::NAN, 10.0), NO_COLOUR);
        assert_eq!(diverging(2.0, 10.0), "#fddbc7");
    }

    #[test]
    fn paths_break_at_gaps() {
        let d = path_data([(1.0, 2.0), (3.0, f64::NAN), (5.0, 6.0), (7.0, 8.0)].into_iter());
        assert_eq!(d, "M1.0,2.0 M5.0,6.0 L7.0,8.0");
        assert_eq!(path_data(std::iter::empty()), "");
    }
}
