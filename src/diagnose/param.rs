//! A candidate's fitted parameter: its bounds, where the effect is absent, and how its
//! search and verification treat it. What is special to one effect's parameter is
//! declared here, on the parameter, rather than tested against the effect where the
//! search and the verification run.

use super::fit::Bounds;
use super::rounds::SEARCH_HALVINGS;

/// A fitted parameter: its key, start, bounds and whether it is fitted in log.
#[derive(Debug, Clone, PartialEq)]
pub struct Param {
    /// The effect's key (`a2`, `backlash_deg`, …).
    pub key: &'static str,
    /// Start value.
    pub start: f64,
    /// Lower bound.
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
    /// Fitted as its logarithm (positive scale-like values).
    pub log: bool,
    /// It places a narrow resonance (a frequency, fitted in log): its fit starts from the
    /// best of values [`RESONANCE_START_STEP`] apart over its whole range, since a start
    /// beside a resonance's valley does not roll into it.
    pub resonance: bool,
    /// The value at which the effect is absent and the model is the plain one (`a2 = 0`,
    /// `pressure_scale = 1`, …); `None` for a parameter without one (a heat capacity is
    /// absent only at infinity, a frequency always places something).
    pub absent_at: Option<f64>,
    /// Its time-domain grid search goes on past an end of the grid, a step at a time and
    /// away from the effect's absence, when the best is at that end
    /// ([`super::rounds`]). Default `false`.
    pub search_past_grid: bool,
    /// What decides whether its screened fit is verified on the whole campaign. Default
    /// [`Verification::ByScore`].
    pub verification: Verification,
}

/// What decides whether a screened candidate is verified in the time domain of the whole
/// campaign ([`super::verify::verify`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verification {
    /// Its score on the fitted data, among the best few.
    ByScore,
    /// Always: its screening held the plain parameters at the plain fit, which had
    /// already taken the effect's mean into a stiffness, so its score is no fair gate.
    Always,
    /// Always, unless the screening found the effect at its absence
    /// ([`Param::is_absent`]), which the plain fit explains as well.
    WhenPresent,
}

/// A fitted value within this fraction of the way from [`Param::absent_at`] to the start
/// value is the effect's absence ([`Param::is_absent`]).
pub const ABSENT_FRACTION: f64 = 0.01;

/// Ratio between the start values of a [`Param::resonance`]: 2^(1/6), 12 %, three times
/// a branch's half-power width at its default damping ratio of 2 %
/// ([`crate::effects::branch::DEFAULT_DAMPING_RATIO`]); a run-up's order amplitudes feel
/// the mode over a wider band than that, so the valley seen from the starts is wider.
pub const RESONANCE_START_STEP: f64 = 1.122_462_048_309_373;

impl Param {
    /// `key` started at `start` within [`lo`, `hi`] (fitted in log when `log`), with no
    /// absence, no resonance, its grid search kept to the grid, verified by its score.
    pub fn new(key: &'static str, start: f64, lo: f64, hi: f64, log: bool) -> Self {
        Self {
            key,
            start,
            lo,
            hi,
            log,
            resonance: false,
            absent_at: None,
            search_past_grid: false,
            verification: Verification::ByScore,
        }
    }

    /// The same parameter, its grid search going on past the grid's ends
    /// ([`Param::search_past_grid`]).
    pub fn searched_past_grid(self) -> Self {
        Self {
            search_past_grid: true,
            ..self
        }
    }

    /// The same parameter, verified by `rule`.
    pub fn verified(self, rule: Verification) -> Self {
        Self {
            verification: rule,
            ..self
        }
    }

    /// Whether a screened fit at `value` is verified whatever its score
    /// ([`Param::verification`]).
    pub fn verified_whatever_scored(&self, value: Option<f64>) -> bool {
        match self.verification {
            Verification::ByScore => false,
            Verification::Always => true,
            Verification::WhenPresent => !self.is_absent(value),
        }
    }

