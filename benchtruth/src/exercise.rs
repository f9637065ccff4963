//! How hard the concealed effect was exercised in each recording, measured on the truth's
//! own state while it is integrated (issue 14, item 4: what is still confused with what,
//! and why). The scorer reads it beside the verdict; torsim never does.
//!
//! A class is only as visible as the campaign makes it. Two measures were needed to read
//! the development seeds (2004–2087):
//! - **Gear backlash:** the fraction of samples whose mesh twist δ lies inside the play
//!   (|δ| < h, the half backlash), and the range of δ/h. A gear whose δ/h stays above 1
//!   never opens its play: all its backlash can show is the contact law's stiffness at the
//!   working deflection, which is a mesh stiffness, not free play.
//! - **Amplitude nonlinearity:** the largest |Δθ| over the stage's static twist at full
//!   load, and the largest secant stiffening g(Δθ) − 1 the recording reached. When the
//!   vibratory twist is several times the static one, the stiffening is set by the
//!   vibration, not by the load.
//!
//! Other classes are not measured (`None`).

use crate::draw::{Case, through_torque};
use crate::effects::{BacklashLaw, Effect};

/// What one recording exercised.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Exercise {
    /// Backlash: fraction of samples inside the play, and the least and largest δ/h.
    Play {
        inside: f64,
        min_over_half: f64,
        max_over_half: f64,
    },
    /// Amplitude nonlinearity: the largest |Δθ| over the full-load static twist, and the
    /// largest secant stiffening g − 1.
    Twist {
        max_over_static: f64,
        max_stiffening: f64,
    },
}

/// Accumulates [`Exercise`] over the samples of one recording.
#[derive(Debug, Clone)]
pub struct Meter {
    /// Connection: `from`, `to` and the lever of `from` (the gear ratio, else 1).
    from: usize,
    to: usize,
    lever: f64,
    kind: Kind,
    samples: usize,
    inside: usize,
    lo: f64,
    hi: f64,
    stiffening: f64,
}

#[derive(Debug, Clone, Copy)]
enum Kind {
    /// Half backlash h, rad.
    Play { half_rad: f64 },
    /// Static twist at full load (rad) and the secant law.
    Twist {
        static_rad: f64,
        law: crate::effects::AmplitudeLaw,
    },
}

impl Meter {
    /// A meter for the effect of `case`, `None` for a class that is not measured.
    pub fn for_case(case: &Case) -> Option<Self> {
        let (conn, kind) = match &case.effect {
            Effect::GearBacklash { conn, law } => {
                let half_rad = match *law {
                    BacklashLaw::Softened { half_rad, .. } => half_rad,
                    BacklashLaw::Hertzian { half_rad, .. } => half_rad,
                };
                (*conn, Kind::Play { half_rad })
            }
            Effect::AmplitudeNonlinearity { conn, law } => {
                let k = case.truth.connections[*conn].stiffness();
                let static_rad = (through_torque(&case.truth, *conn) / k).abs();
                (
                    *conn,
                    Kind::Twist {
                        static_rad,
                        law: *law,
                    },
                )
            }
            _ => return None,
        };
        let c = &case.truth.connections[conn];
        Some(Self::new(c.from, c.to, c.lever(), kind))
    }

    fn new(from: usize, to: usize, lever: f64, kind: Kind) -> Self {
        Self {
            from,
            to,
            lever,
            kind,
            samples: 0,
            inside: 0,
            lo: f64::INFINITY,
            hi: f64::NEG_INFINITY,
            stiffening: 0.0,
        }
    }

    /// Adds one sample of the truth's angles `theta` (rad, one per node).
    pub fn add(&mut self, theta: &[f64]) {
        let d = self.lever * theta[self.from] - theta[self.to];
        if !d.is_finite() {
            return;
        }
        self.samples += 1;
        match self.kind {
            Kind::Play { half_rad } => {
                if d.abs() < half_rad {
                    self.inside += 1;
                }
                self.lo = self.lo.min(d / half_rad);
                self.hi = self.hi.max(d / half_rad);
            }
            Kind::Twist { static_rad, law } => {
                self.hi = self.hi.max(d.abs() / static_rad);
                self.stiffening = self.stiffening.max(law.factor(d) - 1.0);
            }
        }
    }

