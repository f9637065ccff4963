//! `truth.toml`, the scorer's answer sheet of a case, which torsim never reads: the
//! effect, its form, parameters and place, the plain parameters' errors, the campaign's
//! measurement, what each recording exercised and how plainly the campaign shows the
//! effect, and why earlier draws of the seed were set aside.

use crate::draw::Case;
use crate::exercise::Exercise;
use crate::model_file::list;
use crate::visibility::Visibility;
use std::fmt::Write as _;

/// `truth.toml`: effect, form, parameters, place, errors, campaign, seed, and what each
/// recording exercised (`exercise`).
pub(crate) fn truth_toml(
    case: &Case,
    exercise: &[(String, Exercise)],
    visibility: Option<&Visibility>,
    unusable: &[String],
) -> String {
    let redrawn: Vec<String> = unusable
        .iter()
        .map(|u| format!("\"{}\"", u.replace('"', "'")))
        .collect();
    let mut s = format!(
        "# The truth of this benchtruth case; torsim never reads it.\nformat = 1\nseed = {}\ndraw = {}\nredrawn_because = [{}]\neffect = \"{}\"\nform = \"{}\"\nfirst_mode_damping = {}\nmodes_hz = [{}]\n",
        case.seed,
        case.attempt,
        redrawn.join(", "),
        case.class,
        case.form,
        case.zeta1,
        list(&case.modes_hz)
    );
    if let Some((key, ok)) = &case.place {
        let q: Vec<String> = ok.iter().map(|v| format!("\"{v}\"")).collect();
        let _ = writeln!(s, "place_key = \"{key}\"\nplace = [{}]", q.join(", "));
    }
    let _ = writeln!(
        s,
        "effect_detail = \"{}\"",
        format!("{:?}", case.effect).replace('"', "'")
    );
    s.push_str("\n[parameters]\n");
    for (k, v) in &case.params {
        let _ = writeln!(s, "{k} = {v}");
    }
    s.push_str("\n[parameter_errors]\n");
    for (k, v) in &case.errors {
        let _ = writeln!(s, "\"{k}\" = {v}");
    }
    let c = &case.campaign;
    let _ = writeln!(
        s,
        "\n[measurement]\nrate_hz = {}\nnoise_rpm = {}\nwobble = {}\nwobble_period_s = {}\nclock_start_s = {}",
        c.rate_hz, c.noise_rpm, c.wobble, c.wobble_period_s, c.clock_start_s
    );
    if !exercise.is_empty() {
        s.push_str("\n# What each recording exercised of the effect (benchtruth's exercise.rs).\n[exercise]\n");
        for (stem, e) in exercise {
            let _ = writeln!(s, "\"{stem}\" = {}", e.toml());
        }
    }
    if let Some(v) = visibility {
        let _ = writeln!(
            s,
            "\n# How plainly the campaign shows the effect (benchtruth's visibility.rs).\n[visibility]\nz_max = {}\nat = \"{}\"\nabove_3 = {}\nobservations = {}",
            v.z_max, v.at, v.above_3, v.observations
        );
    }
    s
}