    /// The same parameter, absent at `value`.
    pub fn absent_at(self, value: f64) -> Self {
        Self {
            absent_at: Some(value),
            ..self
        }
    }

    /// Whether `value` is the effect's absence: within [`ABSENT_FRACTION`] of the way
    /// from [`Param::absent_at`] to the start. Such a fit has no effect in it, so whatever
    /// it gains over the plain fit is the path its plain parameters took, not the effect
    /// (validation control 1034: `cylinder_imbalance` at `pressure_scale` 1.0001, held-out
    /// χ²/N 13.8 against 17.9 for the plain fit, the gain all in a run-up's passage of a
    /// 164 rpm resonance).
    pub fn is_absent(&self, value: Option<f64>) -> bool {
        match (self.absent_at, value) {
            (Some(null), Some(v)) => {
                (v - null).abs() <= ABSENT_FRACTION * (self.start - null).abs()
            }
            _ => false,
        }
    }

    /// Whether the effect's absence lies above the start: towards [`Param::absent_at`],
    /// or, without one, towards infinity (a heat capacity, the only such parameter a
    /// time-domain search takes; a frequency places something everywhere).
    pub fn absent_above(&self) -> bool {
        self.absent_at.is_none_or(|null| null > self.start)
    }

    /// The step of its time-domain search's coarse grid, in the search's coordinate
    /// ([`Param::search_coordinate`]): a factor 3 (ln 3) for a parameter fitted in log, an
    /// eighth of the range for one fitted linearly ([`super::rounds`]).
    pub fn search_step(&self) -> f64 {
        if self.log {
            3f64.ln()
        } else {
            (self.hi - self.lo) / 8.0
        }
    }

    /// The coordinate its time-domain search steps in: `ln x` for a parameter fitted in
    /// log (`None` for a value ≤ 0, which has none), `x` itself otherwise.
    pub fn search_coordinate(&self, x: f64) -> Option<f64> {
        match self.log {
            true if x > 0.0 => Some(x.ln()),
            true => None,
            false => Some(x),
        }
    }

    /// Whether two fitted values are different places of the effect, not one place
    /// found twice: further apart than the time-domain search resolves, its grid step
    /// ([`Param::search_step`]) halved [`SEARCH_HALVINGS`] times; a factor √3 for a
    /// parameter fitted in log, a sixteenth of the range for one fitted linearly.
    /// `false` when either is missing.
    pub fn apart(&self, a: Option<f64>, b: Option<f64>) -> bool {
        let (Some(a), Some(b)) = (a, b) else {
            return false;
        };
        let (Some(u), Some(v)) = (self.search_coordinate(a), self.search_coordinate(b)) else {
            return false;
        };
        let resolution = self.search_step() / 2f64.powi(SEARCH_HALVINGS as i32);
        (u - v).abs() > resolution
    }

    /// Its bounds for a fit.
    pub fn bounds(&self) -> Bounds {
        Bounds {
            lo: self.lo,
            hi: self.hi,
            log: self.log,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A log parameter's places are apart beyond a factor √3 = 1.732 either way; a linear
    /// one's beyond a sixteenth of its range; a missing value is never apart.
    #[test]
    fn places_are_apart_beyond_the_search_resolution() {
        let backlash = Param::new("backlash_deg", 0.05, 0.002, 2.0, true);
        assert!(!backlash.apart(Some(0.1), Some(0.17)));
        assert!(backlash.apart(Some(0.1), Some(0.18)));
        assert!(backlash.apart(Some(0.0056), Some(0.179)));
        assert!(backlash.apart(Some(0.18), Some(0.1)));
        assert!(!backlash.apart(None, Some(0.179)));
        let scale = Param::new("pressure_scale", 0.95, 0.3, 1.5, false);
        // A sixteenth of 1.2 is 0.075.
        assert!(!scale.apart(Some(0.95), Some(1.02)));
        assert!(scale.apart(Some(0.95), Some(1.03)));
    }
}
