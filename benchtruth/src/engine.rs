//! The engine's torque on the crank, per cylinder (seed 001 eq. 3–5): gas torque
//! `p·A·r_v(φ)` and the reciprocating masses' inertia torque `−m·(φ̇²·r_a + φ̈·r_v)·r_v`,
//! whose φ̈ part is an angle-dependent inertia `m·r_v²` kept on the left-hand side.
//! Kinematics first order in λ = r/l (eq. 4) or, for the `exact` form of the variable
//! inertia effect, the exact slider-crank velocity ratio.

use crate::driveline::{Engine, PressureCurve};

/// Slider-crank kinematics used for the reciprocating masses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kinematics {
    /// Seed 001 eq. 4: r_v = r(sin φ + λ/2 sin 2φ), r_a = r(cos φ + λ cos 2φ).
    FirstOrder,
    /// Exact: r_v = r sin φ (1 + λ cos φ / √(1 − λ² sin² φ)), r_a = d r_v/dφ.
    Exact,
}

/// The engine as the integrator sees it at one load: per-cylinder pressure tables at
/// 1° steps over −360…360° (Pa, gauge), and the mass data.
#[derive(Debug, Clone)]
pub struct EngineLaw {
    pub firing_rad: Vec<f64>,
    pub area_m2: f64,
    pub r_m: f64,
    pub lambda: f64,
    pub recip_kg: f64,
    pub kinematics: Kinematics,
    /// One table per cylinder, 721 samples at −360, −359 … 360°.
    pub pressure_pa: Vec<Vec<f64>>,
}

/// Linear interpolation in a sorted table (held at the ends).
pub fn interp(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    if x <= xs[0] {
        return ys[0];
    }
    for i in 1..xs.len() {
        if x <= xs[i] {
            let t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
            return ys[i - 1] + t * (ys[i] - ys[i - 1]);
        }
    }
    ys[ys.len() - 1]
}

/// The gauge pressure curve at `load`, linearly between the tables (spec
/// `pressure_by_load`), sampled at 1° steps.
pub fn curve_at_load(curves: &[PressureCurve], load: f64) -> Vec<f64> {
    let one = |c: &PressureCurve| -> Vec<f64> {
        (0..=720)
            .map(|i| interp(&c.angle_deg, &c.bar, i as f64 - 360.0) * 1e5)
            .collect()
    };
    if curves.len() == 1 || load <= curves[0].load {
        return one(&curves[0]);
    }
    for w in curves.windows(2) {
        if load <= w[1].load {
            let t = (load - w[0].load) / (w[1].load - w[0].load);
            let (a, b) = (one(&w[0]), one(&w[1]));
            return a.iter().zip(&b).map(|(x, y)| x + t * (y - x)).collect();
        }
    }
    one(&curves[curves.len() - 1])
}

impl EngineLaw {
    /// The law of `e` at `load` with `kinematics` for the masses.
    pub fn new(e: &Engine, load: f64, kinematics: Kinematics) -> Self {
        let table = curve_at_load(&e.pressure, load);
        EngineLaw {
            firing_rad: e.firing_deg.iter().map(|d| d.to_radians()).collect(),
            area_m2: std::f64::consts::PI * e.bore_m * e.bore_m / 4.0,
            r_m: e.crank_radius_m,
            lambda: e.crank_radius_m / e.conrod_m,
            recip_kg: e.reciprocating_kg,
            kinematics,
            pressure_pa: vec![table; e.firing_deg.len()],
        }
    }

    /// Gas pressure of cylinder `i` at crank angle φ from its firing TDC (rad), 720° periodic.
    pub fn pressure(&self, i: usize, phi: f64) -> f64 {
        let deg = (phi.to_degrees() + 360.0).rem_euclid(720.0);
        let k = (deg.floor() as usize).min(719);
        let t = deg - k as f64;
        let p = &self.pressure_pa[i];
        p[k] + t * (p[k + 1] - p[k])
    }

    /// Velocity ratio r_v and its derivative r_a at φ.
    pub fn ratios(&self, phi: f64) -> (f64, f64) {
        let (r, l) = (self.r_m, self.lambda);
        match self.kinematics {
            Kinematics::FirstOrder => (
                r * (phi.sin() + 0.5 * l * (2.0 * phi).sin()),
                r * (phi.cos() + l * (2.0 * phi).cos()),
            ),
            Kinematics::Exact => {
                let rv = |p: f64| {
                    let s = p.sin();
                    r * s * (1.0 + l * p.cos() / (1.0 - l * l * s * s).sqrt())
                };
                let h = 1e-5;
                (rv(phi), (rv(phi + h) - rv(phi - h)) / (2.0 * h))
            }
        }
    }

    /// At crank angle θ (absolute, rad) and speed ω: (torque without the φ̈ term, the
    /// angle-dependent inertia Σ m·r_v²).
    pub fn torque(&self, theta: f64, omega: f64) -> (f64, f64) {
        let mut t = 0.0;
        let mut j = 0.0;
        for (i, f) in self.firing_rad.iter().enumerate() {
            let phi = theta - f;
            let (rv, ra) = self.ratios(phi);
            t +=
                self.pressure(i, phi) * self.area_m2 * rv - self.recip_kg * omega * omega * ra * rv;
            j += self.recip_kg * rv * rv;
        }
        (t, j)
    }

    /// Cycle-mean torque at constant speed (the gas work per cycle over 4π).
    pub fn mean_torque(&self) -> f64 {
        let n = 2880;
        (0..n)
            .map(|k| {
                self.torque(k as f64 / n as f64 * 2.0 * std::f64::consts::TAU, 0.0)
                    .0
            })
            .sum::<f64>()
            / n as f64
    }
}

/// A four-stroke gauge pressure curve (bar at integer degrees from firing TDC): a
/// polytropic compression/expansion (κ = 1.32, compression ratio `eps`) plus a Gaussian
/// combustion bump of `peak_bar` at `peak_deg` after TDC, intake at `intake_bar` gauge.
pub fn pressure_curve(
    eps: f64,
    peak_bar: f64,
    peak_deg: f64,
    intake_bar: f64,
) -> (Vec<f64>, Vec<f64>) {
    let mut ang = Vec::new();
    let mut bar = Vec::new();
    let mut a = -360.0f64;
    while a <= 360.0 {
        let phi = a.to_radians();
        // Volume over clearance volume (λ ≈ 0.3 slider crank, first order).
        let v = 1.0 + (eps - 1.0) / 2.0 * (1.0 - phi.cos() + 0.15 * (1.0 - (2.0 * phi).cos()));
        let p_abs = if (-180.0..=180.0).contains(&a) {
            (1.0 + intake_bar) * (eps / v).powf(1.32)
                + peak_bar * (-((a - peak_deg) / 14.0).powi(2)).exp()
        } else {
            1.0 + intake_bar
        };
        ang.push(a);
        bar.push(((p_abs - 1.0) * 100.0).round() / 100.0);
        a += if a.abs() < 60.0 { 2.0 } else { 10.0 };
    }
    (ang, bar)
}
