//! The mesh damping of a backlash candidate, chosen by the recordings that show the play.
//!
//! A rattling mesh shows its damping as much as its play ([`crate::effects::backlash`]),
//! and a model file rarely says what it is. The candidates damp an undamped mesh at
//! ζ = [`DEFAULT_MESH_DAMPING_RATIO`] ([`super::candidates_backlash`]); no single value
//! serves every mesh. The independent bench's meshes (`benchtruth`, damped in proportion
//! to stiffness) range from ζ = 0.74 % (validation case 1031) to 23 % (1042). 1031's
//! true play held out χ²/N 325 in its own mesh damping and 3114 at ζ = 0.1. Measured with
//! one fixed value for every case (a throw-away build), held-out χ²/N after the fit:
//!
//! | case | ζ = 0.02 | ζ = 0.1 |
//! |---|---|---|
//! | validation 1031 (its mesh 0.74 %) | named right | named `sensor_artifact` |
//! | development 2153 | 77.6 | 1282 |
//! | development 2087 (its mesh 13 %) | 156 | 21 |
//!
//! So, once the play is searched at ζ = 0.1, the candidate is simulated at that play with
//! each of [`ALTERNATIVES`] on the same recordings. When one fits them better, the play
//! is searched again with it, and the better of that search and the point it started
//! from stands. The damping is then a fixed key of the candidate like its contact form:
//! the report names it and accepting the verdict applies it. Two more values cost one
//! stage of the search (they run side by side) and a second search only where one wins.
//!
//! [`DEFAULT_MESH_DAMPING_RATIO`]: crate::effects::backlash::DEFAULT_MESH_DAMPING_RATIO

use super::DiagnoseError;
use super::candidates::Candidate;
use super::candidates_backlash::MESH_DAMPING_KEY as KEY;
use super::context::{Context, Evaluated};
use super::fit::parallel_map;
use super::surrogate::scaled;
use super::trial;

/// The mesh damping ratios tried beside [`DEFAULT_MESH_DAMPING_RATIO`] (0.1): a lightly damped
/// mesh (a few per cent, as the bench's 0.74–1 %) and a heavily damped one (its 23 %).
pub const ALTERNATIVES: [f64; 2] = [0.02, 0.3];

/// A backlash candidate with another mesh damping, fitted on the recordings that show it.
#[derive(Debug)]
pub struct Rechosen {
    /// The candidate with its `mesh_damping_ratio` replaced.
    pub candidate: Candidate,
    /// Its fit on the screened recordings (the others keep the first fit's values).
    pub evaluated: Evaluated,
    /// Steps that could not be simulated, with the reason.
    pub rejected: Vec<String>,
}

/// Tries [`ALTERNATIVES`] for the mesh damping of `c` at `found`, its fit with the
/// fixed damping, on `runs` (the recordings it was screened on). `None` when `c` fixes
/// no damping, when `found` has no play, or when no alternative fits those recordings
/// better; else the candidate with the better damping and its play searched again with
/// it. An alternative that cannot be simulated is a rejected step; only cancelling is an
/// error.
pub fn rechoose(
    cx: &Context,
    c: &Candidate,
    found: &Evaluated,
    runs: &[bool],
) -> Result<Option<Rechosen>, DiagnoseError> {
    let Some(value) = found.value else {
        return Ok(None);
    };
    let variants: Vec<Candidate> = ALTERNATIVES
        .iter()
        .filter_map(|r| c.with_fixed(KEY, *r))
        .collect();
    if variants.is_empty() {
        return Ok(None);
    }
    let base = scaled(cx.user, &cx.plain, &found.factors).map_err(DiagnoseError::Input)?;
    let only = Some((runs, found.simulated.as_slice()));
    let run = |v: &Candidate| {
        let (m, j) = v.apply(&base, value).map_err(DiagnoseError::Input)?;
        let s = trial::simulate(cx, Some(v), &m, j.as_ref(), only)?;
        Ok::<_, DiagnoseError>((cx.fit_cost(&s), m, j, s))
    };
    let tried = parallel_map(variants.len(), cx.options.threads, &|k| {
        Some(run(&variants[k]))
    });
    let mut rejected = Vec::new();
    let mut best: Option<(usize, f64, Evaluated)> = None;
    let mut to_beat = cx.fit_cost(&found.simulated);
    for (k, t) in tried.into_iter().enumerate() {
        let Some(t) = t else { continue };
        match t {
            Ok((cost, m, j, s)) if cost < to_beat => {
                to_beat = cost;
                let e = cx.scored(m, j, s, found.factors.clone(), Some(value));
                best = Some((k, cost, e));
            }
            Ok(_) => {}
            Err(e) if trial::is_fatal(&e) => return Err(e),
            Err(e) => rejected.push(trial::reason(&format!("{KEY} = {}", ALTERNATIVES[k]), &e)),
        }
    }
    let Some((k, cost_there, there)) = best else {
        return Ok(None);
    };
    let candidate = variants[k].clone();
    // The play searched again with the better damping, from the same plain factors; the
    // point it was chosen at stands when the search ends higher.
    let evaluated = match cx.fit_time_domain(found, &candidate, runs) {
        Ok(s) => {
            rejected.extend(s.rejected);
            if cx.fit_cost(&s.best.simulated) < cost_there {
                s.best
            } else {
                there
            }
        }
        Err(e) if trial::is_fatal(&e) => return Err(e),
        Err(e) => {
            rejected.push(trial::reason("the play with that damping", &e));
            there
        }
    };
    Ok(Some(Rechosen {
        candidate,
        evaluated,
        rejected,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::candidates_backlash::backlash_candidates;
    use crate::model::{ConnectionKind, Gear, parse_model, presets};

    fn gear() -> Gear {
        let text = presets::preset("diagnosis-bench").expect("shipped").text;
        let m = parse_model(text, "diagnosis-bench.toml").expect("valid");
        m.connections
            .iter()
            .find_map(|c| match &c.kind {
                ConnectionKind::Gear(g) => Some(g.clone()),
                _ => None,
            })
            .expect("a gear")
    }

    /// Only the damping changes: the place, the contact form and the fitted parameter
    /// stay; a candidate that fixes no damping has no variant.
    #[test]
    fn a_variant_changes_the_damping_only() {
        let mut g = gear();
        for c in backlash_candidates("gearbox", &g) {
            let v = c.with_fixed(KEY, 0.02).expect("an undamped mesh");
            assert_eq!(v.name(), c.name());
            assert_eq!(v.param, c.param);
            let changed: Vec<_> = v
                .fixed
                .iter()
                .zip(&c.fixed)
                .filter(|(a, b)| a != b)
                .collect();
            assert_eq!(changed.len(), 1);
            assert_eq!(changed[0].0, &(KEY, "0.02".to_string()));
        }
        g.mesh_damping_nm_s_per_rad = 2.0;
        for c in backlash_candidates("gearbox", &g) {
            assert!(c.with_fixed(KEY, 0.02).is_none());
        }
    }
}
