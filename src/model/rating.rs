//! A rubber stage's catalogue ratings (issue 16; DIN 740-2 and the makers' catalogues),
//! a model-format extension on a `kind = "rubber"` connection:
//!
//! ```toml
//! rating = { rated_torque_nm = 1600, max_torque_nm = 4000,
//!            permissible_vibratory_torque_nm = 640, permissible_power_loss_w = 160,
//!            ambient_c = 30, permissible_temperature_c = 80 }
//! ```
//!
//! - `rated_torque_nm` (T_KN, required): the torque the coupling carries continuously;
//! - `max_torque_nm` (T_Kmax): the largest torque it takes, during a resonance passage
//!   or a start, mean and vibration together;
//! - `permissible_vibratory_torque_nm` (T_KW): the amplitude of vibratory torque it takes
//!   continuously at 10 Hz; at a frequency f above 10 Hz the load counts √(f/10) times
//!   (DIN 740-2's frequency factor S_f);
//! - `permissible_power_loss_w` (P_KV): the damping power it sheds continuously at the
//!   catalogue's ambient of 30 °C; at a warmer `ambient_c` it sheds only
//!   P_KV·(T_perm − T_u)/(T_perm − 30 °C), T_perm = `permissible_temperature_c` (default
//!   80 °C, natural rubber): the heat flow to the air is proportional to the rubber's
//!   temperature rise, and the permissible rise shrinks as the air warms;
//! - the torques count S_t times at the stage's `temperature_c` (DIN 740-2's temperature
//!   factor for natural rubber: 1.0 to 30 °C, 1.2 at 40, 1.4 at 60, 1.8 at 80 °C, linear
//!   between, held beyond).
//!
//! The checks themselves are [`crate::ratings`].

use super::ModelError;
use super::spanned::Tab;

/// The catalogue's reference ambient for P_KV, °C: 30.
pub const CATALOGUE_AMBIENT_C: f64 = 30.0;
/// The rubber's permissible temperature when none is given, °C: 80 (natural rubber).
pub const DEFAULT_PERMISSIBLE_TEMPERATURE_C: f64 = 80.0;
/// DIN 740-2's temperature factor S_t for natural rubber: (°C, S_t), linear between.
const TEMPERATURE_FACTOR: [(f64, f64); 4] = [(30.0, 1.0), (40.0, 1.2), (60.0, 1.4), (80.0, 1.8)];

/// `rating = { … }` of a rubber stage: its catalogue values.
#[derive(Debug, Clone, PartialEq)]
pub struct CouplingRating {
    /// T_KN, N·m (> 0): the continuous rated torque.
    pub rated_torque_nm: f64,
    /// T_Kmax, N·m (≥ T_KN), if given.
    pub max_torque_nm: Option<f64>,
    /// T_KW, N·m (> 0): the continuous vibratory torque amplitude at 10 Hz, if given.
    pub permissible_vibratory_torque_nm: Option<f64>,
    /// P_KV, W (> 0): the continuous power loss at 30 °C ambient, if given.
    pub permissible_power_loss_w: Option<f64>,
    /// The ambient the coupling runs in, °C (default 30).
    pub ambient_c: f64,
    /// The rubber's permissible temperature, °C (default 80, > 30 and > `ambient_c`).
    pub permissible_temperature_c: f64,
}

impl CouplingRating {
    /// DIN 740-2's temperature factor S_t (natural rubber) at rubber temperature `t_c`.
    pub fn temperature_factor(t_c: f64) -> f64 {
        let table = TEMPERATURE_FACTOR;
        if t_c <= table[0].0 {
            return table[0].1;
        }
        for w in table.windows(2) {
            let ((t0, s0), (t1, s1)) = (w[0], w[1]);
            if t_c <= t1 {
                return s0 + (s1 - s0) * (t_c - t0) / (t1 - t0);
            }
        }
        table[table.len() - 1].1
    }

    /// DIN 740-2's frequency factor S_f at vibration frequency `f_hz`: 1 up to 10 Hz,
    /// √(f/10) above.
    pub fn frequency_factor(f_hz: f64) -> f64 {
        (f_hz.abs() / 10.0).sqrt().max(1.0)
    }

