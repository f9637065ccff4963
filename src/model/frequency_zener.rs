//! A fractional Zener frequency law of a rubber stage (issue 14): the stage relaxes from a
//! rubbery stiffness at rest to a stiffer one at high frequency across an S-curve, with a
//! loss peak where it relaxes. Its complex stiffness, relative to the rubbery one, is
//!
//! `z(ω) = 1 + Δ·(iω/ω_r)^α / (1 + (iω/ω_r)^α)`
//!
//! (the fractional standard linear solid of linear viscoelasticity; Bagley & Torvik,
//! J. Rheology 27 (1983) 201; Pritz, J. Sound Vib. 195 (1996) 103, who fits elastomers by
//! it): `Δ` is the relaxation strength (the stiffness at high frequency is `1 + Δ` times
//! the rubbery one), `ω_r = 2π·relax_hz` where the S-curve is steepest, `0 < α ≤ 1` its
//! breadth (`α = 1` is the classical Zener solid, a single Maxwell arm on a spring). It is
//! causal and passive for `Δ ≥ 0`, so, unlike seed 000 eq. 9, its stiffening carries the
//! loss that Kramers–Kronig ties to it.
//!
//! The model's stiffness is the stage's storage stiffness at `reference_hz` (where a
//! catalogue or the user tuned it); at rest it is `1/Re z(ω_ref)` of that. ψ is read as
//! the rubber's rate-independent loss (the hysteresis of its filler network), and the
//! relaxation's own loss adds to it: the loss factor is `ψ/2π + Im z(ω)/Re z(ω)`, the
//! complex stiffness `k·(z + i·ψ/2π·Re z)/Re z(ω_ref)`. A ψ measured well below the
//! relaxation, where `Im z` is small, is that part. (The power law reads ψ as the total
//! loss instead, [`super::frequency_law`]: its own loss is the same at every frequency,
//! so there the two readings cannot be told apart by the data; a Zener law's loss is
//! not, and a ψ that already held its loss at one frequency would hide the law there.)

use num_complex::Complex64;
use std::f64::consts::FRAC_PI_2;

/// `frequency_zener = { delta, alpha, relax_hz, reference_hz }` of a rubber stage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZenerLaw {
    /// Relaxation strength `Δ ≥ 0`: the stiffness at high frequency over the rubbery one,
    /// less 1.
    pub delta: f64,
    /// Fractional order `0 < α ≤ 1` (1: the classical Zener solid).
    pub alpha: f64,
    /// Relaxation frequency `ω_r/2π`, Hz (> 0): the middle of the S-curve.
    pub relax_hz: f64,
    /// Frequency where the storage stiffness is the stage's stiffness, Hz (> 0).
    pub reference_hz: f64,
}

impl ZenerLaw {
    /// The largest relaxation strength taken, 10: an elastomer's glassy modulus is two to
    /// three decades above its rubbery one, but a coupling runs well below its transition.
    pub const MAX_DELTA: f64 = 10.0;

    /// `z(2π·frequency_hz)`, relative to the rubbery stiffness.
    fn z(&self, frequency_hz: f64) -> Complex64 {
        if frequency_hz <= 0.0 {
            return Complex64::new(1.0, 0.0);
        }
        let x = (frequency_hz / self.relax_hz).powf(self.alpha);
        let (s, c) = (self.alpha * FRAC_PI_2).sin_cos();
        let p = Complex64::new(x * c, x * s);
        1.0 + self.delta * p / (1.0 + p)
    }

    /// Storage stiffness relative to the stage's at `frequency_hz` (1 at `reference_hz`;
    /// `1/Re z(ω_ref)` at rest).
    pub fn storage(&self, frequency_hz: f64) -> f64 {
        self.z(frequency_hz).re / self.z(self.reference_hz).re
    }

    /// The law's own loss factor at `frequency_hz`, `Im z/Re z` (0 at rest).
    pub fn own_loss_factor(&self, frequency_hz: f64) -> f64 {
        let z = self.z(frequency_hz);
        z.im / z.re
    }

    /// The stage's loss factor at `frequency_hz` when its rate-independent part is
    /// `catalogue_loss_factor` (`ψ/2π`, with the temperature factor): that and the law's
    /// own (see the module doc).
    pub fn loss_factor(&self, frequency_hz: f64, catalogue_loss_factor: f64) -> f64 {
        catalogue_loss_factor + self.own_loss_factor(frequency_hz)
    }

