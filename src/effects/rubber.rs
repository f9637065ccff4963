//! Effects on a rubber coupling stage (seed 000): amplitude nonlinearity (eq. 1) and
//! frequency dependence (eq. 9); each takes `connection=<name>`, by default the first
//! rubber stage. Self-heating is in [`super::rubber_thermal`], hysteretic damping in place
//! of the user's viscous equivalent in [`super::hysteretic`].

use super::EffectError;
use super::effect::{EffectSpec, Params};
use super::truth::{Applied, mode_frequencies_hz};
use crate::model::{
    AmplitudeForm, AmplitudeSaturation, ConnectionKind, Model, Poly, RubberElements, RubberStage,
    RubberStiffness,
};

/// Seed 000 eq. 1: α_x(x) = 0.0152 x² + 0.0033 x + 1, x in mm.
pub const SEED_AMPLITUDE_POLY: [f64; 3] = [0.0152, 0.0033, 1.0];
/// The pitch diameter, m, on which a stage given by its stiffness is written as elements
/// for the amplitude law: 0.2.
pub const DEFAULT_PITCH_DIAMETER_M: f64 = 0.2;
/// The largest `a2` of eq. 1 the amplitude effect takes, per mm²: 1e4, the stiffness
/// doubled at 0.01 mm of element deformation. A bound per mm² follows the element's size:
/// the seed's 0.0152 /mm² belongs to elements deforming by millimetres; a stiff coupling
/// whose elements deform by a tenth of that stiffens as much with a hundred times the
/// coefficient (issue 14), so the bound is set by the smallest deformation that means
/// anything, not by the seed's elements.
pub const A2_MAX_PER_MM2: f64 = 1.0e4;
/// The largest `a1` of the amplitude law, /mm: 100, for the same reason as
/// [`A2_MAX_PER_MM2`] (a progressive law linear in the deformation, `a2` = 0, stiffens a
/// stage whose elements deform by 0.01 mm by 100 % at that bound); as much softening
/// below zero.
pub const A1_MAX_PER_MM: f64 = 100.0;
/// The largest `stiffening` s of the saturating amplitude law the effect takes: 3, a stage
/// four times as stiff once its elements bear on their housing.
pub const MAX_SATURATED_STIFFENING: f64 = 3.0;
/// Seed 000 eq. 9: α_f(f) = −0.000023 f² + 0.01519 f + 1, f in Hz (measured 50–300 Hz).
pub const SEED_FREQUENCY_POLY: [f64; 3] = [-0.000023, 0.01519, 1.0];

/// Index of the rubber stage `connection` names (default: the first rubber stage).
pub(super) fn stage_index(model: &Model, p: &mut Params) -> Result<usize, EffectError> {
    let first = model
        .connections
        .iter()
        .find(|c| matches!(c.kind, ConnectionKind::Rubber(_)))
        .map(|c| c.name.clone());
    let name = p.text("connection", first)?;
    model
        .connections
        .iter()
        .position(|c| c.name == name && matches!(c.kind, ConnectionKind::Rubber(_)))
        .ok_or_else(|| {
            p.bad(
                "connection",
                format!("`{name}` is no rubber stage of the model"),
            )
        })
}

/// The rubber stage of connection `j` (found by [`stage_index`]).
pub(super) fn stage_mut(model: &mut Model, j: usize) -> Result<&mut RubberStage, EffectError> {
    let name = model.connections[j].name.clone();
    match &mut model.connections[j].kind {
        ConnectionKind::Rubber(r) => Ok(r),
        _ => Err(EffectError::Input(format!(
            "connection `{name}` is no rubber stage"
        ))),
    }
}

