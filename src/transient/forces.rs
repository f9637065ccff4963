//! The equations of motion of a [`Plant`]:
//! `M_i(θ*)·(α + ω̇_i) = Σ torques on DOF i`, with the engine's inertia `J + Σ m r_v(φ)²`
//! varying with crank angle (seed 001 eq. 3: the `φ̈·r_v` term moves to the left side),
//! `α` the mean angular acceleration of a ramp, and the Maxwell arms and rubber
//! temperatures as further states.

use super::crank_angle::{CrankAnchor, wrap};
use super::plant::{GOVERNOR_FILTER_HZ, Plant, PlantElement, PlantLaw, RubberPlant, Temperature};
use super::speed::SpeedProfile;
use crate::model::AmplitudeForm;
use std::f64::consts::TAU;

/// What one element does at one state: referred torque and dissipated power.
#[derive(Debug, Clone, Copy, Default)]
pub struct ElementState {
    /// Torque passed from `from` to `to`, referred, N·m.
    pub torque_ref_nm: f64,
    /// Power dissipated in its damping, W.
    pub power_w: f64,
}

/// What one run's right-hand side keeps between evaluations: the per-DOF inertia, which
/// the reciprocating masses vary with crank angle, and the crank angle's last sine and
/// cosine ([`CrankAnchor`]). One per run, never shared between runs.
#[derive(Debug, Clone)]
pub struct Scratch {
    mass: Vec<f64>,
    crank: CrankAnchor,
}

impl Scratch {
    /// Scratch for a plant of `n_dof` degrees of freedom.
    pub fn new(n_dof: usize) -> Self {
        Self {
            mass: vec![0.0; n_dof],
            crank: CrankAnchor::default(),
        }
    }
}

impl Plant {
    /// `ratio·(x_from − x_to)` of a per-DOF quantity `x`, in the element's own shaft: its
    /// twist, rad, from the angles `y`, and the twist's rate, rad/s, from the speeds
    /// `&y[n_dof..]`.
    fn own_relative(e: &PlantElement, x: &[f64]) -> f64 {
        let a = e.from_dof.map_or(0.0, |d| x[d]);
        let b = e.to_dof.map_or(0.0, |d| x[d]);
        e.ratio * (a - b)
    }

    /// Torque and dissipation of element `e` at state `y`; writes the arm derivatives of
    /// a rubber stage into `dy` when given.
    #[inline]
    pub fn element_state(
        &self,
        e: &PlantElement,
        y: &[f64],
        dy: Option<&mut [f64]>,
    ) -> ElementState {
        let n = self.n_dof;
        match &e.law {
            PlantLaw::Linear { stiffness, damping } => {
                let twist = e.from_dof.map_or(0.0, |d| y[d]) - e.to_dof.map_or(0.0, |d| y[d]);
                let rate =
                    e.from_dof.map_or(0.0, |d| y[n + d]) - e.to_dof.map_or(0.0, |d| y[n + d]);
                ElementState {
                    torque_ref_nm: stiffness * twist + damping * rate,
                    power_w: damping * rate * rate,
                }
            }
            PlantLaw::Backlash {
                stiffness_own,
                damping_own,
                contact,
            } => {
                let contact = contact.deflection(Self::own_relative(e, y));
                let rate_own = Self::own_relative(e, &y[n..]);
                ElementState {
                    torque_ref_nm: (stiffness_own * contact + damping_own * rate_own) * e.ratio,
                    power_w: damping_own * rate_own * rate_own,
                }
            }
            PlantLaw::Rubber(r) => {
                let own = [Self::own_relative(e, y), Self::own_relative(e, &y[n..])];
                rubber_state(r, own, e.ratio, y, dy)
            }
        }
    }