    /// `None` when the law is usable, else why not (for validation).
    pub fn problem(&self) -> Option<String> {
        if !(self.delta.is_finite() && (0.0..=Self::MAX_DELTA).contains(&self.delta)) {
            return Some(format!(
                "delta {} must be in [0, {}] (the high-frequency stiffness over the rubbery \
                 one, less 1)",
                self.delta,
                Self::MAX_DELTA
            ));
        }
        if !(self.alpha.is_finite() && self.alpha > 0.0 && self.alpha <= 1.0) {
            return Some(format!("alpha {} must be in (0, 1]", self.alpha));
        }
        for (key, v) in [
            ("relax_hz", self.relax_hz),
            ("reference_hz", self.reference_hz),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Some(format!("{key} {v} must be > 0"));
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law() -> ZenerLaw {
        ZenerLaw {
            delta: 0.5,
            alpha: 0.45,
            relax_hz: 60.0,
            reference_hz: 30.0,
        }
    }

    /// The classical Zener solid (α = 1) is a spring `1` beside a Maxwell arm of stiffness
    /// `Δ` and relaxation time `1/ω_r`: storage `1 + Δ·x²/(1 + x²)`, loss `Δ·x/(1 + x²)`.
    #[test]
    fn alpha_one_is_the_classical_solid() {
        let l = ZenerLaw {
            alpha: 1.0,
            ..law()
        };
        let arm = |f: f64| {
            let x: f64 = f / l.relax_hz;
            (
                1.0 + l.delta * x * x / (1.0 + x * x),
                l.delta * x / (1.0 + x * x),
            )
        };
        let (r_ref, _) = arm(l.reference_hz);
        for f in [1.0, 30.0, 60.0, 500.0] {
            let (re, im) = arm(f);
            assert!((l.storage(f) - re / r_ref).abs() < 1e-12, "{f} Hz");
            assert!((l.own_loss_factor(f) - im / re).abs() < 1e-12, "{f} Hz");
        }
    }

    /// Rubbery at rest, `1 + Δ` at high frequency, monotone between, relative to the
    /// reference; the loss peaks near the relaxation frequency and vanishes at both ends.
    #[test]
    fn is_an_s_curve_with_a_loss_peak() {
        let l = law();
        assert_eq!(l.storage(l.reference_hz), 1.0);
        let rest = l.storage(0.0);
        assert!((l.storage(1e9) / rest - 1.5).abs() < 1e-3);
        let fs: Vec<f64> = (0..60).map(|i| 0.1 * 1.3f64.powi(i)).collect();
        assert!(fs.windows(2).all(|w| l.storage(w[1]) > l.storage(w[0])));
        let peak = fs
            .iter()
            .copied()
            .max_by(|a, b| l.own_loss_factor(*a).total_cmp(&l.own_loss_factor(*b)))
            .unwrap();
        // The loss factor's peak lies at ω_r·(1 + Δ)^(−1/2α)… above, within a factor 2.
        assert!(peak > 30.0 && peak < 240.0, "{peak}");
        assert!(l.own_loss_factor(0.01) < 0.01 && l.own_loss_factor(1e7) < 0.01);
        assert_eq!(l.own_loss_factor(0.0), 0.0);
    }

    /// The rate-independent part adds to the law's own loss at every frequency, and is
    /// all that is left at rest.
    #[test]
    fn the_rate_independent_loss_adds_to_the_laws() {
        let l = law();
        for f in [0.0, l.reference_hz, l.relax_hz, 400.0] {
            let both = l.loss_factor(f, 0.1);
            assert!(
                (both - (0.1 + l.own_loss_factor(f))).abs() < 1e-15,
                "{f} Hz"
            );
        }
        assert_eq!(l.loss_factor(0.0, 0.1), 0.1);
        assert!(l.loss_factor(l.relax_hz, 0.1) > 0.15);
    }

    /// The model file's key reads, writes back the same, and is refused out of range,
    /// incomplete or beside another frequency law, the error naming the key.
    #[test]
    fn reads_writes_and_refuses() {
        use crate::model::{ConnectionKind, parse_model, presets, to_toml_string};
        let base = presets::preset("diagnosis-bench").expect("shipped").text;
        let at = "psi = 1.0\n";
        assert!(base.contains(at));
        let with = |extra: &str| base.replacen(at, &format!("{at}{extra}\n"), 1);
        let key = "frequency_zener = { delta = 0.5, alpha = 0.45, relax_hz = 60.0, \
                   reference_hz = 30.0 }";
        let model = parse_model(&with(key), "m.toml").unwrap();
        let read = model.connections.iter().find_map(|c| match &c.kind {
            ConnectionKind::Rubber(r) => r.frequency_zener,
            _ => None,
        });
        assert_eq!(read, Some(law()));
        let again = parse_model(&to_toml_string(&model), "again.toml").unwrap();
        assert_eq!(again, model);
        for bad in [
            "frequency_zener = { delta = -0.5, alpha = 0.45, relax_hz = 60.0, reference_hz = 30.0 }",
            "frequency_zener = { delta = 0.5, alpha = 0.45, relax_hz = 60.0 }",
            "frequency_zener = { delta = 0.5, alpha = 0.45, relax_hz = 60.0, reference_hz = 30.0, \
             beta = 1 }",
            "frequency_zener = { delta = 0.5, alpha = 0.45, relax_hz = 60.0, reference_hz = 30.0 }\n\
             frequency_power_law = { exponent = 0.1, reference_hz = 30.0 }",
        ] {
            let e = parse_model(&with(bad), "bad.toml").unwrap_err().to_string();
            assert!(
                e.contains("frequency_zener") && e.contains("bad.toml"),
                "{bad}: {e}"
            );
        }
    }

    #[test]
    fn refuses_what_is_no_law() {
        assert!(law().problem().is_none());
        let bad = [
            ZenerLaw {
                delta: -0.1,
                ..law()
            },
            ZenerLaw {
                delta: f64::NAN,
                ..law()
            },
            ZenerLaw {
                alpha: 0.0,
                ..law()
            },
            ZenerLaw {
                alpha: 1.2,
                ..law()
            },
            ZenerLaw {
                relax_hz: 0.0,
                ..law()
            },
            ZenerLaw {
                reference_hz: f64::INFINITY,
                ..law()
            },
        ];
        for l in bad {
            assert!(l.problem().is_some(), "{l:?}");
        }
    }
}
