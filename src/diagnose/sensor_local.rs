//! Whether a sensor artifact explains a mismatch that only its own sensor sees.
//!
//! A test engineer who finds an odd order at one tape checks the other sensors: a
//! torsional vibration shows at every station its mode shape moves (each by its share), a
//! tape joint, a pitch error or an eccentric encoder only at its own. The diagnosis asks
//! the same of a fitted `sensor_artifact` at station S: where it improves the fit at S
//! (the run, its time block or speed bin, and the order), do the other stations, with the
//! artifact's model, fit their amplitudes of the same run and order to the noise? If they
//! keep at least [`SEEN_ELSEWHERE`] of the mismatch the artifact removed at S, the
//! mismatch is physical and seen by several sensors, and the artifact only covers its own
//! sensor's view of it (independent bench, validation seeds 1003 and 1014: amplitude
//! nonlinearity with an order 1.5 at every station, named `sensor_artifact` at one).

use super::candidates::Candidate;
use super::context::{Context, Evaluated};
use crate::effects::Effect;

/// Share of the removed mismatch that the other stations may keep (in χ² above the
/// noise's 1 per amplitude) before the mismatch counts as seen elsewhere: one half.
pub const SEEN_ELSEWHERE: f64 = 0.5;

/// A z² change at S below this is no improvement of that amplitude (2σ).
const IMPROVED_Z2: f64 = 4.0;

/// The station of a sensor-artifact candidate, `None` for any other effect.
fn station(c: &Candidate) -> Option<&str> {
    (c.effect == Effect::SensorArtifact)
        .then(|| c.fixed.iter().find(|(k, _)| *k == "station"))
        .flatten()
        .map(|(_, v)| v.as_str())
}

/// The χ² the artifact removes at its station (`removed`) and the χ² above the noise the
/// other stations keep at the same runs, parts and orders (`kept`), with the artifact's
/// model `with` against the plain fit `plain`. `None` for a candidate that is no sensor
/// artifact.
pub fn removed_and_kept(
    cx: &Context,
    c: &Candidate,
    plain: &Evaluated,
    with: &Evaluated,
) -> Option<(f64, f64)> {
    let s = station(c)?;
    let obs = &cx.observed.observations;
    let mut removed = 0.0;
    let mut places: Vec<(usize, usize, f64)> = Vec::new();
    for (k, o) in obs.iter().enumerate() {
        let gain = plain.z[k].powi(2) - with.z[k].powi(2);
        if o.station == s && gain > IMPROVED_Z2 {
            removed += gain;
            places.push((o.run, o.part, o.order));
        }
    }
    let kept: f64 = obs
        .iter()
        .enumerate()
        .filter(|(_, o)| o.station != s && places.contains(&(o.run, o.part, o.order)))
        .map(|(k, _)| (with.z[k].powi(2) - 1.0).max(0.0))
        .sum();
    Some((removed, kept))
}

/// Whether `c` may be a verdict as far as locality goes: always for another effect; for a
/// sensor artifact, when the other stations keep less than [`SEEN_ELSEWHERE`] of what it
/// removes at its own.
pub fn local(cx: &Context, c: &Candidate, plain: &Evaluated, with: &Evaluated) -> bool {
    removed_and_kept(cx, c, plain, with)
        .is_none_or(|(removed, kept)| kept < SEEN_ELSEWHERE * removed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::candidates::candidates;
    use crate::diagnose::observe::observe;
    use crate::diagnose::tests::steady;
    use crate::diagnose::tests_guard::bench;
    use crate::diagnose::{DiagnoseOptions, LabelledRecording};
    use crate::recording::{Channel, ChannelKind};

    /// Two steady runs seen at the engine and the brake (the same signal at both).
    fn two_stations() -> Vec<LabelledRecording> {
        [3000.0, 4000.0]
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let mut r = steady(&format!("R{i}"), *s, 5.0, 2.0, 0.3, 50 + i as u64);
                let values = r.recording.channels[0].values.clone();
                r.recording.channels.push(Channel {
                    column: "brake_rpm".into(),
                    kind: ChannelKind::SpeedRpm {
                        node: "brake".into(),
                    },
                    values,
                });
                r
            })
            .collect()
    }

    /// A mismatch of 30σ at the engine's order 2 of run 0, which the artifact at the
    /// engine removes: local when the brake fits that order (z = 1), seen elsewhere when
    /// the brake misfits it by 25σ with the artifact's model; the removed and kept χ² are
    /// the sums of the squares.
    #[test]
    fn an_artifact_is_local_only_when_the_other_sensors_fit() {
        let model = bench();
        let options = DiagnoseOptions::default();
        let observed = observe(&two_stations(), 8.0).expect("observed");
        let cx = Context::new(&model, &options, observed);
        let list = candidates(&model, &["engine".into(), "brake".into()], false);
        let artifact = list
            .iter()
            .find(|c| station(c) == Some("engine"))
            .expect("an artifact at the engine");
        let obs = &cx.observed.observations;
        let at = |station: &str| {
            obs.iter()
                .position(|o| o.run == 0 && o.order == 2.0 && o.station == station)
                .expect("order 2 of run 0")
        };
        let (engine, brake) = (at("engine"), at("brake"));
        let flat = || {
            let simulated = obs.iter().map(|o| o.measured_rpm).collect();
            let mut e = cx.scored(
                model.clone(),
                None,
                simulated,
                vec![1.0; cx.plain.len()],
                None,
            );
            e.z = vec![1.0; obs.len()];
            e
        };
        let mut plain = flat();
        plain.z[engine] = 30.0;
        plain.z[brake] = 25.0;
        let mut with = flat();
        assert_eq!(
            removed_and_kept(&cx, artifact, &plain, &with),
            Some((899.0, 0.0))
        );
        assert!(local(&cx, artifact, &plain, &with));
        with.z[brake] = 25.0;
        assert_eq!(
            removed_and_kept(&cx, artifact, &plain, &with),
            Some((899.0, 624.0))
        );
        assert!(!local(&cx, artifact, &plain, &with));
        // Another effect is never judged here.
        let other = list
            .iter()
            .find(|c| station(c).is_none())
            .expect("an effect");
        assert_eq!(removed_and_kept(&cx, other, &plain, &with), None);
        assert!(local(&cx, other, &plain, &with));
    }
}