    /// Derivatives `dy = f(t, y)` for the speed profile `profile`, with the run's
    /// `scratch` (of this plant's `n_dof`).
    pub fn derivatives(
        &self,
        t: f64,
        y: &[f64],
        dy: &mut [f64],
        profile: &SpeedProfile,
        scratch: &mut Scratch,
    ) {
        let n = self.n_dof;
        let (phi_m, big_omega, alpha) = profile.at(t);
        let mass = &mut scratch.mass;
        mass.copy_from_slice(&self.inertia_kg_m2);
        dy[..n].copy_from_slice(&y[n..2 * n]);
        for i in 0..n {
            dy[n + i] = -self.damping_nm_s_per_rad[i] * y[n + i];
        }
        // Modal damping (`[modal_damping]`): the full matrix C_m of the linear system.
        if let Some(c) = &self.system.modal_damping {
            for i in 0..n {
                dy[n + i] -= (0..n).map(|j| c[(i, j)] * y[n + j]).sum::<f64>();
            }
        }
        for e in &self.elements {
            let s = self.element_state(e, y, Some(dy));
            if let Some(d) = e.from_dof {
                dy[n + d] -= s.torque_ref_nm;
            }
            if let Some(d) = e.to_dof {
                dy[n + d] += s.torque_ref_nm;
            }
            if let PlantLaw::Rubber(r) = &e.law
                && let Temperature::Thermal {
                    state,
                    capacity_j_per_k,
                    conductance_w_per_k,
                    ambient_c,
                } = r.temperature
            {
                dy[state] =
                    (s.power_w - conductance_w_per_k * (y[state] - ambient_c)) / capacity_j_per_k;
            }
        }
        if let Some(engine) = &self.engine {
            let m = engine.oscillating_mass_kg;
            let (r, lambda) = (engine.crank_radius_m, engine.lambda);
            // The mean angle wrapped to the cycle once: each cylinder's angle is that plus
            // its DOF's vibration θ minus its firing angle. sin/cos(φ_m + θ) of the last
            // DOF worked out is kept: an engine's cylinders share their node, and θ is not
            // always small (a run-up's crank strays from the measured ramp by up to 3 rad),
            // where each cylinder paid a `sincos` of its own (14 % of a thermal-drift
            // diagnosis, `perf`). Each DOF's is taken from the run's anchor
            // ([`CrankAnchor`]).
            // (Not `rem_euclid`: its `fmod` is exact and slow, 2 % of a thermal-drift
            // diagnosis; this is within an ulp of the mean angle, which carries that
            // rounding anyway.)
            let cycle = engine.cycle_rad;
            let phase_m = wrap(phi_m - (phi_m / cycle).floor() * cycle, cycle);
            let mut last: Option<(usize, f64, f64)> = None;
            for c in &engine.cylinders {
                let speed = c.ratio * (big_omega + y[n + c.dof]);
                let (phase, s1, c1) = if c.ratio == 1.0 {
                    let offset = y[c.dof] - c.firing_rad;
                    let (s_a, c_a) = match last {
                        Some((dof, s_a, c_a)) if dof == c.dof => (s_a, c_a),
                        _ => {
                            let a = scratch.crank.sin_cos(phase_m + y[c.dof]);
                            last = Some((c.dof, a.0, a.1));
                            a
                        }
                    };
                    // sin/cos(φ_m + θ − α) with α's sine and cosine precomputed.
                    let (s_f, c_f) = c.firing_sin_cos;
                    (
                        wrap(phase_m + offset, engine.cycle_rad),
                        s_a * c_f - c_a * s_f,
                        c_a * c_f + s_a * s_f,
                    )
                } else {
                    let phi = c.ratio * (phi_m + y[c.dof]) - c.firing_rad;
                    let (s1, c1) = phi.sin_cos();
                    (phi.rem_euclid(engine.cycle_rad), s1, c1)
                };
                let (s2, c2) = (2.0 * s1 * c1, c1 * c1 - s1 * s1);
                let rv = r * (s1 + 0.5 * lambda * s2);
                let ra = r * (c1 + lambda * c2);
                let x = phase * engine.pressure_points_per_rad;
                let last = engine.pressure_pa.len() - 1;
                let k = (x as usize).min(last);
                // The next point, the first after the last (a `%` is an integer division).
                let next = engine.pressure_pa[if k == last { 0 } else { k + 1 }];
                let p = engine.pressure_pa[k] + (x - k as f64) * (next - engine.pressure_pa[k]);
                let torque_own =
                    p * c.pressure_scale * engine.area_m2 * rv - m * speed * speed * ra * rv;
                dy[n + c.dof] += torque_own * c.ratio;
                mass[c.dof] += m * rv * rv * c.ratio * c.ratio;
            }
        }
        let crank = phi_m + y[self.reference_dof];
        let speed_rpm = big_omega * 60.0 / TAU;
        for h in &self.harmonics {
            let amplitude = h.amplitude_nm(speed_rpm);
            dy[n + h.dof] += h.ratio * amplitude * (h.order * crank + h.phase_rad).cos();
        }
        if let Some(g) = &self.governor {
            let mean = self.engine.as_ref().map_or(0.0, |e| e.mean_torque_nm);
            dy[n + g.dof] += -mean + g.dissipation_torque_nm + g.total_inertia_kg_m2 * alpha;
            // The PI loop on the rigid-body coordinate, spread by inertia ([`Governor`]).
            let (mut rate, mut angle) = (0.0, -g.rigid_angle_ref_rad);
            for (i, w) in g.inertia_share.iter().enumerate() {
                rate += w * y[n + i];
                angle += w * y[i];
            }
            let filtered = y[g.filter_state];
            dy[g.filter_state] = TAU * GOVERNOR_FILTER_HZ * (rate - filtered);
            let correction = g.kp * filtered + g.ki * angle;
            for (i, w) in g.inertia_share.iter().enumerate() {
                dy[n + i] -= w * correction;
            }
        }
        for i in 0..n {
            dy[n + i] = dy[n + i] / mass[i] - alpha;
        }
    }
}

