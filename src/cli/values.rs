//! Checks of the numeric flags of the linear commands (`modes`, `coupling`): each value
//! finite and within a range derived from physics or from [`torsim::limits`], refused
//! (exit 2) with the flag and the range (issue 13, "nonsense values are taken as given").

use super::error::CliError;
use torsim::limits;
use torsim::model::rubber::temperature_problem;

/// A refusal of `flag`'s `value`.
fn refuse(flag: &str, value: f64, why: String) -> CliError {
    CliError::input(anyhow::anyhow!("{flag} {}: {why}", shown(value)))
}

/// A value as given, in exponent form when it is huge or tiny (1e300, not 301 digits).
fn shown(value: f64) -> String {
    if value != 0.0 && value.is_finite() && !(1e-4..1e7).contains(&value.abs()) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

/// A shaft speed, rpm: finite, > 0 and at most `limits::current().max_speed_rpm`.
pub fn speed_rpm(flag: &str, value: f64) -> Result<f64, CliError> {
    let max = limits::current().max_speed_rpm;
    if value.is_finite() && value > 0.0 && value <= max {
        Ok(value)
    } else {
        Err(refuse(
            flag,
            value,
            format!("a speed must be finite, > 0 and at most {max} rpm (limit max_speed_rpm)"),
        ))
    }
}

/// The highest vibration frequency any analysis asks about, Hz: the highest order at the
/// highest speed, `max_order · max_speed_rpm / 60` (166 667 Hz by default).
pub fn max_frequency_hz() -> f64 {
    let l = limits::current();
    l.max_order * l.max_speed_rpm / 60.0
}

/// A vibration frequency, Hz: finite, ≥ 0 (0 is static) and at most
/// [`max_frequency_hz`].
pub fn frequency_hz(flag: &str, value: f64) -> Result<f64, CliError> {
    let max = max_frequency_hz();
    if value.is_finite() && (0.0..=max).contains(&value) {
        Ok(value)
    } else {
        Err(refuse(
            flag,
            value,
            format!(
                "a frequency must be finite, ≥ 0 and at most {max:.0} Hz (the highest order \
                 at the highest speed, limits max_order · max_speed_rpm / 60)"
            ),
        ))
    }
}

/// A rubber temperature, °C, within the seed 000 law's range
/// ([`torsim::model::rubber::TEMPERATURE_RANGE_C`]).
pub fn temperature_c(flag: &str, value: f64) -> Result<f64, CliError> {
    match temperature_problem(value) {
        None => Ok(value),
        Some(why) => Err(refuse(flag, value, why)),
    }
}

/// Largest twist across a rubber stage, degrees: a full turn (couplings twist a few
/// degrees; the static twist is searched up to 10 rad ≈ 573°, far beyond any rubber).
pub const MAX_TWIST_DEG: f64 = 360.0;

/// A twist across a stage, degrees: finite and within ±[`MAX_TWIST_DEG`].
pub fn twist_deg(flag: &str, value: f64) -> Result<f64, CliError> {
    if value.is_finite() && value.abs() <= MAX_TWIST_DEG {
        Ok(value)
    } else {
        Err(refuse(
            flag,
            value,
            format!("a twist must be finite and within ±{MAX_TWIST_DEG}°"),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_nonsense_and_accepts_the_range() {
        for bad in [f64::NAN, -5.0, 0.0, 1e300, f64::INFINITY] {
            assert!(speed_rpm("--speed-rpm", bad).is_err(), "{bad}");
        }
        assert_eq!(speed_rpm("--speed-rpm", 100_000.0).ok(), Some(100_000.0));
        for bad in [f64::NAN, -1.0, 1e300] {
            assert!(frequency_hz("--frequency-hz", bad).is_err(), "{bad}");
        }
        assert!(frequency_hz("--frequency-hz", 0.0).is_ok());
        for bad in [-300.0, -273.15, 301.0, f64::NAN] {
            assert!(temperature_c("--temperature-c", bad).is_err(), "{bad}");
        }
        assert!(temperature_c("--temperature-c", -40.0).is_ok());
        for bad in [f64::NAN, 361.0, -1e9] {
            assert!(twist_deg("--twist-deg", bad).is_err(), "{bad}");
        }
        let e = speed_rpm("--speed-rpm", f64::NAN)
            .unwrap_err()
            .error
            .to_string();
        assert!(
            e.starts_with("--speed-rpm NaN: a speed must be finite"),
            "{e}"
        );
    }
}
