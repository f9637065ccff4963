//! The truth's equations of motion: every node's absolute angle and speed in its own
//! shaft, the rubber stages' Maxwell branches (`visco.rs`), a Dahl friction state, a
//! rubber temperature, and the bench's speed controller at the load node. Implements
//! [`System`] for the RK4 integrator.

use crate::driveline::{Driveline, Kind};
use crate::effects::{
    AmplitudeLaw, BacklashLaw, CylinderLaw, Effect, FrequencyLaw, HystereticLaw, Thermal,
};
use crate::engine::{EngineLaw, Kinematics};
use crate::fitpoints;
use crate::integrate::System;
use crate::visco::{Anchor, Bank};
use std::f64::consts::TAU;

/// Bandwidth of the dyno's speed loop, Hz (a bench dyno holds the mean speed slowly).
const CONTROL_BANDWIDTH_HZ: f64 = 0.2;
/// Corner of the low-pass on the speed error of the loop's proportional part, Hz.
const CONTROL_FILTER_HZ: f64 = 1.0;

/// Bound on a Dahl state's relaxation rate σ·|Δθ̇|/F_c over its value at the sizing
/// pre-run's twist rate amplitude: the RK4 step (at most 0.5/rate, `sim.rs`) then stays
/// stable (λh < 2.78) up to 5.6× this margin, 17× the sized twist rate, which covers a
/// run-up through resonance and the start from the static twist.
const DAHL_RATE_MARGIN: f64 = 3.0;

/// A connection's law in the truth.
#[derive(Debug, Clone)]
enum Link {
    Linear {
        k: f64,
        c: f64,
    },
    Visco {
        bank: Bank,
        amp: Option<AmplitudeLaw>,
        thermal: Option<(Thermal, usize)>,
        off: usize,
        /// Static twist under the mean torque, rad: the bank's vibration is about it.
        phi_s: f64,
    },
    Dahl {
        k: f64,
        fc: f64,
        sigma: f64,
        off: usize,
    },
    Gear {
        k: f64,
        c: f64,
        play: Option<BacklashLaw>,
    },
}

/// The reference speed the bench's controller follows (engine shaft, rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Profile {
    /// Settling time before the recording starts, s.
    pub settle_s: f64,
    pub from_rpm: f64,
    pub to_rpm: f64,
    /// Ramp (or hold) duration after settling, s.
    pub duration_s: f64,
    /// Slow wobble of the mean speed: relative amplitude and period.
    pub wobble: f64,
    pub wobble_period_s: f64,
    pub wobble_phase: f64,
}

impl Profile {
    /// (Ω_ref, dΩ_ref/dt) at t, rad/s.
    pub fn at(&self, t: f64) -> (f64, f64) {
        let rate = (self.to_rpm - self.from_rpm) / self.duration_s.max(1e-9);
        let (rpm, drpm) = if t <= self.settle_s {
            (self.from_rpm, 0.0)
        } else if t >= self.settle_s + self.duration_s {
            (self.to_rpm, 0.0)
        } else {
            (self.from_rpm + rate * (t - self.settle_s), rate)
        };
        let w = TAU / self.wobble_period_s;
        let s = 1.0 + self.wobble * (w * t + self.wobble_phase).sin();
        let ds = self.wobble * w * (w * t + self.wobble_phase).cos();
        let k = TAU / 60.0;
        (k * rpm * s, k * (drpm * s + rpm * ds))
    }
}

/// The truth integrated for one recording.
#[derive(Debug, Clone)]
pub struct Plant {
    pub n: usize,
    inertia: Vec<f64>,
    /// Each node's `damping` to the frame, N·m·s/rad in its own shaft, on its vibration.
    damping: Vec<f64>,
    conns: Vec<(usize, usize, f64, Link)>,
    engine: EngineLaw,
    engine_node: usize,
    load_node: usize,
    load_ratio: f64,
    kp: f64,
    kc: f64,
    ki: f64,
    t_mean: f64,
    j_ref: f64,
    pub profile: Profile,
    /// Length of the state vector; the controller's filtered error and integral are
    /// the last two entries.
    pub len: usize,
    /// The highest relaxation rate of any branch, 1/s (for the step size).
    pub fastest_rate: f64,
    pub speed_ratio: Vec<f64>,
}

