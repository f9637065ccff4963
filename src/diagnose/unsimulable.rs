//! Recordings the user's model cannot simulate, set aside instead of ending the diagnosis.
//!
//! A model can fail to reach a steady state at one regime of a campaign and not at the
//! others: a first mode damped at 0.5 %, excited by the major order at its resonance, grows
//! until the crank's speed passes zero, where the bench's nonlinear driveline (a gear's
//! play, a softening coupling) detuned itself and ran. The independent bench's published
//! case 100548 (README, fifth published run) was such a campaign: the user's model of a
//! Hertzian-backlash gearbox stalled at Regime A (1150 rpm, order 1.5 on a 28.6 Hz mode at
//! ζ = 0.54 %) and the whole diagnosis stopped with `simulating Regime A: the reference
//! speed is not > 0`. The user got nothing from six recordings the model could simulate.
//!
//! Now such a recording is set aside with the simulation's own message, the held-out
//! split is drawn again over the rest, and the diagnosis goes on; the report lists the
//! recording with the role `set aside` and the reason ([`super::report::RecordingUse`]).
//! Only the user's model decides: a candidate whose simulation fails on a recording is
//! rejected ([`super::report::Candidate::set_aside`]), never allowed to shrink the data
//! it is judged on.

use super::context::{Context, Evaluated};
use super::observe::{Observed, Run};
use super::{DiagnoseError, DiagnoseOptions, holdout};
use crate::model::Model;

/// A recording the user's model cannot simulate.
#[derive(Debug, Clone, PartialEq)]
pub struct SetAside {
    /// The recording as analysed.
    pub run: Run,
    /// The simulation's message.
    pub reason: String,
}

/// `observed` without run `r`: its observations dropped and the later runs' indices moved
/// down by one. The noise of the remaining amplitudes is left as it was measured.
fn without_run(observed: Observed, r: usize) -> Observed {
    let Observed {
        mut runs,
        observations,
        mut sample_noise_rpm,
    } = observed;
    runs.remove(r);
    if r < sample_noise_rpm.len() {
        sample_noise_rpm.remove(r);
    }
    let observations = observations
        .into_iter()
        .filter(|o| o.run != r)
        .map(|mut o| {
            if o.run > r {
                o.run -= 1;
            }
            o
        })
        .collect();
    Observed {
        runs,
        observations,
        sample_noise_rpm,
    }
}

/// The diagnosis' context and the user's model evaluated on every recording it can
/// simulate. A recording whose simulation fails is set aside (in
/// [`Context::set_aside`], by label) and the rest are simulated again; the diagnosis ends
/// only when none is left that can be fitted and held out, with the reasons in its
/// message.
pub fn context_and_baseline<'a>(
    model: &'a Model,
    options: &'a DiagnoseOptions,
    mut observed: Observed,
) -> Result<(Context<'a>, Evaluated), DiagnoseError> {
    let mut set_aside: Vec<SetAside> = Vec::new();
    loop {
        let mut cx = Context::new(model, options, observed);
        holdout::check_split(&cx.observed, &cx.held_out)
            .map_err(|e| with_reasons(e, &set_aside))?;
        let ones = vec![1.0; cx.plain.len()];
        let (label, message) = match cx.evaluate(model.clone(), None, ones, None) {
            Ok(baseline) => {
                cx.set_aside = set_aside;
                return Ok((cx, baseline));
            }
            Err(DiagnoseError::Simulation { label, message }) => (label, message),
            Err(e) => return Err(e),
        };
        let Some(r) = cx.observed.runs.iter().position(|run| run.label == label) else {
            return Err(DiagnoseError::Simulation { label, message });
        };
        set_aside.push(SetAside {
            run: cx.observed.runs[r].clone(),
            reason: message,
        });
        set_aside.sort_by(|a, b| a.run.label.cmp(&b.run.label));
        observed = without_run(cx.observed, r);
    }
}

