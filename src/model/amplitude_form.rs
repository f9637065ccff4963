//! `amplitude_form` of a rubber stage: what its amplitude law α_x (seed 000 eq. 1) scales —
//! the whole stage with its damping (seed 000 eq. 13–15), or the elastic spring only
//! (issue 14: a coupling on a bench that stiffens with twist while its loss stays).

/// What a rubber stage's amplitude law α_x scales (model key `amplitude_form`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AmplitudeForm {
    /// `"whole"` (default): the whole stage, its damping with it — seed 000 eq. 13–15,
    /// where the dynamic stiffness `c_Tstat·α_x·…` carries the loss factor, so the loss
    /// modulus grows with the stiffening.
    #[default]
    Whole,
    /// `"elastic"`: the elastic (equilibrium) spring only; the loss stays the user's ψ at
    /// the unstiffened stiffness, so the loss factor falls as the stage stiffens. A
    /// progressive coupling whose elements come into contact with their housing or whose
    /// filler stiffens with compression does this: the stiffening is geometric, the
    /// rubber's hysteresis is not scaled by it (issue 14).
    Elastic,
}

impl AmplitudeForm {
    /// The model file's spelling.
    pub fn key(self) -> &'static str {
        match self {
            AmplitudeForm::Whole => "whole",
            AmplitudeForm::Elastic => "elastic",
        }
    }

    /// The form a model file's spelling names, if any.
    pub fn from_key(key: &str) -> Option<Self> {
        [AmplitudeForm::Whole, AmplitudeForm::Elastic]
            .into_iter()
            .find(|f| f.key() == key)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::presets::preset;
    use crate::model::{ConnectionKind, Model, parse_model, to_toml_string};

    /// The cng-genset preset with `line` added after its rubber stage's `amplitude_poly`
    /// (or, for `diagnosis-bench`, after its `psi`).
    fn with_line(name: &str, after: &str, line: &str) -> String {
        let text = preset(name).expect("shipped preset").text;
        let at = text.find(after).expect("the key is in the preset");
        let end = at + text[at..].find('\n').expect("a line end");
        format!("{}\n{line}{}", &text[..end], &text[end..])
    }

    fn form_of(model: &Model) -> AmplitudeForm {
        model
            .connections
            .iter()
            .find_map(|c| match &c.kind {
                ConnectionKind::Rubber(r) => Some(r.amplitude_form),
                _ => None,
            })
            .expect("a rubber stage")
    }

    #[test]
    fn the_key_reads_writes_back_and_defaults_to_whole() {
        let plain = parse_model(preset("cng-genset").expect("preset").text, "p.toml")
            .expect("the preset reads");
        assert_eq!(form_of(&plain), AmplitudeForm::Whole);
        assert!(!to_toml_string(&plain).contains("amplitude_form"));
        let text = with_line(
            "cng-genset",
            "amplitude_poly =",
            "amplitude_form = \"elastic\"",
        );
        let elastic = parse_model(&text, "e.toml").expect("reads");
        assert_eq!(form_of(&elastic), AmplitudeForm::Elastic);
        let written = to_toml_string(&elastic);
        assert!(
            written.contains("amplitude_form = \"elastic\""),
            "{written}"
        );
        assert_eq!(
            parse_model(&written, "w.toml").expect("reads back"),
            elastic
        );
    }

    #[test]
    fn an_unknown_form_or_one_without_a_law_is_refused_at_its_key() {
        let text = with_line(
            "cng-genset",
            "amplitude_poly =",
            "amplitude_form = \"damping\"",
        );
        let e = parse_model(&text, "e.toml")
            .expect_err("unknown form")
            .to_string();
        assert!(
            e.contains("amplitude_form") && e.contains("whole or elastic"),
            "{e}"
        );
        let text = with_line("diagnosis-bench", "psi =", "amplitude_form = \"elastic\"");
        let e = parse_model(&text, "e.toml")
            .expect_err("no law")
            .to_string();
        assert!(e.contains("without `amplitude_poly`"), "{e}");
    }
}