/// Stage `j` of `model`, for a frequency law to be put on it: refused, naming parameter
/// `connection`, when it has one already (`frequency_poly`, `frequency_power_law` or
/// `frequency_zener`; the model allows one).
pub(super) fn stage_without_frequency_law<'m>(
    model: &'m mut Model,
    j: usize,
    p: &Params,
) -> Result<&'m mut RubberStage, EffectError> {
    let stage = stage_mut(model, j)?;
    if stage.frequency_poly.is_some()
        || stage.frequency_power_law.is_some()
        || stage.frequency_zener.is_some()
    {
        return Err(p.bad("connection", "the stage already has a frequency law"));
    }
    Ok(stage)
}

/// `coupling_amplitude_nonlinearity`: α_x(x) = a2·x² + a1·x + 1 (default seed 000 eq. 1),
/// or, with `saturation_mm` x_s given, the saturating law 1 + s·tanh((x/x_s)²) with
/// `stiffening` s (default 0.3, up to [`MAX_SATURATED_STIFFENING`];
/// [`crate::model::amplitude_saturation`]), on the whole stage (`form = whole`, default: the damping scales with it, eq. 13–15) or
/// on its elastic spring only (`form = elastic`, [`AmplitudeForm::Elastic`]).
/// A stage given by `stiffness` is first written as 8 elements, 4 per side, on pitch
/// diameter `pitch_diameter_m` (default 0.2 m) with the same static stiffness. `a2` is
/// taken up to [`A2_MAX_PER_MM2`], `a1` within ±[`A1_MAX_PER_MM`].
pub(crate) fn amplitude(model: &mut Model, spec: &EffectSpec) -> Result<Applied, EffectError> {
    let mut p = Params::new(
        spec,
        &[
            "connection",
            "a2",
            "a1",
            "pitch_diameter_m",
            "form",
            "stiffening",
            "saturation_mm",
        ],
    )?;
    let j = stage_index(model, &mut p)?;
    // Read only when given, so the seed form resolves to the same keys as before.
    let form = match spec.params.contains_key("form") {
        false => AmplitudeForm::Whole,
        true => {
            let key = p.text("form", None)?;
            AmplitudeForm::from_key(&key)
                .ok_or_else(|| p.bad("form", format!("`{key}`: expected whole or elastic")))?
        }
    };
    // One law, the saturating one or eq. 1's polynomial, and its words for the summary.
    let (saturation, poly, law) = match p.optional_number("saturation_mm", 1e-9, 1e3)? {
        Some(deformation_mm) => {
            if spec.params.contains_key("a2") || spec.params.contains_key("a1") {
                return Err(p.bad("saturation_mm", "give either a2/a1 or saturation_mm"));
            }
            let stiffening = p.number("stiffening", 0.3, 0.0, MAX_SATURATED_STIFFENING)?;
            let law = AmplitudeSaturation {
                stiffening,
                deformation_mm,
            };
            let words =
                format!(" and saturates: α_x = 1 + {stiffening}·tanh((x/{deformation_mm})²)");
            (Some(law), None, words)
        }
        None => {
            let a2 = p.number("a2", SEED_AMPLITUDE_POLY[0], 0.0, A2_MAX_PER_MM2)?;
            let a1 = p.number("a1", SEED_AMPLITUDE_POLY[1], -A1_MAX_PER_MM, A1_MAX_PER_MM)?;
            let poly = Poly {
                coeffs: [a2, a1, 1.0],
                range: None,
            };
            let words = format!(": α_x = {a2}·x² + {a1}·x + 1 (seed 000 eq. 1 form)");
            (None, Some(poly), words)
        }
    };
    let direct = match &stage_mut(model, j)?.stiffness {
        RubberStiffness::Direct(k) => Some(*k),
        RubberStiffness::Elements(_) => None,
    };
    if direct.is_none() && spec.params.contains_key("pitch_diameter_m") {
        return Err(p.bad("pitch_diameter_m", "the stage already has elements"));
    }
    if let Some(k) = direct {
        let d = p.number("pitch_diameter_m", DEFAULT_PITCH_DIAMETER_M, 0.02, 5.0)?;
        let mut e = RubberElements {
            count: 8,
            per_side: 4,
            pitch_diameter_m: d,
            radial_stiffness_n_per_m: 1.0,
        };
        e.radial_stiffness_n_per_m = k / e.torsional_stiffness_nm_per_rad();
        stage_mut(model, j)?.stiffness = RubberStiffness::Elements(e);
    }
    let stage = stage_mut(model, j)?;
    if stage.has_amplitude_law() {
        return Err(p.bad("connection", "the stage already has an amplitude law"));
    }
    stage.amplitude_saturation = saturation;
    stage.amplitude_poly = poly;
    stage.amplitude_form = form;
    let name = &model.connections[j].name;
    let what = match form {
        AmplitudeForm::Whole => "stiffness and damping",
        AmplitudeForm::Elastic => "elastic stiffness only, damping the user's",
    };
    let summary = format!(
        "rubber stage `{name}` stiffens with the element deformation x (mm){law} on its {what}"
    );
    Ok((p.resolved, summary))
}

