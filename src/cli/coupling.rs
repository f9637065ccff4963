//! `torsim coupling MODEL [--frequency-hz F] [--temperature-c T] [--twist-deg X]`: each
//! rubber stage's dynamic stiffness and damping by the seed 000 law (a calculator).

use super::error::CliError;
use super::format::{emit, number, outln, print_json, table};
use super::input::load_model;
use serde_json::json;
use torsim::model::ConnectionKind;

/// Runs the command.
pub fn run(
    model_arg: &str,
    frequency_hz: Option<f64>,
    temperature_c: Option<f64>,
    twist_deg: f64,
    json: bool,
) -> Result<(), CliError> {
    let model = load_model(model_arg)?;
    for (name, v) in [
        ("--frequency-hz", frequency_hz),
        ("--temperature-c", temperature_c),
    ] {
        if v.is_some_and(|v| !v.is_finite()) {
            return Err(CliError::input(anyhow::anyhow!(
                "{name}: not a finite number"
            )));
        }
    }
    if frequency_hz.is_some_and(|f| f < 0.0) || !twist_deg.is_finite() {
        return Err(CliError::input(anyhow::anyhow!(
            "--frequency-hz must be ≥ 0 and --twist-deg finite"
        )));
    }
    let mut list = Vec::new();
    let mut rows = Vec::new();
    for c in &model.connections {
        let ConnectionKind::Rubber(stage) = &c.kind else {
            continue;
        };
        let t = temperature_c.unwrap_or(stage.temperature_c);
        let s = stage.state(frequency_hz, t, twist_deg.to_radians());
        for w in &s.warnings {
            eprintln!(
                "warning: `{}`: {} at {} is outside its range [{}, {}]; held at the end value",
                c.name,
                w.factor.key(),
                w.argument,
                w.range[0],
                w.range[1]
            );
        }
        let omega = frequency_hz.map(|f| std::f64::consts::TAU * f);
        let viscous = omega
            .filter(|w| *w > 0.0)
            .map(|w| s.stiffness_nm_per_rad * s.loss_factor / w);
        list.push(json!({
            "name": c.name,
            "stiffness_nm_per_rad": number(s.stiffness_nm_per_rad, "stiffness")?,
            "tangent_stiffness_nm_per_rad": number(s.tangent_stiffness_nm_per_rad, "tangent stiffness")?,
            "static_stiffness_nm_per_rad": number(s.static_stiffness_nm_per_rad, "static stiffness")?,
            "loss_factor": number(s.loss_factor, "loss factor")?,
            "psi": number(s.psi, "psi")?,
            "equivalent_viscous_nm_s_per_rad": viscous,
            "alpha_x": s.alpha_x, "alpha_x_tangent": s.alpha_x_tangent,
            "alpha_f": s.alpha_f, "alpha_tc": s.alpha_tc, "alpha_txi": s.alpha_txi,
            "frequency_hz": frequency_hz, "temperature_c": t, "twist_deg": twist_deg,
            "radial_deformation_mm": stage.radial_deformation_mm(twist_deg.to_radians()),
        }));
        rows.push(vec![
            c.name.clone(),
            format!("{:.1}", s.stiffness_nm_per_rad),
            format!("{:.1}", s.tangent_stiffness_nm_per_rad),
            format!("{:.4}", s.loss_factor),
            format!("{:.3}", s.psi),
            format!("{:.4}", s.alpha_x),
            format!("{:.4}", s.alpha_f),
            format!("{:.4}", s.alpha_tc),
            format!("{:.4}", s.alpha_txi),
            viscous.map_or("—".into(), |v| format!("{v:.2}")),
        ]);
    }
    if json {
        return print_json(&json!({ "couplings": list }));
    }
    let mut text = String::new();
    if rows.is_empty() {
        outln!(text, "{}: no rubber stages", model.name);
        return emit(&text);
    }
    outln!(
        text,
        "{} — seed 000 law at {}, twist {twist_deg}°",
        model.name,
        frequency_hz.map_or("static (α_f = 1)".into(), |f| format!("{f} Hz"))
    );
    let header = [
        "stage",
        "k [N·m/rad]",
        "k_tan [N·m/rad]",
        "ξ_T",
        "ψ_T",
        "α_x",
        "α_f",
        "α_Tc",
        "α_Tξ",
        "b_T [N·m·s/rad]",
    ];
    text += &table(&header.map(String::from), &rows);
    emit(&text)
}
