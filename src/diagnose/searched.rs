//! Every candidate a diagnosis searches, built in one place.
//!
//! The run ([`super::run`]) screens this list on a campaign, and accepting a verdict
//! ([`super::accept`]) finds the verdict's candidate in it again. Built twice, the two
//! lists drifted apart: accepting a verdict of the branch form of a local mode failed
//! until the twenty-third session, and one of the heat-time-constant form of thermal
//! drift ([`super::drift::with_time_constant`]) until this one, each with "the model has
//! no place".
//!
//! The list is the candidates of [`super::candidates::candidates`] (one set per
//! connection and engine, the sensor artifacts at the measured stations), then the
//! thermal candidates again with the long runs' heat time constant, then a local mode
//! hanging on every node ([`super::branch::branch_candidates`]); the thermal candidates'
//! heat capacities start from the stage's loss in the heat run
//! ([`super::thermal_start`]).

use super::candidates::{Candidate, candidates};
use super::observe::{Observed, RunShape};
use super::thermal_start::{HeatRun, start_capacities};
use crate::model::Model;

/// What a campaign tells the candidate list: which forms it can show.
#[derive(Debug, Clone, Default)]
pub struct Campaign {
    /// The measured nodes (a sensor artifact sits at one of them).
    pub stations: Vec<String>,
    /// Whether a long run was recorded (thermal drift shows nowhere else).
    pub long_run: bool,
    /// The heat time constant (s) the long runs' amplitudes settle with
    /// ([`super::drift::long_run_time_constant`]); `None`: no thermal candidate of that
    /// form.
    pub time_constant_s: Option<f64>,
    /// The band (Hz) the campaign excites ([`super::branch::excited_band_hz`]), over
    /// which a local mode's frequency is fitted; `None`: no branch candidate.
    pub band_hz: Option<[f64; 2]>,
    /// The longest long run, where the thermal candidates' heat capacities start
    /// ([`super::thermal_start`]); `None`: they start at their fixed value.
    pub heat_run: Option<HeatRun>,
}

impl Campaign {
    /// What the campaign `observed` shows.
    pub fn of(observed: &Observed) -> Self {
        let mut stations: Vec<String> = observed
            .runs
            .iter()
            .flat_map(|r| r.stations.clone())
            .collect();
        stations.sort();
        stations.dedup();
        Campaign {
            stations,
            long_run: observed
                .runs
                .iter()
                .any(|r| matches!(r.regime, RunShape::LongRun { .. })),
            time_constant_s: super::drift::long_run_time_constant(observed),
            band_hz: super::branch::excited_band_hz(observed),
            heat_run: HeatRun::of(observed),
        }
    }

    /// A campaign that shows every form, for finding the place a verdict names: a long
    /// run of some time constant, and a band wide enough for any local mode (only the
    /// fit is bounded by it). The time constant's value is the verdict's, not this one.
    pub fn any() -> Self {
        Campaign {
            stations: Vec::new(),
            long_run: true,
            time_constant_s: Some(100.0),
            band_hz: Some([1.0, 1.0e4]),
            heat_run: None,
        }
    }
}

/// Every candidate of `model` that a diagnosis of `campaign` searches (module docs).
pub fn searched(model: &Model, campaign: &Campaign) -> Vec<Candidate> {
    let mut list = candidates(model, &campaign.stations, campaign.long_run);
    // A warming stage's drift in a second form: the shape the long runs show, its
    // conductance the capacity over their time constant ([`super::drift`]).
    if let Some(tau_s) = campaign.time_constant_s {
        list.extend(super::drift::with_time_constant(&list, tau_s));
    }
    // The branch form of `unmodelled_mode`: a local mode hanging on any node.
    if let Some(band) = campaign.band_hz {
        list.extend(super::branch::branch_candidates(model, band));
    }
    // Heat capacities from the stage's loss in the heat run.
    if let Some(heat) = &campaign.heat_run {
        start_capacities(&mut list, model, heat);
    }
    list
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::Effect;
    use crate::model::{parse_model, presets};

    /// Every form is listed for a campaign that shows it, and none for one that does not:
    /// the thermal candidates twice with a long run and its time constant, once with a
    /// long run alone, never without one; the branches only with a band.
    #[test]
    fn the_campaign_chooses_the_forms() {
        let p = presets::preset("diagnosis-bench").expect("shipped");
        let model = parse_model(p.text, "bench").expect("parses");
        let count = |c: &Campaign, pick: &dyn Fn(&Candidate) -> bool| {
            searched(&model, c).iter().filter(|c| pick(c)).count()
        };
        let thermal = |c: &Candidate| c.effect == Effect::CouplingThermalDrift;
        let timed = |c: &Candidate| {
            thermal(c)
                && c.fixed_value(super::super::drift::TIME_CONSTANT_KEY)
                    .is_some()
        };
        let branch = |c: &Candidate| c.fixed_value("form") == Some("branch");
        let any = Campaign::any();
        let once = count(&any, &thermal) - count(&any, &timed);
        assert!(once > 0);
        assert_eq!(count(&any, &timed), once);
        assert_eq!(
            count(&any, &branch),
            model.inertias.len() * super::super::branch::INERTIA_RATIOS.len()
        );
        let steady = Campaign::default();
        assert_eq!(count(&steady, &thermal), 0);
        assert_eq!(count(&steady, &branch), 0);
        let long = Campaign {
            long_run: true,
            ..Campaign::default()
        };
        assert_eq!(count(&long, &thermal), once);
        assert_eq!(count(&long, &timed), 0);
    }
}