/// The model's band over which rubber laws are fitted, Hz (`fitpoints.rs`).
#[derive(Debug, Clone, Copy)]
pub struct Band {
    pub lo_hz: f64,
    pub hi_hz: f64,
}

impl Plant {
    /// Builds the truth of `d` with `effect` at engine `load`, following `profile`; its
    /// rubber banks fitted over the model's `band` and at the modes of `d` at this load.
    pub fn new(d: &Driveline, effect: &Effect, load: f64, profile: Profile, band: Band) -> Self {
        let n = d.nodes.len();
        let mut off = 2 * n;
        let mut conns = Vec::new();
        let mut fastest: f64 = 0.0;
        let kin = match effect {
            Effect::CrankVariableInertia { exact: true } => Kinematics::Exact,
            _ => Kinematics::FirstOrder,
        };
        let mut engine = EngineLaw::new(&d.engine, load, kin);
        if let Effect::CylinderImbalance { cylinder, law } = effect {
            let healthy = engine.pressure_pa[*cylinder].clone();
            engine.pressure_pa[*cylinder] = unequal_cylinder(&healthy, law);
        }
        let t_mean = engine.mean_torque();
        let amp_of = |i: usize| match effect {
            Effect::AmplitudeNonlinearity { conn, law } if *conn == i => Some(*law),
            _ => None,
        };
        let freq_of = |i: usize| match effect {
            Effect::FrequencyDependence { conn, law } if *conn == i => Some(*law),
            _ => None,
        };
        // Each rubber stage's static twist and tangent factor d(g·x)/dx there.
        let torques = fitpoints::static_torques(d, t_mean);
        let statics: Vec<(f64, f64)> = d
            .connections
            .iter()
            .enumerate()
            .map(|(i, c)| match c.kind {
                Kind::Rubber { stiffness, .. } => static_point(stiffness, amp_of(i), torques[i]),
                _ => (0.0, 1.0),
            })
            .collect();
        // The nominal system's stiffness factors: rubber stages at their tangent at the
        // static twist times their frequency factor at the mode's own frequency.
        let factor = |i: usize, f: f64| match d.connections[i].kind {
            Kind::Rubber { psi, .. } => {
                statics[i].1
                    * freq_of(i).map_or(1.0, |law| frequency_target(&law, 1.0, psi / TAU, f).0)
            }
            _ => 1.0,
        };
        let modes = fitpoints::modes_with_shares(d, &factor);
        for (i, c) in d.connections.iter().enumerate() {
            let link = match c.kind {
                Kind::Shaft { stiffness, damping } => Link::Linear {
                    k: stiffness,
                    c: damping,
                },
                Kind::Gear {
                    mesh_stiffness,
                    mesh_damping,
                    ..
                } => Link::Gear {
                    k: mesh_stiffness,
                    c: mesh_damping,
                    play: match effect {
                        Effect::GearBacklash { conn, law } if *conn == i => Some(*law),
                        _ => None,
                    },
                },
                Kind::Rubber { stiffness, psi } => {
                    let xi = psi / TAU;
                    match effect {
                        Effect::Hysteretic {
                            conn,
                            law:
                                HystereticLaw::Dahl {
                                    f_c_nm,
                                    sigma_nm_per_rad,
                                    twist_rate_rad_s,
                                },
                        } if *conn == i => {
                            // The friction state relaxes at σ·|Δθ̇|/F_c: bounded from the
                            // sized twist rate with a margin for resonances and the start.
                            fastest = fastest.max(
                                DAHL_RATE_MARGIN * sigma_nm_per_rad * twist_rate_rad_s
                                    / f_c_nm.max(f64::MIN_POSITIVE),
                            );
                            let l = Link::Dahl {
                                k: stiffness,
                                fc: *f_c_nm,
                                sigma: *sigma_nm_per_rad,
                                off,
                            };
                            off += 1;
                            l
                        }
                        _ => {
                            let at = fitpoints::for_connection(&modes, i);
                            let bank = match freq_of(i) {
                                Some(law) => Bank::fit(
                                    |f| frequency_target(&law, stiffness, xi, f),
                                    match law {
                                        FrequencyLaw::PowerLaw { .. } => Anchor::BelowArms,
                                        FrequencyLaw::FractionalZener { .. } => Anchor::Rest,
                                    },
                                    band.lo_hz,
                                    band.hi_hz,
                                    &at,
                                ),
                                None => Bank::fit(
                                    |_| (stiffness, stiffness * xi),
                                    Anchor::Rest,
                                    band.lo_hz,
                                    band.hi_hz,
                                    &at,
                                ),
                            };
                            fastest = bank.rate.iter().fold(fastest, |a, &b| a.max(b));
                            let amp = amp_of(i);
                            let nb = bank.k.len();
                            let thermal = match effect {
                                Effect::ThermalDrift { conn, law } if *conn == i => {
                                    Some((*law, off + nb))
                                }
                                _ => None,
                            };
                            let l = Link::Visco {
                                bank,
                                amp,
                                thermal,
                                off,
                                phi_s: statics[i].0,
                            };
                            off += nb + thermal.is_some() as usize;
                            l
                        }
                    }
                }
            };
            conns.push((c.from, c.to, c.lever(), link));
        }
        let speed_ratio = d.speed_ratios();
        let j_ref: f64 = (0..n)
            .map(|i| d.nodes[i].inertia_kg_m2 * speed_ratio[i].powi(2))
            .sum();
        let load_ratio = speed_ratio[d.load_node];
        let j_load = j_ref / load_ratio.powi(2);
        let kp = d.load_damping_nm_s;
        // The dyno's own speed loop, independent of the drawn load damping (which is the
        // `[load] damping` the model file declares): bandwidth 0.2 Hz, its proportional
        // part on the speed error low-passed at 1 Hz so that at the driveline's modes
        // (≥ 5 Hz) it is a spring to the reference of (c·a + k_i) ≈ 12.6·J_load rad²/s²,
        // under 0.4 % of the load's inertia force J_load·ω² at 10 Hz. Closed loop (J_load
        // alone): s³ + 6.3 s² + 12.6 s + 9.9, poles −3.4 and −1.4 ± 1.0i (settles in ~3 s).
        let wn = TAU * CONTROL_BANDWIDTH_HZ;
        Plant {
            n,
            inertia: d.nodes.iter().map(|x| x.inertia_kg_m2).collect(),
            damping: d.nodes.iter().map(|x| x.damping_nm_s).collect(),
            conns,
            engine,
            engine_node: d.engine.node,
            load_node: d.load_node,
            load_ratio,
            kp,
            kc: 1.4 * j_load * wn,
            ki: j_load * wn * wn,
            t_mean,
            j_ref,
            profile,
            len: off + 2,
            fastest_rate: fastest,
            speed_ratio,
        }
    }

