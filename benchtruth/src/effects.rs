//! The concealed effects of the truth, each in more than one functional form (issue 14,
//! item 3). Names are the identifiers of spec/diagnosis.md. Sizes are drawn in
//! `draw.rs`; the laws act in `plant.rs` (driveline) or `measure.rs` (sensors).

/// Every class the bench draws, in the order `seed mod 11` cycles through them.
pub const CLASSES: [&str; 11] = [
    "none",
    "parameter_error",
    "coupling_amplitude_nonlinearity",
    "coupling_frequency_dependence",
    "coupling_thermal_drift",
    "hysteretic_damping",
    "unmodelled_mode",
    "crank_variable_inertia",
    "gear_backlash",
    "cylinder_imbalance",
    "sensor_artifact",
];

/// Stiffness growing with twist Δθ (rad): the elastic torque is `k₀·g(Δθ)·Δθ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AmplitudeLaw {
    /// g = 1 + a·|Δθ|^p, p ∈ {1, 2, 3}.
    Power { a: f64, p: f64 },
    /// Progressive: g = 1 + a·tanh((Δθ/θ_s)²).
    Tanh { a: f64, theta_s: f64 },
}

impl AmplitudeLaw {
    /// The secant factor g(Δθ).
    pub fn factor(&self, d: f64) -> f64 {
        match *self {
            AmplitudeLaw::Power { a, p } => 1.0 + a * d.abs().powf(p),
            AmplitudeLaw::Tanh { a, theta_s } => 1.0 + a * ((d / theta_s).powi(2)).tanh(),
        }
    }
}

/// Frequency dependence of a rubber's storage stiffness.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FrequencyLaw {
    /// k(f) = k₀·(f/f₀)^n.
    PowerLaw { n: f64, f0_hz: f64 },
    /// Fractional Zener: k(iω) = k₀·(1 + Δ·(iωτ)^α/(1 + (iωτ)^α)) / (1 + Δ·x₀) normalised
    /// to k₀ at f₀.
    FractionalZener {
        delta: f64,
        alpha: f64,
        f_relax_hz: f64,
        f0_hz: f64,
    },
}

/// How the warm rubber softens.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Softening {
    /// k(T) = k·exp(−β·(T − T₀)).
    Exponential { beta_per_k: f64 },
    /// k(T) = k·(1 − β·(T − T₀)), held ≥ 0.3·k.
    Linear { beta_per_k: f64 },
}

impl Softening {
    /// The stiffness factor at a temperature rise `dt_k` above the start.
    pub fn factor(&self, dt_k: f64) -> f64 {
        match *self {
            Softening::Exponential { beta_per_k } => (-beta_per_k * dt_k).exp(),
            Softening::Linear { beta_per_k } => (1.0 - beta_per_k * dt_k).max(0.3),
        }
    }
}

/// Heat balance `C·dT/dt = P_loss − G·(T − T_amb)` of one rubber stage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Thermal {
    pub capacity_j_per_k: f64,
    pub conductance_w_per_k: f64,
    pub softening: Softening,
}

/// Damping that is frequency-independent per cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HystereticLaw {
    /// Structural: constant loss factor ξ over the band (causal bank, `visco.rs`).
    Structural,
    /// Dahl friction: dF/dt = σ·Δθ̇·(1 − F/F_c·sgn Δθ̇), beside the spring. σ (N·m/rad)
    /// is the contact's stiffness before sliding, a multiple of the spring's; F_c (N·m)
    /// the sliding torque, sized from the twist amplitude (`sizing.rs`); the state relaxes
    /// at σ·|Δθ̇|/F_c (1/s), which the RK4 step must resolve: `twist_rate_rad_s` is the
    /// twist rate amplitude the sizing pre-run measured (0 until sized), from which the
    /// plant bounds that rate (`plant.rs`, `DAHL_RATE_MARGIN`).
    Dahl {
        f_c_nm: f64,
        sigma_nm_per_rad: f64,
        twist_rate_rad_s: f64,
    },
}

/// Smooth free play in a gear mesh (half play h at the `to` side, rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BacklashLaw {
    /// Softened dead zone: s(δ) = ½[(δ−h)+√((δ−h)²+ε²)] + ½[(δ+h)−√((δ+h)²+ε²)].
    Softened { half_rad: f64, eps_rad: f64 },
    /// Hertz-like contact after the play: k·s^1.5/√s_ref, s the softened penetration.
    Hertzian {
        half_rad: f64,
        eps_rad: f64,
        s_ref_rad: f64,
    },
}