/// `coupling_frequency_dependence`: the truth's α_f is seed 000 eq. 9 scaled by `scale`
/// (default 0.1) about `reference_hz`, where it equals the user's stiffness (default: the
/// user model's first mode, the frequency a user would have tuned the stiffness to):
/// `α_f(f) = 1 + scale·(g(f) − g(f_ref))`, g eq. 9, held beyond its measured 300 Hz.
/// `form` is `poly` (this, the default), `power_law` ([`super::rubber_power`]) or `zener`
/// ([`super::rubber_zener`]).
pub(crate) fn frequency(
    model: &mut Model,
    user: &Model,
    spec: &EffectSpec,
) -> Result<Applied, EffectError> {
    if spec.params.contains_key("form") {
        let form = spec.params.get("form").map(String::as_str);
        if form == Some(super::rubber_power::FORM) {
            return super::rubber_power::power_law(model, user, spec);
        }
        if form == Some(super::rubber_zener::FORM) {
            return super::rubber_zener::zener(model, user, spec);
        }
        if form != Some("poly") {
            return Err(EffectError::Input(format!(
                "effect `coupling_frequency_dependence`, parameter `form`: `{}`: expected \
                 poly, power_law or zener",
                form.unwrap_or_default()
            )));
        }
    }
    let mut p = Params::new(spec, &["connection", "form", "scale", "reference_hz"])?;
    if spec.params.contains_key("form") {
        p.text("form", None)?;
    }
    let j = stage_index(model, &mut p)?;
    let scale = p.number("scale", 0.1, 0.0, 1.0)?;
    let first_mode = mode_frequencies_hz(user)?.first().copied().unwrap_or(50.0);
    let f_ref = p.number("reference_hz", first_mode.min(300.0), 0.0, 300.0)?;
    let [b2, b1, b0] = SEED_FREQUENCY_POLY;
    let g_ref = (b2 * f_ref + b1) * f_ref + b0;
    let coeffs = [scale * b2, scale * b1, 1.0 + scale * (b0 - g_ref)];
    if coeffs[2] <= 0.0 {
        return Err(p.bad("scale", "makes the static stiffness ≤ 0"));
    }
    let stage = stage_without_frequency_law(model, j, &p)?;
    stage.frequency_poly = Some(Poly {
        coeffs,
        range: Some([0.0, 300.0]),
    });
    let at = |f: f64| (coeffs[0] * f + coeffs[1]) * f + coeffs[2];
    let summary = format!(
        "rubber stage `{}` stiffens with frequency: α_f = {:.4} at 0 Hz, 1 at {f_ref:.1} Hz, \
         {:.4} at 100 Hz, {:.4} from 300 Hz (seed 000 eq. 9 × {scale})",
        model.connections[j].name,
        at(0.0),
        at(100.0),
        at(300.0)
    );
    Ok((p.resolved, summary))
}