    /// Rotor state at t = 0: every node at its share of the reference speed, twisted by
    /// the mean torque only through the controller (the settling time takes the rest);
    /// the rubber branches relaxed at their stage's static twist.
    pub fn initial_state(&self) -> Vec<f64> {
        let mut y = vec![0.0; self.len];
        let (w, _) = self.profile.at(0.0);
        for i in 0..self.n {
            y[self.n + i] = w * self.speed_ratio[i];
        }
        for (_, _, _, link) in &self.conns {
            if let Link::Visco {
                bank, off, phi_s, ..
            } = link
            {
                y[*off..*off + bank.k.len()].fill(*phi_s);
            }
        }
        y
    }

    /// Mean engine torque at this load, N·m.
    pub fn mean_torque(&self) -> f64 {
        self.t_mean
    }

    /// Power dissipated in the rubber branches and friction at state `y`, W (for sizing).
    pub fn rubber_loss_w(&self, y: &[f64]) -> f64 {
        let mut dy = vec![0.0; self.len];
        self.derivative(0.0, y, &mut dy);
        let mut p = 0.0;
        for (from, to, g, link) in &self.conns {
            let d = g * y[*from] - y[*to];
            if let Link::Visco { bank, off, .. } = link {
                for (j, k) in bank.k.iter().enumerate() {
                    p += k * (d - y[off + j]) * dy[off + j];
                }
            }
            if let Link::Dahl { off, .. } = link {
                p += y[*off] * (g * y[self.n + from] - y[self.n + to]);
            }
        }
        p
    }
}