    /// What is wrong with these values, if anything: the key under `rating` and why (the
    /// same rules the reader applies, for a rating edited in memory).
    pub fn problem(&self) -> Option<(&'static str, String)> {
        let positive = |v: f64| v.is_finite() && v > 0.0;
        if !positive(self.rated_torque_nm) {
            return Some((
                "rated_torque_nm",
                format!("must be > 0 (got {})", self.rated_torque_nm),
            ));
        }
        if let Some(m) = self.max_torque_nm
            && !(m.is_finite() && m >= self.rated_torque_nm)
        {
            return Some((
                "max_torque_nm",
                format!(
                    "T_Kmax {m} N·m is below the rated torque {} N·m",
                    self.rated_torque_nm
                ),
            ));
        }
        for (key, v) in [
            (
                "permissible_vibratory_torque_nm",
                self.permissible_vibratory_torque_nm,
            ),
            ("permissible_power_loss_w", self.permissible_power_loss_w),
        ] {
            if let Some(v) = v.filter(|v| !positive(*v)) {
                return Some((key, format!("must be > 0 (got {v})")));
            }
        }
        let (t_u, t_p) = (self.ambient_c, self.permissible_temperature_c);
        if !(t_u.is_finite() && t_p > CATALOGUE_AMBIENT_C && t_p > t_u) {
            return Some((
                "permissible_temperature_c",
                format!("must be above both 30 °C and the ambient {t_u} °C (got {t_p})"),
            ));
        }
        None
    }

    /// The power loss the stage sheds continuously at its `ambient_c`, W.
    pub fn permissible_power_loss_at_ambient_w(&self) -> Option<f64> {
        let rise_now = self.permissible_temperature_c - self.ambient_c;
        let rise_catalogue = self.permissible_temperature_c - CATALOGUE_AMBIENT_C;
        self.permissible_power_loss_w
            .map(|p| p * (rise_now / rise_catalogue).max(0.0))
    }
}

/// Reads `rating = { … }` of a rubber connection, checking every value where it is.
pub(crate) fn read(t: &Tab) -> Result<Option<CouplingRating>, ModelError> {
    let Some(r) = t.opt_table("rating")? else {
        return Ok(None);
    };
    r.allow(&[
        "rated_torque_nm",
        "max_torque_nm",
        "permissible_vibratory_torque_nm",
        "permissible_power_loss_w",
        "ambient_c",
        "permissible_temperature_c",
    ])?;
    let rating = CouplingRating {
        rated_torque_nm: r.f64("rated_torque_nm")?,
        max_torque_nm: r.opt_f64("max_torque_nm")?,
        permissible_vibratory_torque_nm: r.opt_f64("permissible_vibratory_torque_nm")?,
        permissible_power_loss_w: r.opt_f64("permissible_power_loss_w")?,
        ambient_c: r.f64_or("ambient_c", CATALOGUE_AMBIENT_C)?,
        permissible_temperature_c: r.f64_or(
            "permissible_temperature_c",
            DEFAULT_PERMISSIBLE_TEMPERATURE_C,
        )?,
    };
    match rating.problem() {
        Some((key, why)) => Err(ModelError::at(r.key(key), why)),
        None => Ok(Some(rating)),
    }
}

/// The `(key, value)` pairs of `rating`'s inline table, defaults left out.
pub(crate) fn fields(
    r: &CouplingRating,
    num: impl Fn(f64) -> String,
) -> Vec<(&'static str, String)> {
    let mut out = vec![("rated_torque_nm", num(r.rated_torque_nm))];
    let optional = [
        ("max_torque_nm", r.max_torque_nm),
        (
            "permissible_vibratory_torque_nm",
            r.permissible_vibratory_torque_nm,
        ),
        ("permissible_power_loss_w", r.permissible_power_loss_w),
        (
            "ambient_c",
            Some(r.ambient_c).filter(|t| *t != CATALOGUE_AMBIENT_C),
        ),
        (
            "permissible_temperature_c",
            Some(r.permissible_temperature_c).filter(|t| *t != DEFAULT_PERMISSIBLE_TEMPERATURE_C),
        ),
    ];
    for (key, v) in optional {
        if let Some(v) = v {
            out.push((key, num(v)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_factors_follow_din_740_2() {
        assert_eq!(CouplingRating::temperature_factor(20.0), 1.0);
        assert_eq!(CouplingRating::temperature_factor(40.0), 1.2);
        assert!((CouplingRating::temperature_factor(50.0) - 1.3).abs() < 1e-12);
        assert_eq!(CouplingRating::temperature_factor(95.0), 1.8);
        assert_eq!(CouplingRating::frequency_factor(5.0), 1.0);
        assert!((CouplingRating::frequency_factor(40.0) - 2.0).abs() < 1e-12);
    }

    #[test]
    fn the_power_loss_derates_with_the_ambient() {
        let r = CouplingRating {
            rated_torque_nm: 1000.0,
            max_torque_nm: None,
            permissible_vibratory_torque_nm: None,
            permissible_power_loss_w: Some(200.0),
            ambient_c: 55.0,
            permissible_temperature_c: 80.0,
        };
        // (80 − 55)/(80 − 30) = 0.5
        assert_eq!(r.permissible_power_loss_at_ambient_w(), Some(100.0));
    }
}
