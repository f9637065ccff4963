//! Exports: the data a plot shows as CSV ([`PlotData`], [`csv_text`]) and the window as
//! PNG ([`png_bytes`]). The file dialog, the encoding and the writing run on their own
//! thread (as the model dialogs of [`crate::gui::files`] do); the outcome comes back over a
//! channel and shows in the status line.

use crate::gui::app::TorsimApp;
use crate::gui::background::{self, Lost, Pending};
use crate::gui::overwrite::PendingWrite;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::sync::Arc;

/// What a plot shows, for export: every series with its points.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PlotData {
    /// Plot title; also the suggested file name.
    pub title: String,
    /// The x axis with its unit (`engine speed [rpm]`), the first CSV column.
    pub x_label: String,
    /// Names of the x values `0, 1, 2, …` (the nodes of a mode shape), written as a second
    /// column; empty when x is a plain number.
    pub x_names: Vec<String>,
    /// Series: column name with its unit, and its points `[x, y]`.
    pub columns: Vec<(String, Vec<[f64; 2]>)>,
}

/// A CSV field, quoted when it holds a comma, a quote or a line break.
fn field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// The CSV of `data`: a header (x label, names column if any, one column per series),
/// then one row per x value. When every series has the same x values the rows follow
/// them; otherwise the rows are the sorted union of all x values and a series without a
/// point at some x leaves its cell empty. Numbers are written in full precision.
pub fn csv_text(data: &PlotData) -> String {
    let mut out = field(&data.x_label);
    if !data.x_names.is_empty() {
        out.push_str(",name");
    }
    for (name, _) in &data.columns {
        out.push(',');
        out.push_str(&field(name));
    }
    out.push('\n');
    let first: Vec<f64> = data
        .columns
        .first()
        .map(|(_, p)| p.iter().map(|p| p[0]).collect())
        .unwrap_or_default();
    let shared = data
        .columns
        .iter()
        .all(|(_, p)| p.len() == first.len() && p.iter().zip(&first).all(|(a, &b)| a[0] == b));
    let xs: Vec<f64> = if shared {
        first
    } else {
        let mut xs: Vec<f64> = data
            .columns
            .iter()
            .flat_map(|(_, p)| p.iter().map(|p| p[0]))
            .collect();
        xs.sort_by(f64::total_cmp);
        xs.dedup();
        xs
    };
    // Each series in x order, with a cursor: linear in the rows, not rows × points.
    let sorted: Vec<Vec<[f64; 2]>> = data
        .columns
        .iter()
        .map(|(_, p)| {
            let mut p = p.clone();
            if !shared {
                p.sort_by(|a, b| a[0].total_cmp(&b[0]));
            }
            p
        })
        .collect();
    let mut cursors = vec![0usize; sorted.len()];
    for (row, &x) in xs.iter().enumerate() {
        let _ = write!(out, "{x}");
        if !data.x_names.is_empty() {
            let name = (x >= 0.0 && x.fract() == 0.0)
                .then(|| data.x_names.get(x as usize))
                .flatten();
            out.push(',');
            out.push_str(&field(name.map_or("", String::as_str)));
        }
        for (points, cursor) in sorted.iter().zip(&mut cursors) {
            out.push(',');
            let y = if shared {
                points.get(row).map(|p| p[1])
            } else {
                while points.get(*cursor).is_some_and(|p| p[0] < x) {
                    *cursor += 1;
                }
                points.get(*cursor).filter(|p| p[0] == x).map(|p| p[1])
            };
            if let Some(y) = y {
                let _ = write!(out, "{y}");
            }
        }
        out.push('\n');
    }
    out
}

/// A PNG (8-bit RGBA) of a screenshot.
pub fn png_bytes(image: &egui::ColorImage) -> Result<Vec<u8>, String> {
    let [w, h] = image.size;
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, w as u32, h as u32);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| e.to_string())?;
    let rgba: Vec<u8> = image
        .pixels
        .iter()
        .flat_map(|c| c.to_srgba_unmultiplied())
        .collect();
    writer.write_image_data(&rgba).map_err(|e| e.to_string())?;
    writer.finish().map_err(|e| e.to_string())?;
    Ok(bytes)
}

/// How an export ended: `None` when the dialog was cancelled.
type Outcome = Option<Result<PathBuf, String>>;

/// Exports in progress.
#[derive(Default)]
pub struct Exports {
    /// A CSV dialog: the path chosen and the data (written once checked against the
    /// open files, [`crate::gui::overwrite`]).
    csv: Option<Pending<Option<(PathBuf, PlotData)>>>,
    /// The PNG dialog; the screenshot is taken once it has closed.
    png_path: Option<Pending<Option<PathBuf>>>,
    /// The PNG encoding and writing.
    png: Option<Pending<Outcome>>,
}

