//! `coupling_frequency_dependence` with `form = power_law` (issue 14): the stage follows
//! a causal power law, storage `(f/f_ref)^n` with the loss factor `tan(nπ/2)` that
//! Kramers–Kronig ties to it ([`crate::model::frequency_law`]). The default form (seed
//! 000 eq. 9, [`super::rubber::frequency`]) stiffens the storage only and keeps ψ, which no
//! causal material does.

use super::EffectError;
use super::effect::{EffectSpec, Params};
use super::rubber::{stage_index, stage_without_frequency_law};
use super::truth::{Applied, mode_frequencies_hz};
use crate::model::{Model, PowerLaw};

/// The `form` key's value of this form.
pub const FORM: &str = "power_law";

/// The largest exponent taken, 0.5: loss factor tan(π/4) = 1, the middle of an
/// elastomer's glass transition; a coupling's rubber runs in its rubbery region well below.
pub const MAX_EXPONENT: f64 = 0.5;

/// Applies the causal power law of `exponent` `n` (default 0.1) about `reference_hz`
/// (default: the user model's first mode, where the user's stiffness was tuned, as for
/// the default form) to stage `connection`.
pub(crate) fn power_law(
    model: &mut Model,
    user: &Model,
    spec: &EffectSpec,
) -> Result<Applied, EffectError> {
    let mut p = Params::new(spec, &["connection", "form", "exponent", "reference_hz"])?;
    p.text("form", Some(FORM.into()))?;
    let j = stage_index(model, &mut p)?;
    let exponent = p.number("exponent", 0.1, 0.0, MAX_EXPONENT)?;
    let first_mode = mode_frequencies_hz(user)?.first().copied().unwrap_or(50.0);
    let reference_hz = p.number("reference_hz", first_mode.max(1.0), 0.1, 1.0e4)?;
    let law = PowerLaw {
        exponent,
        reference_hz,
    };
    let stage = stage_without_frequency_law(model, j, &p)?;
    stage.frequency_power_law = Some(law);
    let summary = format!(
        "rubber stage `{}` follows a causal power law: storage stiffness × (f/{reference_hz:.1} \
         Hz)^{exponent:.4} ({:.4} at 10 Hz, {:.4} at 100 Hz), loss factor ≥ tan(nπ/2) = {:.4}",
        model.connections[j].name,
        law.storage(10.0),
        law.storage(100.0),
        law.own_loss_factor()
    );
    Ok((p.resolved, summary))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::{Effect, build_truth};
    use crate::model::{parse_model, presets};

    #[test]
    fn puts_the_law_on_the_stage() {
        let text = presets::preset("diagnosis-bench").expect("shipped").text;
        let user = parse_model(text, "bench.toml").unwrap();
        let spec = EffectSpec::new(Effect::CouplingFrequencyDependence)
            .with("form", FORM)
            .with("exponent", 0.12)
            .with("reference_hz", 30.0);
        let truth = build_truth(&user, &spec, 0.0, 0).unwrap();
        let law = crate::model::frequency_law::first_power_law(&truth.model).unwrap();
        assert_eq!(law.exponent, 0.12);
        assert_eq!(law.reference_hz, 30.0);
        assert!(truth.effect.summary.contains("tan(nπ/2) = 0.1908"));
        // The default form's key is refused here, and the exponent's bound holds.
        let bad = spec.clone().with("scale", 0.1);
        assert!(build_truth(&user, &bad, 0.0, 0).is_err());
        let big = spec.with("exponent", 0.6);
        assert!(build_truth(&user, &big, 0.0, 0).is_err());
    }
}