/// `e` with what was set aside before it, so that the user sees why too few recordings
/// were left.
fn with_reasons(e: DiagnoseError, set_aside: &[SetAside]) -> DiagnoseError {
    if set_aside.is_empty() {
        return e;
    }
    let reasons: Vec<String> = set_aside
        .iter()
        .map(|s| {
            format!(
                "`{}` set aside: the model cannot be simulated there ({})",
                s.run.label, s.reason
            )
        })
        .collect();
    match e {
        DiagnoseError::Input(m) => DiagnoseError::Input(format!("{m}; {}", reasons.join("; "))),
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::observe::{Observation, RunShape, observe};
    use crate::diagnose::test_fixtures;

    fn run(label: &str) -> Run {
        test_fixtures::run(label, RunShape::Steady { speed_rpm: 1000.0 }, "crank")
    }

    fn observation(run: usize, order: f64) -> Observation {
        Observation {
            measured_rpm: run as f64 + order,
            ..test_fixtures::observation(run, 0, "crank", order)
        }
    }

    #[test]
    fn a_run_leaves_with_its_observations_and_the_later_indices_move_down() {
        let observed = Observed {
            runs: vec![run("A"), run("B"), run("C")],
            observations: (0..3)
                .flat_map(|r| [observation(r, 1.0), observation(r, 2.0)])
                .collect(),
            sample_noise_rpm: vec![vec![0.1], vec![0.2], vec![0.3]],
        };
        let left = without_run(observed, 1);
        let labels: Vec<&str> = left.runs.iter().map(|r| r.label.as_str()).collect();
        assert_eq!(labels, ["A", "C"]);
        assert_eq!(left.sample_noise_rpm, vec![vec![0.1], vec![0.3]]);
        let runs: Vec<usize> = left.observations.iter().map(|o| o.run).collect();
        assert_eq!(runs, [0, 0, 1, 1]);
        // C's amplitudes (run 2 + order) now point at index 1, unchanged.
        assert_eq!(left.observations[2].measured_rpm, 3.0);
        assert_eq!(left.observations[3].measured_rpm, 4.0);
    }

    /// The independent bench's published case 100548 (benchtruth, which shares no code
    /// with torsim): its user's model stalls at Regime A (order 1.5 on its 28.6 Hz first
    /// mode at ζ = 0.54 %) and runs at Regimes C and D.
    fn case_100548(dir: &std::path::Path) -> (Model, Vec<crate::diagnose::LabelledRecording>) {
        let files = benchtruth::write_case(100548, None, dir).expect("case 100548");
        let text = std::fs::read_to_string(&files.model).expect("model.toml");
        let model = crate::model::parse_model(&text, "model.toml").expect("model parses");
        let nodes: Vec<String> = model.inertias.iter().map(|n| n.name.clone()).collect();
        let recordings = ["regime-a", "regime-c", "regime-d"]
            .iter()
            .map(|stem| {
                let path = dir.join(format!("{stem}.csv"));
                let recording =
                    crate::recording::read_recording(&path, Some(&nodes)).expect("recording reads");
                let label = recording.meta.label.clone().expect("sidecar label");
                crate::diagnose::LabelledRecording { label, recording }
            })
            .collect();
        (model, recordings)
    }

    #[test]
    fn a_regime_the_model_cannot_simulate_is_set_aside_and_the_rest_are_simulated() {
        let dir = tempfile::tempdir().expect("temp dir");
        let (model, recordings) = case_100548(dir.path());
        let options = DiagnoseOptions {
            threads: 2,
            max_order: 8.0,
        };
        let observed = observe(&recordings, options.max_order).expect("recordings analyse");
        let n_c_d = observed.observations.iter().filter(|o| o.run > 0).count();
        let (cx, baseline) =
            context_and_baseline(&model, &options, observed.clone()).expect("C and D simulate");
        let aside: Vec<&str> = cx.set_aside.iter().map(|s| s.run.label.as_str()).collect();
        assert_eq!(aside, ["Regime A"]);
        assert!(
            cx.set_aside[0]
                .reason
                .contains("reference speed is not > 0"),
            "{}",
            cx.set_aside[0].reason
        );
        let left: Vec<&str> = cx.observed.runs.iter().map(|r| r.label.as_str()).collect();
        assert_eq!(left, ["Regime C", "Regime D"]);
        assert_eq!(cx.observed.observations.len(), n_c_d);
        assert_eq!(baseline.simulated.len(), n_c_d);
        assert!(baseline.simulated.iter().all(|x| x.is_finite()));
        // The split is drawn again over C and D: C fitted, D held out.
        assert_eq!(crate::diagnose::decide::run_roles(&cx), ["fit", "held out"]);

        // With A and C alone, C cannot be both fitted and judged: the error says so and
        // names A's reason.
        let mut two = observed;
        two.runs.truncate(2);
        two.sample_noise_rpm.truncate(2);
        two.observations.retain(|o| o.run < 2);
        let e = context_and_baseline(&model, &options, two)
            .err()
            .expect("too few recordings left");
        let message = e.to_string();
        assert!(message.contains("none to be held out"), "{message}");
        assert!(
            message.contains("`Regime A` set aside: the model cannot be simulated there"),
            "{message}"
        );
    }

    #[test]
    fn too_few_recordings_left_says_which_were_set_aside_and_why() {
        let e = with_reasons(
            DiagnoseError::Input("none to be held out".into()),
            &[SetAside {
                run: run("Regime A"),
                reason: "the reference speed is not > 0 at 0.02 s".into(),
            }],
        );
        assert_eq!(
            e.to_string(),
            "none to be held out; `Regime A` set aside: the model cannot be simulated there \
             (the reference speed is not > 0 at 0.02 s)"
        );
    }
}
