//! Coupling ratings in the Forced response tab (issue 16, [`torsim::ratings`]): the limit
//! lines of the selected rated stage on its torque and power-loss plots, and above the
//! plot a line for every limit a rated stage exceeds and every node whose IAS leaves the
//! linear model's range. The checks come from the simulation thread with the response.

use crate::gui::app::TorsimApp;
use crate::gui::views::plots::quantity::Quantity;
use crate::gui::views::plots::series::Series;
use egui::{Color32, RichText, Ui};
use torsim::model::CouplingRating;
use torsim::ratings::{CheckKind, LINEAR_IAS_SHARE, StageRating};

/// The colour of a limit line and of an exceeded limit.
const LIMIT: Color32 = Color32::from_rgb(235, 80, 70);
/// The colour of a limit exceeded only outside the operating range, and of T_KN's line.
const OUTSIDE: Color32 = Color32::from_rgb(240, 160, 60);
/// The colour of T_KW's line.
const VIBRATORY: Color32 = Color32::from_rgb(220, 90, 200);

fn stage(app: &TorsimApp, connection: usize) -> Option<&StageRating> {
    let ratings = app.results.ratings.as_ref()?;
    ratings
        .stages
        .iter()
        .find(|s| s.connection_index == connection)
}

fn flat(name: String, column: String, speeds: &[f64], value: f64) -> Option<Series> {
    let (&a, &b) = (speeds.first()?, speeds.last()?);
    Some(Series::new(name, column, vec![[a, value], [b, value]]))
}

/// The limit lines of `quantity` for the model connection `connection`, if it is rated:
/// on the torque plot T_KN/S_t (for the mean), T_Kmax/S_t (for the peak) and, for the
/// decisive order q, T_KW/(S_t·S_f(q·n/60)) (for that order's amplitude); on the power
/// loss plot P_KV at the ambient.
pub fn limit_series(app: &TorsimApp, quantity: Quantity, connection: usize) -> Vec<Series> {
    let (Some(s), Some(r)) = (stage(app, connection), app.results.response.as_ref()) else {
        return Vec::new();
    };
    let speeds = &r.speeds_rpm;
    let (rating, s_t) = (&s.rating, s.temperature_factor);
    let mut out = Vec::new();
    match quantity {
        Quantity::Torque => {
            out.extend(
                flat(
                    "T_KN / S_t (limit of the mean)".into(),
                    "T_KN / S_t [N·m]".into(),
                    speeds,
                    rating.rated_torque_nm / s_t,
                )
                .map(|l| l.color(OUTSIDE)),
            );
            if let Some(t_max) = rating.max_torque_nm {
                out.extend(
                    flat(
                        "T_Kmax / S_t (limit of the peak)".into(),
                        "T_Kmax / S_t [N·m]".into(),
                        speeds,
                        t_max / s_t,
                    )
                    .map(|l| l.color(LIMIT)),
                );
            }
            let decisive = s
                .worst(None)
                .into_iter()
                .find(|c| c.kind == CheckKind::VibratoryTorque)
                .and_then(|c| c.order);
            if let (Some(t_kw), Some(q)) = (rating.permissible_vibratory_torque_nm, decisive) {
                let points = speeds
                    .iter()
                    .map(|&n| {
                        let s_f = CouplingRating::frequency_factor(q * n / 60.0);
                        [n, t_kw / (s_t * s_f)]
                    })
                    .collect();
                out.push(
                    Series::new(
                        format!("T_KW / (S_t·S_f), order {q}"),
                        format!("T_KW / (S_t S_f) for order {q} [N·m]"),
                        points,
                    )
                    .color(VIBRATORY),
                );
            }
        }
        Quantity::PowerLoss => {
            if let Some(p) = rating.permissible_power_loss_at_ambient_w() {
                out.extend(
                    flat(
                        format!("P_KV at {:.0} °C ambient", rating.ambient_c),
                        "P_KV at the ambient [W]".into(),
                        speeds,
                        p,
                    )
                    .map(|l| l.color(LIMIT)),
                );
            }
        }
        Quantity::Ias => {}
    }
    out.into_iter().map(|l| l.width(1.5).dashed()).collect()
}

fn at(n: f64, q: Option<f64>) -> String {
    match q {
        Some(q) => format!("order {q} at {n:.0} rpm"),
        None => format!("{n:.0} rpm"),
    }
}

/// At most three lines, each with its details on hover: the limits rated stages exceed
/// in the operating range (red), those exceeded only outside it (orange), and the nodes
/// whose IAS leaves the linear range.
pub fn warnings_ui(app: &TorsimApp, ui: &mut Ui) {
    let Some(ratings) = app.results.ratings.as_ref() else {
        return;
    };
    let operating = app.model.operation.operating_range_rpm;
    let (mut inside, mut outside) = (Vec::new(), Vec::new());
    for s in &ratings.stages {
        let within = s.worst(operating);
        for w in s.worst(None).into_iter().filter(|w| w.utilisation > 1.0) {
            match within
                .iter()
                .find(|c| c.kind == w.kind && c.utilisation > 1.0)
            {
                Some(c) => inside.push(format!(
                    "{} {} {:.0} % ({})",
                    s.connection,
                    c.kind.limit_name(),
                    100.0 * c.utilisation,
                    at(c.speed_rpm, c.order)
                )),
                None => outside.push(format!(
                    "{} {} {:.0} % ({})",
                    s.connection,
                    w.kind.limit_name(),
                    100.0 * w.utilisation,
                    at(w.speed_rpm, w.order)
                )),
            }
        }
    }
    if !inside.is_empty() {
        let text = RichText::new(format!(
            "Ratings exceeded in the operating range (DIN 740-2): {}",
            inside.join("; ")
        ))
        .color(LIMIT);
        ui.add(egui::Label::new(text).wrap());
    }
    if !outside.is_empty() {
        ui.add(
            egui::Label::new(
                RichText::new(format!(
                    "{} rating(s) exceeded outside the operating range: pass there quickly, or \
                 at part load (hover for which)",
                    outside.len()
                ))
                .color(OUTSIDE),
            )
            .wrap(),
        )
        .on_hover_text(outside.join("\n"));
    }
    if let Some(worst) = ratings
        .beyond
        .iter()
        .max_by(|a, b| a.worst_share.total_cmp(&b.worst_share))
    {
        let lines: Vec<String> = ratings
            .beyond
            .iter()
            .map(|b| {
                format!(
                    "{}: up to {:.0} % at {:.0}–{:.0} rpm",
                    b.node,
                    100.0 * b.worst_share,
                    b.speeds_rpm[0],
                    b.speeds_rpm[1]
                )
            })
            .collect();
        ui.add(
            egui::Label::new(
                RichText::new(format!(
                    "Beyond the linear model: IAS above {:.0} % of the mean speed at {} node(s), \
                 up to {:.0} % ({}, {:.0}–{:.0} rpm); check it in the Time traces",
                    100.0 * LINEAR_IAS_SHARE,
                    ratings.beyond.len(),
                    100.0 * worst.worst_share,
                    worst.node,
                    worst.speeds_rpm[0],
                    worst.speeds_rpm[1]
                ))
                .weak(),
            )
            .wrap(),
        )
        .on_hover_text(lines.join("\n"));
    }
    for o in &ratings.outside_law {
        ui.add(egui::Label::new(RichText::new(o.to_string()).weak()).wrap());
    }
}