    /// What the recording exercised; `None` before any finite sample.
    pub fn result(&self) -> Option<Exercise> {
        (self.samples > 0).then(|| match self.kind {
            Kind::Play { .. } => Exercise::Play {
                inside: self.inside as f64 / self.samples as f64,
                min_over_half: self.lo,
                max_over_half: self.hi,
            },
            Kind::Twist { .. } => Exercise::Twist {
                max_over_static: self.hi,
                max_stiffening: self.stiffening,
            },
        })
    }
}

impl Exercise {
    /// `truth.toml`'s inline table for one recording.
    pub fn toml(&self) -> String {
        match *self {
            Exercise::Play {
                inside,
                min_over_half,
                max_over_half,
            } => format!(
                "{{ inside_play = {inside:.4}, twist_over_half_backlash = [{min_over_half:.3}, {max_over_half:.3}] }}"
            ),
            Exercise::Twist {
                max_over_static,
                max_stiffening,
            } => format!(
                "{{ twist_over_static = {max_over_static:.3}, max_stiffening = {max_stiffening:.4} }}"
            ),
        }
    }

    /// One number per case for `results.csv`, the largest over its recordings: the
    /// fraction of samples inside the play, or the largest secant stiffening.
    pub fn headline(all: &[Exercise]) -> Option<f64> {
        all.iter()
            .map(|e| match *e {
                Exercise::Play { inside, .. } => inside,
                Exercise::Twist { max_stiffening, .. } => max_stiffening,
            })
            .reduce(f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::AmplitudeLaw;

    #[test]
    fn the_play_fraction_counts_samples_inside_the_half_backlash() {
        // Gear 2:1 from node 0 to node 1, h = 0.01 rad: δ = 2·θ0 − θ1.
        let mut m = Meter::new(0, 1, 2.0, Kind::Play { half_rad: 0.01 });
        for d in [0.005, -0.009, 0.011, 0.02, -0.03] {
            m.add(&[d / 2.0, 0.0]);
        }
        m.add(&[f64::NAN, 0.0]);
        let Some(Exercise::Play {
            inside,
            min_over_half,
            max_over_half,
        }) = m.result()
        else {
            panic!("a play measure")
        };
        assert_eq!(inside, 2.0 / 5.0, "two of five finite samples inside");
        assert!((min_over_half + 3.0).abs() < 1e-12, "{min_over_half}");
        assert!((max_over_half - 2.0).abs() < 1e-12, "{max_over_half}");
    }

    #[test]
    fn the_twist_measure_is_the_peak_over_the_static_twist_and_its_stiffening() {
        let law = AmplitudeLaw::Power { a: 100.0, p: 1.0 };
        let mut m = Meter::new(
            0,
            1,
            1.0,
            Kind::Twist {
                static_rad: 0.002,
                law,
            },
        );
        assert_eq!(m.result(), None, "nothing before a sample");
        for d in [0.002, -0.006, 0.001] {
            m.add(&[d, 0.0]);
        }
        let Some(Exercise::Twist {
            max_over_static,
            max_stiffening,
        }) = m.result()
        else {
            panic!("a twist measure")
        };
        // |Δθ| peaks at 0.006 = 3 static twists; g − 1 = 100·0.006 = 0.6 there.
        assert!((max_over_static - 3.0).abs() < 1e-12, "{max_over_static}");
        assert!((max_stiffening - 0.6).abs() < 1e-12, "{max_stiffening}");
        let all = [m.result().expect("measured")];
        assert_eq!(Exercise::headline(&all), Some(max_stiffening));
        assert_eq!(Exercise::headline(&[]), None);
    }
}