/// A rubber stage's static twist under the mean torque `torque` (N·m) on the static curve
/// `k·g(x)·x`, and its tangent factor `d(g·x)/dx` there: (rad, 1).
fn static_point(k: f64, amp: Option<AmplitudeLaw>, torque: f64) -> (f64, f64) {
    let Some(law) = amp else {
        return (torque / k, 1.0);
    };
    let curve = |x: f64| law.factor(x) * x;
    // g ≥ 1: the twist lies between 0 and the linear one; bisection on the monotone curve.
    let (mut a, mut b) = (0.0f64, torque / k);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if (curve(m) - torque / k) * (curve(a) - torque / k) <= 0.0 {
            b = m;
        } else {
            a = m;
        }
    }
    let x = 0.5 * (a + b);
    let h = 1e-6 * x.abs().max(1e-4);
    (x, (curve(x + h) - curve(x - h)) / (2.0 * h))
}

/// The target complex stiffness of a frequency-dependent rubber at `f` Hz.
fn frequency_target(law: &FrequencyLaw, k: f64, xi: f64, f: f64) -> (f64, f64) {
    match *law {
        FrequencyLaw::PowerLaw { n, f0_hz } => {
            // A causal power law carries the loss factor tan(nπ/2) (Kramers–Kronig); the
            // rubber's own ψ is kept if larger.
            let s = k * (f / f0_hz).powf(n);
            (s, s * xi.max((n * std::f64::consts::FRAC_PI_2).tan()))
        }
        FrequencyLaw::FractionalZener {
            delta,
            alpha,
            f_relax_hz,
            f0_hz,
        } => {
            let z = |f: f64| {
                // (iωτ)^α = x^α·(cos(απ/2) + i sin(απ/2)), x = f/f_relax
                let x = (f / f_relax_hz).powf(alpha);
                let (c, s) = (
                    (alpha * std::f64::consts::FRAC_PI_2).cos(),
                    (alpha * std::f64::consts::FRAC_PI_2).sin(),
                );
                let (nr, ni) = (x * c, x * s);
                let (dr, di) = (1.0 + nr, ni);
                let m = dr * dr + di * di;
                (
                    1.0 + delta * (nr * dr + ni * di) / m,
                    delta * (ni * dr - nr * di) / m,
                )
            };
            let (r0, _) = z(f0_hz);
            let (r, i) = z(f);
            (k * r / r0, k * (i / r0 + xi * r / r0))
        }
    }
}

/// One cylinder's pressure table after its deviation (1° steps, −360…360°).
pub fn unequal_cylinder(p: &[f64], law: &CylinderLaw) -> Vec<f64> {
    // The motored curve: the compression half (−360…0°) mirrored about TDC.
    let motored: Vec<f64> = (0..=720)
        .map(|i| if i <= 360 { p[i] } else { p[720 - i] })
        .collect();
    match *law {
        CylinderLaw::Scale { scale } => p.iter().map(|x| x * scale).collect(),
        CylinderLaw::Misfire { residual } => (0..=720)
            .map(|i| motored[i] + residual * (p[i] - motored[i]))
            .collect(),
        CylinderLaw::Late { delay_deg, scale } => (0..=720)
            .map(|i| {
                let src = i as f64 - delay_deg;
                let j = src.floor().clamp(0.0, 719.0) as usize;
                let t = (src - j as f64).clamp(0.0, 1.0);
                let excess = |k: usize| p[k] - motored[k];
                motored[i] + scale * (excess(j) + t * (excess(j + 1) - excess(j)))
            })
            .collect(),
    }
}

