//! `coupling_frequency_dependence` with `form = zener` (issue 14): the stage follows a
//! fractional Zener law ([`crate::model::frequency_zener`]), an S-curve from its rubbery
//! stiffness to `1 + Δ` times it with a loss peak where it relaxes. The power law
//! ([`super::rubber_power`]) stiffens by the same ratio in every decade; an elastomer
//! nearer its transition stiffens mostly across one or two decades, and its loss peaks
//! there (Pritz, J. Sound Vib. 195 (1996) 103).
//!
//! The candidate fits `Δ` with the breadth `α` and the relaxation frequency fixed. Where
//! the S-curve sits matters as much as its height, so the diagnosis tries it at two
//! places ([`RELAX_RATIOS`]).

use super::EffectError;
use super::effect::{EffectSpec, Params};
use super::rubber::{stage_index, stage_without_frequency_law};
use super::truth::{Applied, mode_frequencies_hz};
use crate::model::{Model, ZenerLaw};

/// The `form` key's value of this form.
pub const FORM: &str = "zener";

/// The breadth `α` taken when none is given: 0.5, the middle of what elastomers show
/// (0.3–0.7, Pritz 1996, Table 1), a loss peak about two decades wide.
pub const DEFAULT_ALPHA: f64 = 0.5;

/// Relaxation frequencies the diagnosis tries, as multiples of the user model's first
/// mode: the S-curve's middle just above the mode the user tuned the stiffness at, and
/// a few times above it, where it reaches the higher orders and modes.
pub const RELAX_RATIOS: [f64; 2] = [1.5, 4.0];

/// Applies the Zener law of relaxation strength `delta` (default 0.5), breadth `alpha`
/// (default [`DEFAULT_ALPHA`]), `relax_hz` (default 2× the user model's first mode, or
/// `relax_ratio` times it) about `reference_hz` (default that first mode, where the user's
/// stiffness was tuned, as for the other forms) to stage `connection`.
pub(crate) fn zener(
    model: &mut Model,
    user: &Model,
    spec: &EffectSpec,
) -> Result<Applied, EffectError> {
    let mut p = Params::new(
        spec,
        &[
            "connection",
            "form",
            "delta",
            "alpha",
            "relax_hz",
            "relax_ratio",
            "reference_hz",
        ],
    )?;
    p.text("form", Some(FORM.into()))?;
    let j = stage_index(model, &mut p)?;
    let delta = p.number("delta", 0.5, 0.0, ZenerLaw::MAX_DELTA)?;
    let alpha = p.number("alpha", DEFAULT_ALPHA, 0.05, 1.0)?;
    let first_mode = mode_frequencies_hz(user)?
        .first()
        .copied()
        .unwrap_or(50.0)
        .max(1.0);
    let reference_hz = p.number("reference_hz", first_mode, 0.1, 1.0e4)?;
    let relax_hz = if spec.params.contains_key("relax_ratio") {
        let hz = first_mode * p.number("relax_ratio", 2.0, 0.01, 100.0)?;
        // Said in hertz too, for the report's words.
        p.resolved
            .push(("relax_hz".into(), super::effect::ParamValue::Number(hz)));
        hz
    } else {
        p.number("relax_hz", 2.0 * first_mode, 0.1, 1.0e4)?
    };
    let law = ZenerLaw {
        delta,
        alpha,
        relax_hz,
        reference_hz,
    };
    let stage = stage_without_frequency_law(model, j, &p)?;
    stage.frequency_zener = Some(law);
    let summary = format!(
        "rubber stage `{}` follows a fractional Zener law: storage stiffness {:.4} at rest, 1 \
         at {reference_hz:.1} Hz, {:.4} at 10× that, relaxing by {delta:.4} about \
         {relax_hz:.1} Hz (α = {alpha}); own loss factor {:.4} at {relax_hz:.1} Hz",
        model.connections[j].name,
        law.storage(0.0),
        law.storage(10.0 * reference_hz),
        law.own_loss_factor(relax_hz)
    );
    Ok((p.resolved, summary))
}

