//! `torsim coupling MODEL [--frequency-hz F] [--temperature-c T] [--twist-deg X]`: each
//! rubber stage's dynamic stiffness and damping by the seed 000 law (a calculator).
//!
//! Flags out of range and a correction factor ≤ 0 at the point asked for are refused
//! (exit 2, issue 13); the JSON leaves out keys that do not apply instead of writing null.

use super::error::CliError;
use super::format::{emit, number, outln, print_json, table};
use super::input::load_model;
use super::values;
use serde_json::json;
use torsim::model::ConnectionKind;
use torsim::model::rubber::Factor;
use torsim::physics::PhysicsError;

/// Runs the command.
pub fn run(
    model_arg: &str,
    frequency_hz: Option<f64>,
    temperature_c: Option<f64>,
    twist_deg: f64,
    json: bool,
) -> Result<(), CliError> {
    let frequency_hz = frequency_hz
        .map(|f| values::frequency_hz("--frequency-hz", f))
        .transpose()?;
    let temperature_c = temperature_c
        .map(|t| values::temperature_c("--temperature-c", t))
        .transpose()?;
    let twist_deg = values::twist_deg("--twist-deg", twist_deg)?;
    let model = load_model(model_arg)?;
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
        match (s.non_positive_factor(), frequency_hz) {
            (Some((Factor::Frequency, value)), Some(frequency_hz)) => {
                return Err(PhysicsError::FrequencyFactor {
                    connection: c.name.clone(),
                    frequency_hz,
                    value,
                }
                .into());
            }
            (Some((factor, value)), _) => {
                return Err(PhysicsError::Factor {
                    connection: c.name.clone(),
                    key: factor.key(),
                    value,
                }
                .into());
            }
            (None, _) => {}
        }
        let omega = frequency_hz.map(|f| std::f64::consts::TAU * f);
        let viscous = omega
            .filter(|w| *w > 0.0)
            .map(|w| s.stiffness_nm_per_rad * s.loss_factor / w);
        let mut entry = json!({
            "name": c.name,
            "stiffness_nm_per_rad": number(s.stiffness_nm_per_rad, "stiffness")?,
            "tangent_stiffness_nm_per_rad": number(s.tangent_stiffness_nm_per_rad, "tangent stiffness")?,
            "static_stiffness_nm_per_rad": number(s.static_stiffness_nm_per_rad, "static stiffness")?,
            "loss_factor": number(s.loss_factor, "loss factor")?,
            "psi": number(s.psi, "psi")?,
            "alpha_x": number(s.alpha_x, "alpha_x")?,
            "alpha_x_tangent": number(s.alpha_x_tangent, "alpha_x_tangent")?,
            "alpha_f": number(s.alpha_f, "alpha_f")?,
            "alpha_tc": number(s.alpha_tc, "alpha_tc")?,
            "alpha_txi": number(s.alpha_txi, "alpha_txi")?,
            "temperature_c": number(t, "temperature")?,
            "twist_deg": number(twist_deg, "twist")?,
            "radial_deformation_mm": number(stage.radial_deformation_mm(twist_deg.to_radians()), "radial deformation")?,
        });
        // Keys that do not apply are left out rather than null (issue 13): the frequency
        // of a static evaluation, the viscous equivalent at 0 Hz.
        if let Some(f) = frequency_hz {
            entry["frequency_hz"] = number(f, "frequency")?;
        }
        if let Some(b) = viscous {
            entry["equivalent_viscous_nm_s_per_rad"] = number(b, "equivalent viscous damping")?;
        }
        list.push(entry);
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

#[cfg(test)]
mod tests {
    use super::run;

    /// The message and exit code of a refused run.
    fn refused(model: &str, f: Option<f64>, t: Option<f64>, twist: f64) -> (u8, String) {
        match run(model, f, t, twist, true) {
            Ok(()) => panic!("expected a refusal"),
            Err(e) => (e.code, e.error.to_string()),
        }
    }

    #[test]
    fn nonsense_flags_are_refused_with_the_flag_and_range() {
        let rig = "preset:test-rig-mod1";
        let (code, e) = refused(rig, None, Some(-300.0), 0.0);
        assert_eq!(code, 2);
        assert!(e.starts_with("--temperature-c -300: "), "{e}");
        assert!(e.contains("-100 … 300 °C"), "{e}");
        for f in [-1.0, f64::NAN, 1e300] {
            let (code, e) = refused(rig, Some(f), None, 0.0);
            assert_eq!(code, 2);
            assert!(e.starts_with("--frequency-hz "), "{e}");
        }
        let (code, e) = refused(rig, None, None, f64::NAN);
        assert_eq!((code, e.starts_with("--twist-deg NaN")), (2, true), "{e}");
    }

    #[test]
    fn a_frequency_factor_at_or_below_zero_is_refused() {
        let text = torsim::model::presets::preset("test-rig-mod1")
            .map(|p| {
                p.text.replacen(
                    "psi = 0.3257",
                    "psi = 0.3257\nfrequency_poly = [0, -0.02, 1]",
                    1,
                )
            })
            .unwrap();
        // Removed when dropped.
        let path = tempfile::Builder::new()
            .prefix("torsim-negf-")
            .suffix(".toml")
            .tempfile()
            .unwrap()
            .into_temp_path();
        std::fs::write(&path, text).unwrap();
        let (code, e) = refused(&path.display().to_string(), Some(100.0), None, 0.0);
        assert_eq!(code, 2);
        assert!(
            e.contains("rubber stage `b`: `frequency_poly` gives α_f = -1.0000 at 100.0 Hz"),
            "{e}"
        );
    }
}