impl System for Plant {
    fn derivative(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        let n = self.n;
        let mut torque = vec![0.0; n];
        let (w_ref, dw_ref) = self.profile.at(t);
        // A node's damping to the frame acts on its vibration, the speed about the
        // shaft's mean (`spec/model-format.md`: the stages' static twist is the one "the
        // engine's mean torque puts on each stage, with the load node holding it", so
        // no mean torque leaves the line on the way). On the absolute speed, as this
        // bench had it until 2026-11-29, it was a drag: 0.275 N·m·s/rad at the crank
        // took 86 N·m at 3000 rpm, the gear of case 2087 carried less than nothing, its
        // teeth sat on the other flank, and no model written from the spec could
        // reproduce the recordings (held-out χ²/N 158 for the exact truth, 1.17 with
        // this).
        for i in 0..n {
            dy[i] = y[n + i];
            torque[i] = -self.damping[i] * (y[n + i] - self.speed_ratio[i] * w_ref);
        }
        for (from, to, g, link) in &self.conns {
            let d = g * y[*from] - y[*to];
            let dd = g * y[n + from] - y[n + to];
            let tq = match link {
                Link::Linear { k, c } => k * d + c * dd,
                Link::Gear { k, c, play } => {
                    let s = play.map_or(d, |p| p.deflection(d));
                    k * s + c * dd
                }
                Link::Dahl { k, fc, sigma, off } => {
                    let f = y[*off];
                    dy[*off] = sigma * dd * (1.0 - f / fc * dd.signum());
                    k * d + f
                }
                Link::Visco {
                    bank,
                    amp,
                    thermal,
                    off,
                    phi_s,
                } => {
                    let s = thermal.map_or(1.0, |(th, i)| th.softening.factor(y[i]));
                    let g0 = amp.map_or(1.0, |a| a.factor(d));
                    // The static curve holds the twist; the bank's equilibrium spring
                    // acts on the vibration about the static twist.
                    let mut tq =
                        bank.k_static * g0 * d + (bank.k_inf - bank.k_static) * (d - phi_s);
                    let mut loss = 0.0;
                    for (j, (k, l)) in bank.k.iter().zip(&bank.rate).enumerate() {
                        let u = y[off + j];
                        let du = l * (d - u);
                        dy[off + j] = du;
                        tq += k * (d - u);
                        loss += k * (d - u) * du;
                    }
                    if let Some((th, i)) = thermal {
                        dy[*i] = (s * loss - th.conductance_w_per_k * y[*i]) / th.capacity_j_per_k;
                    }
                    s * tq
                }
            };
            torque[*to] += tq;
            torque[*from] -= g * tq;
        }
        let e = y[n + self.load_node] - self.load_ratio * w_ref;
        // Feed-forward: the engine's mean torque less what accelerates the line, referred
        // to the load shaft (power balance).
        let ff = (self.t_mean - self.j_ref * dw_ref) / self.load_ratio;
        let e_f = y[self.len - 2];
        torque[self.load_node] -= ff + self.kp * e + self.kc * e_f + self.ki * y[self.len - 1];
        dy[self.len - 2] = TAU * CONTROL_FILTER_HZ * (e - e_f);
        dy[self.len - 1] = e;
        let en = self.engine_node;
        let (te, jv) = self.engine.torque(y[en], y[n + en]);
        torque[en] += te;
        for i in 0..n {
            let j = self.inertia[i] + if i == en { jv } else { 0.0 };
            dy[n + i] = torque[i] / j;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cylinder_laws_change_only_the_combustion() {
        let p: Vec<f64> = (0..=720)
            .map(|i| {
                let a = i as f64 - 360.0;
                1e5 * (10.0 * (-(a / 60.0).powi(2)).exp()
                    + 40.0 * (-((a - 12.0) / 14.0).powi(2)).exp())
            })
            .collect();
        let scaled = unequal_cylinder(&p, &CylinderLaw::Scale { scale: 0.9 });
        assert!((scaled[372] / p[372] - 0.9).abs() < 1e-12);
        let mis = unequal_cylinder(&p, &CylinderLaw::Misfire { residual: 0.0 });
        // a misfire keeps compression (before TDC) and loses the combustion bump
        assert_eq!(mis[300], p[300]);
        assert!(mis[372] < 0.5 * p[372]);
        let late = unequal_cylinder(
            &p,
            &CylinderLaw::Late {
                delay_deg: 6.0,
                scale: 1.0,
            },
        );
        let peak = |v: &[f64]| {
            (360..500)
                .max_by(|&a, &b| v[a].total_cmp(&v[b]))
                .unwrap_or(0)
        };
        assert!(peak(&late) > peak(&p));
    }
}