/// The amplitude law's static curve, temperature factors and the chain: the stage's
/// torque (own shaft) is
/// `c_Tstat·α_Tc(T)·[κ0·α_x(x)·φ + h'(φ)·D]`, with `D = (k∞ − κ0)(φ − φ_s) + a·
/// (Σ k_j (φ − q_j) + c_v φ̇)` (`a = α_Tξ(T)/α_Tξ(T0)`, the chain fitted at the stage's
/// own temperature `T0`) the chain's part above its static stiffness (seed 000
/// eq. 1–2, 10–15 with the causal chain of [`crate::rubber`]; `φ_s` the static twist the
/// chain vibrates about; `c_v` the dashpot of the arms taken out,
/// [`RubberPlant::viscous_s`]) and `h' = d(α_x x)/dx` the amplitude law's tangent. Slow
/// twist follows the static curve `κ0·α_x(x)·φ` exactly, and small vibration about `φ_s`
/// sees `c_Tstat·α_Tc·h'(φ_s)·K*(ω)`: the tangent times the chain, as the spec linearizes
/// the law (`model-format.md`, amplitude). With `amplitude_form = "elastic"` only the
/// static curve carries α_x (`h' = 1` on `D`): the arms, which carry the loss, are not
/// stiffened. `[twist_own, rate_own]`: rad, rad/s.
fn rubber_state(
    r: &RubberPlant,
    [twist_own, rate_own]: [f64; 2],
    ratio: f64,
    y: &[f64],
    dy: Option<&mut [f64]>,
) -> ElementState {
    let temperature = match r.temperature {
        Temperature::Fixed(t) => t,
        Temperature::Thermal { state, .. } => y[state],
    };
    let (alpha_x, tangent) = match (&r.amplitude_poly, &r.amplitude_saturation, r.mm_per_rad) {
        (Some(p), _, Some(mm)) => {
            let x = twist_own.abs() * mm;
            let secant = p.eval(x);
            (secant, secant + x * p.derivative(x))
        }
        (None, Some(s), Some(mm)) => {
            let x = twist_own.abs() * mm;
            (s.secant(x), s.tangent(x))
        }
        _ => (1.0, 1.0),
    };
    let alpha_tc = r
        .temperature_stiffness_poly
        .as_ref()
        .map_or(1.0, |p| p.eval(temperature));
    let alpha_txi = r
        .temperature_damping_poly
        .as_ref()
        .map_or(1.0, |p| p.eval(temperature))
        / r.damping_reference;
    let dynamic_scale = match r.amplitude_form {
        AmplitudeForm::Whole => tangent,
        AmplitudeForm::Elastic => 1.0,
    };
    let scale = r.static_stiffness_nm_per_rad * alpha_tc;
    let mut arms_torque = 0.0;
    let mut arms_power = 0.0;
    let mut dy = dy;
    let arms = r.chain.arms.iter().zip(&r.arm_rates_per_s).enumerate();
    for (j, (&(k, _), &rate)) in arms {
        let stretch = twist_own - y[r.arm_offset + j];
        arms_torque += k * stretch;
        arms_power += k * stretch * stretch * rate;
        if let Some(d) = dy.as_deref_mut() {
            d[r.arm_offset + j] = stretch * rate;
        }
    }
    arms_torque += r.viscous_s * rate_own;
    arms_power += r.viscous_s * rate_own * rate_own;
    let chain = &r.chain;
    let dynamic = (chain.equilibrium - chain.static_stiffness) * (twist_own - r.static_twist_rad)
        + alpha_txi * arms_torque;
    let torque_own =
        scale * (chain.static_stiffness * alpha_x * twist_own + dynamic_scale * dynamic);
    ElementState {
        torque_ref_nm: torque_own * ratio,
        power_w: scale * dynamic_scale * alpha_txi * arms_power,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stage of k0 = 5e4 N·m/rad with α_x = 1 + a2·x² (x = 100 mm/rad · |φ|), the
    /// `arms` of its chain, at 25 °C without temperature laws.
    fn cubic_plant(a2: f64, form: AmplitudeForm, arms: Vec<(f64, f64)>) -> RubberPlant {
        use crate::model::Poly;
        use crate::rubber::MaxwellChain;
        let arm_rates_per_s = arms.iter().map(|(_, tau)| 1.0 / tau).collect();
        RubberPlant {
            static_stiffness_nm_per_rad: 5.0e4,
            mm_per_rad: Some(100.0),
            amplitude_poly: Some(Poly {
                coeffs: [a2, 0.0, 1.0],
                range: None,
            }),
            amplitude_saturation: None,
            amplitude_form: form,
            temperature_stiffness_poly: None,
            temperature_damping_poly: None,
            damping_reference: 1.0,
            chain: MaxwellChain {
                equilibrium: 1.0,
                static_stiffness: 1.0,
                arms,
                band_hz: [10.0, 100.0],
                stiffness_error: 0.0,
                loss_error: 0.0,
            },
            static_twist_rad: 0.0,
            arm_offset: 0,
            arm_rates_per_s,
            viscous_s: 0.0,
            temperature: Temperature::Fixed(25.0),
        }
    }

    #[test]
    fn a_cubic_stage_has_the_harmonic_balance_stiffness_in_either_form() {
        // T = k0·(1 + a2·(100 φ)²)·φ; for φ = A sin ωt its first harmonic is
        // k0·(1 + ¾·a2·(100 A)²)·A (harmonic balance of a cubic spring).
        let (k0, a2, amp): (f64, f64, f64) = (5.0e4, 20.0, 2.0e-3);
        let expected = k0 * (1.0 + 0.75 * a2 * (100.0 * amp).powi(2));
        for form in [AmplitudeForm::Whole, AmplitudeForm::Elastic] {
            let plant = cubic_plant(a2, form, Vec::new());
            let n = 720;
            let b1: f64 = (0..n)
                .map(|i| {
                    let s = (TAU * i as f64 / n as f64).sin();
                    let t = rubber_state(&plant, [amp * s, 0.0], 1.0, &[], None).torque_ref_nm;
                    2.0 / n as f64 * t * s
                })
                .sum();
            // The rectangle rule is exact for this trigonometric polynomial (degree 3 <
            // 720): only rounding remains.
            let k_eq = b1 / amp;
            assert!(
                (k_eq - expected).abs() < 1e-12 * expected,
                "{form:?}: {k_eq} vs {expected}"
            );
        }
    }

    #[test]
    fn a_saturating_stage_carries_its_secant_law_at_every_twist() {
        // T = k0·(1 + s·tanh((x/x_s)²))·φ, x = 100·|φ| mm, from the quadratic start to
        // saturation, either sign (closed form; only rounding remains).
        let (k0, s, x_s) = (5.0e4, 0.4, 0.25);
        let mut plant = cubic_plant(0.0, AmplitudeForm::Elastic, Vec::new());
        plant.amplitude_poly = None;
        plant.amplitude_saturation = Some(crate::model::AmplitudeSaturation {
            stiffening: s,
            deformation_mm: x_s,
        });
        for phi in [1e-4, -1e-3, 2.5e-3, 4e-3, -2e-2] {
            let u = (100.0 * phi / x_s).powi(2);
            let expected = k0 * (1.0 + s * u.tanh()) * phi;
            let t = rubber_state(&plant, [phi, 0.0], 1.0, &[], None).torque_ref_nm;
            assert!((t - expected).abs() < 1e-12 * expected.abs(), "{phi}: {t}");
        }
    }

    #[test]
    fn the_elastic_form_leaves_the_arms_and_their_loss_unstiffened() {
        // At twist φ with one arm stretched by s: elastic T = k0·(α(φ)·φ + k1·s), loss
        // k0·k1·s²/τ; whole T = k0·(α(φ)·φ + h'(φ)·k1·s), loss h'(φ)·k0·k1·s²/τ with
        // h' = d(α x)/dx = 1 + 3·a2·x² the cubic's tangent.
        let (k0, a2, phi, s, k1, tau): (f64, f64, f64, f64, f64, f64) =
            (5.0e4, 20.0, 1.5e-3, 2.0e-4, 0.3, 0.01);
        let alpha = 1.0 + a2 * (100.0 * phi).powi(2);
        let tangent = 1.0 + 3.0 * a2 * (100.0 * phi).powi(2);
        let y = [phi - s];
        let at = |form| {
            let plant = cubic_plant(a2, form, vec![(k1, tau)]);
            let mut dy = [0.0];
            let st = rubber_state(&plant, [phi, 0.0], 1.0, &y, Some(&mut dy));
            assert!((dy[0] - s / tau).abs() < 1e-12 * s / tau);
            (st.torque_ref_nm, st.power_w)
        };
        let (t_e, p_e) = at(AmplitudeForm::Elastic);
        let (t_w, p_w) = at(AmplitudeForm::Whole);
        let loss = k0 * k1 * s * s / tau;
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12 * b.abs();
        assert!(close(t_e, k0 * (alpha * phi + k1 * s)), "{t_e}");
        assert!(close(p_e, loss), "{p_e}");
        assert!(close(t_w, k0 * (alpha * phi + tangent * k1 * s)), "{t_w}");
        assert!(close(p_w, tangent * loss), "{p_w}");
    }
}