/// A file name from a plot title: letters, digits, `-` and `_`.
fn file_name(title: &str, extension: &str) -> String {
    let stem: String = title
        .chars()
        .map(|c| {
            if c.is_alphanumeric() || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("{}.{extension}", stem.trim_matches('_'))
}

/// Runs `work` (a dialog, writing) on a named thread ([`background::spawn`]); a thread
/// that cannot start answers [`Lost`], which [`poll`] reports.
fn on_thread<T: Send + 'static>(
    name: &str,
    ctx: &egui::Context,
    work: impl FnOnce() -> T + Send + 'static,
) -> Pending<T> {
    let (work_later, pending) = background::deferred();
    work_later.spawn(name, ctx, work);
    pending
}

/// Asks where to save `data` as CSV, off the GUI thread; [`poll`] writes it there.
pub fn export_csv(exports: &mut Exports, ctx: &egui::Context, data: PlotData) {
    let default = file_name(&data.title, "csv");
    exports.csv = Some(on_thread("torsim-export-csv", ctx, move || {
        let path = rfd::FileDialog::new()
            .add_filter("CSV", &["csv"])
            .set_file_name(default)
            .save_file()?;
        Some((path, data))
    }));
}

/// Asks where to save the window as PNG; the screenshot follows when the dialog closes.
pub fn export_png(exports: &mut Exports, ctx: &egui::Context) {
    exports.png_path = Some(on_thread("torsim-export-png", ctx, || {
        rfd::FileDialog::new()
            .add_filter("PNG image", &["png"])
            .set_file_name("torsim.png")
            .save_file()
    }));
}

/// Takes a screenshot of the next frame and writes it to `path` as PNG (encoding and
/// writing on a thread).
pub fn screenshot_to(exports: &mut Exports, ctx: &egui::Context, path: PathBuf) {
    let (write_later, pending) = background::deferred();
    exports.png = Some(pending);
    let repaint = ctx.clone();
    ctx.request_screenshot(move |image: Arc<egui::ColorImage>| {
        write_later.spawn("torsim-export-png", &repaint, move || {
            let written = png_bytes(&image).and_then(|bytes| {
                torsim::files::write_atomic(&path, bytes)
                    .map_err(|e| format!("could not write {}: {e}", path.display()))
            });
            Some(written.map(|()| path))
        });
    });
}

/// Takes finished exports and reports them in the status line.
pub fn poll(app: &mut TorsimApp, ctx: &egui::Context) {
    let failed = || Some(Err("the export thread ended without an answer".to_string()));
    let report = |outcome: Outcome, what: &str, status: &mut String| match outcome {
        Some(Ok(path)) => *status = format!("exported {what} to {}", path.display()),
        Some(Err(e)) => *status = e,
        None => {}
    };
    // Issue 13: a chosen path that is an open file is written only once the user agrees.
    match background::take(&mut app.exports.csv) {
        Some(Ok(Some((path, data)))) => {
            crate::gui::overwrite::request(app, ctx, PendingWrite::PlotCsv(path, data))
        }
        Some(Err(Lost)) => report(failed(), "", &mut app.status),
        _ => {}
    }
    match background::take(&mut app.exports.png_path) {
        Some(Ok(Some(path))) => crate::gui::overwrite::request(app, ctx, PendingWrite::Png(path)),
        Some(Err(Lost)) => report(failed(), "", &mut app.status),
        _ => {}
    }
    if let Some(answer) = background::take(&mut app.exports.png) {
        report(
            answer.unwrap_or_else(|Lost| failed()),
            "the window",
            &mut app.status,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Series on one grid give one row per point; series on different grids give the
    /// union of x with empty cells; names are quoted when they hold a comma.
    #[test]
    fn csv_has_a_header_with_units_and_one_row_per_x() {
        let data = PlotData {
            title: "t".into(),
            x_label: "engine speed [rpm]".into(),
            x_names: Vec::new(),
            columns: vec![
                ("mode 1 [Hz]".into(), vec![[400.0, 26.0], [500.0, 26.0]]),
                ("order 3 [Hz]".into(), vec![[400.0, 20.0], [500.0, 25.0]]),
            ],
        };
        assert_eq!(
            csv_text(&data),
            "engine speed [rpm],mode 1 [Hz],order 3 [Hz]\n400,26,20\n500,26,25\n"
        );
        let data = PlotData {
            columns: vec![
                ("a, b [W]".into(), vec![[1.0, 0.5], [2.0, 0.25]]),
                ("c [W]".into(), vec![[1.5, 3.0]]),
            ],
            ..data
        };
        assert_eq!(
            csv_text(&data),
            "engine speed [rpm],\"a, b [W]\",c [W]\n1,0.5,\n1.5,,3\n2,0.25,\n"
        );
        let shape = PlotData {
            title: "mode 1".into(),
            x_label: "node".into(),
            x_names: vec!["crank".into(), "flywheel".into()],
            columns: vec![("mode 1 [-]".into(), vec![[0.0, -0.1], [1.0, 1.0]])],
        };
        assert_eq!(
            csv_text(&shape),
            "node,name,mode 1 [-]\n0,crank,-0.1\n1,flywheel,1\n"
        );
        assert_eq!(
            file_name("Campbell: cng-genset", "csv"),
            "Campbell__cng-genset.csv"
        );
    }

    /// The PNG decodes to the screenshot's size and pixels.
    #[test]
    fn png_round_trips() {
        let mut image = egui::ColorImage::filled([3, 2], egui::Color32::from_rgb(10, 20, 30));
        image.pixels[4] = egui::Color32::from_rgb(200, 100, 0);
        let bytes = png_bytes(&image).unwrap();
        let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        let mut reader = decoder.read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buf).unwrap();
        assert_eq!((info.width, info.height), (3, 2));
        assert_eq!(&buf[16..20], &[200, 100, 0, 255]);
        assert_eq!(&buf[0..4], &[10, 20, 30, 255]);
    }
}