impl BacklashLaw {
    /// The equivalent mesh deflection for a twist δ.
    pub fn deflection(&self, d: f64) -> f64 {
        let soft = |h: f64, e: f64| {
            0.5 * ((d - h) + ((d - h).powi(2) + e * e).sqrt())
                + 0.5 * ((d + h) - ((d + h).powi(2) + e * e).sqrt())
        };
        match *self {
            BacklashLaw::Softened { half_rad, eps_rad } => soft(half_rad, eps_rad),
            BacklashLaw::Hertzian {
                half_rad,
                eps_rad,
                s_ref_rad,
            } => {
                let s = soft(half_rad, eps_rad);
                s * (s.abs() / s_ref_rad).sqrt()
            }
        }
    }
}

/// One cylinder's deviation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CylinderLaw {
    /// Gauge pressure times `scale`.
    Scale { scale: f64 },
    /// No combustion: the motored curve (the compression part mirrored) plus `residual`
    /// of the combustion excess.
    Misfire { residual: f64 },
    /// Combustion `delay_deg` late and its excess times `scale`.
    Late { delay_deg: f64, scale: f64 },
}

/// A measurement fault at one station.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SensorLaw {
    /// Zebra-tape butt joint: one pitch is `fraction` longer, once per revolution.
    TapeJoint {
        fraction: f64,
        lines: u32,
        angle_rad: f64,
    },
    /// Encoder eccentricity: angle error e·sin(θ + φ), once per revolution.
    Eccentricity { e_rad: f64, phase_rad: f64 },
    /// Missing tooth, incompletely compensated: one pitch reads `fraction` long.
    MissingTooth {
        fraction: f64,
        lines: u32,
        angle_rad: f64,
    },
}

/// What the truth has that the user's model lacks.
#[derive(Debug, Clone, PartialEq)]
pub enum Effect {
    None,
    /// Only plain parameters off (the user's model carries the error).
    ParameterError,
    AmplitudeNonlinearity {
        conn: usize,
        law: AmplitudeLaw,
    },
    FrequencyDependence {
        conn: usize,
        law: FrequencyLaw,
    },
    ThermalDrift {
        conn: usize,
        law: Thermal,
    },
    Hysteretic {
        conn: usize,
        law: HystereticLaw,
    },
    /// The truth's extra node (last node) and its spring (last connection), at `host`.
    UnmodelledMode {
        host: usize,
    },
    CrankVariableInertia {
        exact: bool,
    },
    GearBacklash {
        conn: usize,
        law: BacklashLaw,
    },
    CylinderImbalance {
        cylinder: usize,
        law: CylinderLaw,
    },
    SensorArtifact {
        station: usize,
        law: SensorLaw,
    },
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_form_changes_what_it_should() {
        // Amplitude laws stiffen with twist and are 1 at zero twist.
        for law in [
            AmplitudeLaw::Power { a: 100.0, p: 2.0 },
            AmplitudeLaw::Tanh {
                a: 0.3,
                theta_s: 0.01,
            },
        ] {
            assert_eq!(law.factor(0.0), 1.0);
            assert!(law.factor(0.02) > law.factor(0.01) && law.factor(0.01) > 1.0);
        }
        // Softening lowers stiffness with temperature rise, linear law held at 0.3.
        assert!(Softening::Exponential { beta_per_k: 0.01 }.factor(10.0) < 1.0);
        assert_eq!(Softening::Linear { beta_per_k: 0.01 }.factor(1000.0), 0.3);
        // Backlash: (almost) no deflection inside the play, full slope outside.
        let h = 1e-3;
        for law in [
            BacklashLaw::Softened {
                half_rad: h,
                eps_rad: 1e-4,
            },
            BacklashLaw::Hertzian {
                half_rad: h,
                eps_rad: 1e-4,
                s_ref_rad: 1e-3,
            },
        ] {
            assert!(law.deflection(0.5 * h).abs() < 0.01 * h);
            assert!(law.deflection(3.0 * h) > 1.5 * h && law.deflection(-3.0 * h) < -1.5 * h);
        }
        let soft = BacklashLaw::Softened {
            half_rad: h,
            eps_rad: 1e-4,
        };
        // far outside the play the slope is 1 (to 1e-6: the ε² correction)
        assert!(((soft.deflection(0.1) - soft.deflection(0.09)) / 0.01 - 1.0).abs() < 1e-6);
    }
}