/// The relaxation frequency (Hz) of the Zener law that `model`'s rubber stage
/// `connection` follows, `None` when it follows none: what a fitted candidate's
/// `relax_ratio` came to on the model it was fitted on.
pub fn relax_hz(model: &Model, connection: &str) -> Option<f64> {
    model.connections.iter().find_map(|c| match &c.kind {
        crate::model::ConnectionKind::Rubber(r) if c.name == connection => {
            r.frequency_zener.map(|z| z.relax_hz)
        }
        _ => None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::{Effect, build_truth};
    use crate::model::{ConnectionKind, parse_model, presets, to_toml_string};

    fn zener_of(model: &Model) -> Option<ZenerLaw> {
        model.connections.iter().find_map(|c| match &c.kind {
            ConnectionKind::Rubber(r) => r.frequency_zener,
            _ => None,
        })
    }

    #[test]
    fn puts_the_law_on_the_stage() {
        let text = presets::preset("diagnosis-bench").expect("shipped").text;
        let user = parse_model(text, "bench.toml").unwrap();
        let spec = EffectSpec::new(Effect::CouplingFrequencyDependence)
            .with("form", FORM)
            .with("delta", 0.6)
            .with("relax_hz", 80.0)
            .with("reference_hz", 30.0);
        let truth = build_truth(&user, &spec, 0.0, 0).unwrap();
        let law = zener_of(&truth.model).unwrap();
        assert_eq!(
            law,
            ZenerLaw {
                delta: 0.6,
                alpha: DEFAULT_ALPHA,
                relax_hz: 80.0,
                reference_hz: 30.0
            }
        );
        assert!(
            truth
                .effect
                .summary
                .contains("relaxing by 0.6000 about 80.0 Hz")
        );
        // The model file carries it and reads it back the same.
        let again = parse_model(&to_toml_string(&truth.model), "again.toml").unwrap();
        assert_eq!(again, truth.model);
        // A ratio of the first mode places it as well; the other forms' keys and a
        // negative strength are refused.
        let first = mode_frequencies_hz(&user).unwrap()[0];
        let by_ratio = EffectSpec::new(Effect::CouplingFrequencyDependence)
            .with("form", FORM)
            .with("relax_ratio", 4.0);
        let placed = build_truth(&user, &by_ratio, 0.0, 0).unwrap().model;
        let law = zener_of(&placed).unwrap();
        assert!((law.relax_hz - 4.0 * first).abs() < 1e-9 * first);
        // What the report names: that frequency in Hz, at that stage only.
        assert_eq!(relax_hz(&placed, "coupling"), Some(law.relax_hz));
        assert_eq!(relax_hz(&placed, "shaft"), None);
        assert_eq!(relax_hz(&user, "coupling"), None);
        assert_eq!(law.reference_hz, first);
        assert!(build_truth(&user, &spec.clone().with("exponent", 0.1), 0.0, 0).is_err());
        assert!(build_truth(&user, &spec.with("delta", -0.1), 0.0, 0).is_err());
    }

    /// The linear views see the law: the stage's storage and loss in the nominal system
    /// are the law's, and the causal chain every view reads meets it at the stage's mode.
    #[test]
    fn every_view_reads_the_law() {
        use crate::physics::{OperatingPoint, System};
        let text = presets::preset("diagnosis-bench").expect("shipped").text;
        let user = parse_model(text, "bench.toml").unwrap();
        let spec = EffectSpec::new(Effect::CouplingFrequencyDependence)
            .with("form", FORM)
            .with("delta", 0.5)
            .with("relax_ratio", 1.5);
        let truth = build_truth(&user, &spec, 0.0, 0).unwrap();
        let law = zener_of(&truth.model).unwrap();
        let point = OperatingPoint {
            load: 0.0,
            temperature_c: None,
        };
        let nominal = System::nominal(&truth.model, point).unwrap();
        let causal = System::new(&truth.model, point).unwrap();
        let (stage, catalogue) = truth
            .model
            .connections
            .iter()
            .enumerate()
            .find_map(|(i, c)| match &c.kind {
                ConnectionKind::Rubber(r) if r.frequency_zener.is_some() => {
                    let alpha_txi = r.state(None, r.temperature_c, 0.0).alpha_txi;
                    Some((i, r.psi / std::f64::consts::TAU * alpha_txi))
                }
                _ => None,
            })
            .unwrap();
        let nom = nominal
            .elements
            .iter()
            .find(|e| e.connection == stage)
            .unwrap();
        let cau = causal
            .elements
            .iter()
            .find(|e| e.connection == stage)
            .unwrap();
        let (k_ref, _) = nom.stiffness_at(law.reference_hz);
        for f in [
            0.5 * law.reference_hz,
            law.reference_hz,
            law.relax_hz,
            300.0,
        ] {
            let (k, eta) = nom.stiffness_at(f);
            assert!((k / k_ref - law.storage(f)).abs() < 1e-12, "{f} Hz");
            assert!(
                (eta - law.loss_factor(f, catalogue)).abs() < 1e-12,
                "{f} Hz"
            );
        }
        // At the first mode, where the stage holds most of the strain energy, the chain
        // meets the law (the chain's own tolerance, `rubber::chain`: 1 % and 5 %).
        let (k_n, eta_n) = nom.stiffness_at(law.reference_hz);
        let (k_c, eta_c) = cau.stiffness_at(law.reference_hz);
        assert!((k_c / k_n - 1.0).abs() < 0.01, "{k_c} {k_n}");
        assert!((eta_c / eta_n - 1.0).abs() < 0.05, "{eta_c} {eta_n}");
    }
}
