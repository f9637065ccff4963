//! `hysteretic_damping`: the truth's coupling is a rubber stage (loss per cycle independent
//! of frequency) where the user has seed 001's spring and viscous damper (eq. 1–2).

use super::EffectError;
use super::effect::{EffectSpec, Params};
use super::truth::Applied;
use crate::model::{ConnectionKind, Model, RubberStage, RubberStiffness};
use crate::physics::{OperatingPoint, System};
use crate::rubber::{MaxwellChain, ModeTarget, law_band_hz};
use std::f64::consts::TAU;

/// `hysteretic_damping`: the user's coupling is a viscous `shaft` (k, c), as seed 001's
/// model has it (eq. 1–2); the truth is a rubber stage, whose loss per cycle does not
/// depend on frequency. Every view represents a rubber stage by its causal chain
/// ([`crate::rubber`]), which stiffens with frequency (Kramers–Kronig) and meets ψ/2π
/// only near the model's modes. So the truth's ψ and static stiffness are set such that
/// the truth model's own chain (its band, its modes at the default load) has at
/// `reference_hz` the user's loss factor `c·ω_ref/k` (the user's k and c) and the truth's
/// spring stiffness (the user's, with any plain error): the two agree there and part away
/// from it. The chain's modes move with the stiffness, so ψ and the stiffness are set in
/// passes until the stiffness stops changing ([`MAX_PASSES`]). Default reference: seed 001's choice, the engine cycle frequency at the middle
/// of the operating range (speed range if none). A loss factor the chain cannot reach is
/// an error that says the most it can.
pub(crate) fn hysteretic(
    model: &mut Model,
    user: &Model,
    spec: &EffectSpec,
) -> Result<Applied, EffectError> {
    let mut p = Params::new(spec, &["connection", "reference_hz"])?;
    let softest = model
        .connections
        .iter()
        .filter_map(|c| match &c.kind {
            ConnectionKind::Shaft(s) => Some((c.name.clone(), s.stiffness_nm_per_rad)),
            _ => None,
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(n, _)| n);
    let name = p.text("connection", softest)?;
    let Some(j) = model.connections.iter().position(|c| c.name == name) else {
        return Err(p.bad("connection", format!("no connection `{name}`")));
    };
    let ConnectionKind::Shaft(shaft) = &model.connections[j].kind else {
        return Err(p.bad(
            "connection",
            format!(
                "`{name}` is no viscous `shaft`: this effect needs the user's coupling as a \
                 spring and viscous damper (seed 001 eq. 1–2)"
            ),
        ));
    };
    // The truth's spring (with any plain error) is calibrated; ψ is the material's, from
    // the user's own k and c.
    let (k, c) = (shaft.stiffness_nm_per_rad, shaft.damping_nm_s_per_rad);
    let k_user = user
        .connections
        .iter()
        .find_map(|u| match &u.kind {
            ConnectionKind::Shaft(s) if u.name == name => Some(s.stiffness_nm_per_rad),
            _ => None,
        })
        .unwrap_or(k);
    if c <= 0.0 {
        return Err(p.bad("connection", format!("shaft `{name}` has no damping")));
    }
    let range = user
        .operation
        .operating_range_rpm
        .or(user.operation.speed_range_rpm);
    let cycle_rev = f64::from(user.strokes()) / 2.0;
    let default_ref = range.map(|[a, b]| 0.5 * (a + b) / 60.0 / cycle_rev);
    let f_ref = p.number("reference_hz", default_ref.unwrap_or(50.0), 0.1, 1.0e4)?;
    let xi_target = c * TAU * f_ref / k_user;
    if xi_target >= 1.0 {
        return Err(p.bad(
            "reference_hz",
            format!("gives a loss factor {xi_target:.2} ≥ 1 for shaft `{name}`"),
        ));
    }
    let band = law_band_hz(model);
    let mut static_stiffness = f64::INFINITY;
    let mut stage = RubberStage {
        stiffness: RubberStiffness::Direct(k),
        psi: 1.0,
        temperature_c: 25.0,
        amplitude_poly: None,
        amplitude_saturation: None,
        amplitude_form: Default::default(),
        frequency_poly: None,
        frequency_power_law: None,
        frequency_zener: None,
        temperature_stiffness_poly: None,
        temperature_damping_poly: None,
        thermal: None,
        rating: None,
    };
    let loss = |z: num_complex::Complex64| z.im / z.re;
    for _ in 0..MAX_PASSES {
        let targets = mode_targets(model, j, &stage);
        let at = |stage: &mut RubberStage, psi: f64| {
            stage.psi = psi;
            MaxwellChain::fit_at_modes(stage, band, &targets).complex_stiffness(f_ref)
        };
        // The chain's loss factor rises with ψ, peaks, then falls (the fit trades loss for
        // stiffness): take the first ψ on a 0.05 grid that reaches the target, then search
        // the bracket below it ([`crossing`]).
        // The grid is walked up only to that ψ (each point is a chain fit, and the target
        // is mostly reached below ψ = 1); all of it only to report the most it reaches.
        let mut grid: Vec<(f64, f64)> = Vec::with_capacity(100);
        for i in 1..=100 {
            let psi = 0.05 * f64::from(i);
            grid.push((psi, loss(at(&mut stage, psi))));
            if grid[grid.len() - 1].1 >= xi_target {
                break;
            }
        }
        let Some(i) = grid.iter().position(|(_, xi)| *xi >= xi_target) else {
            let (psi, xi) = grid
                .iter()
                .copied()
                .fold((0.0, 0.0), |m, g| if g.1 > m.1 { g } else { m });
            return Err(p.bad(
                "connection",
                format!(
                    "the user's damper asks a loss factor {xi_target:.4} at {f_ref} Hz; the time \
                     domain's causal chain reaches at most {xi:.4} there (ψ = {psi:.2}): lower the \
                     damping or move the reference"
                ),
            ));
        };
        let lo_psi = if i == 0 { 1e-4 } else { grid[i - 1].0 };
        let below = match i {
            0 => loss(at(&mut stage, lo_psi)),
            _ => grid[i - 1].1,
        };
        let psi = crossing(
            |psi| loss(at(&mut stage, psi)) - xi_target,
            (lo_psi, below - xi_target),
            (grid[i].0, grid[i].1 - xi_target),
        );
        let relative = at(&mut stage, psi);
        let previous = static_stiffness;
        static_stiffness = k / relative.re;
        stage.stiffness = RubberStiffness::Direct(static_stiffness);
        if (static_stiffness - previous).abs() <= CONVERGED * static_stiffness {
            break;
        }
    }
    let summary = format!(
        "`{name}` is a rubber stage with frequency-independent loss, ψ = {:.4}, static \
         stiffness {:.1} N·m/rad, where the user has a spring {k_user} N·m/rad and viscous \
         damper {c} N·m·s/rad; at {f_ref:.2} Hz its causal chain has the user's loss factor \
         {xi_target:.4} and the truth's spring stiffness ({k:.1} N·m/rad, with its plain error)",
        stage.psi, static_stiffness
    );
    model.connections[j].kind = ConnectionKind::Rubber(stage);
    Ok((p.resolved, summary))
}

/// Where `f` crosses zero between `lo = (x, f(x))`, `f < 0`, and `hi`, `f ≥ 0`: the
/// Illinois form of regula falsi (Dowell & Jarratt, BIT 11, 1971), which keeps the
/// bracket and shrinks it from both ends, superlinearly (order ≈ 1.44); until the bracket
/// is [`CROSSING_WIDTH`] wide relative to `x`, at most 60 steps. Each step here is a
/// chain fit: bisection to adjacent floats took some 50 of them per pass, this takes
/// about ten, and some seven more halve the last bracket to adjacent floats. A bracket
/// whose `f` does not change sign is not searched (its midpoint).
fn crossing(mut f: impl FnMut(f64) -> f64, lo: (f64, f64), hi: (f64, f64)) -> f64 {
    let ((mut a, mut fa), (mut b, mut fb)) = (lo, hi);
    if !(fa < 0.0 && fb >= 0.0) {
        return 0.5 * (a + b);
    }
    // Which end the last step moved: the end that stays twice in a row has its value
    // halved (Illinois), so that the other end moves too.
    let mut last = 0;
    for _ in 0..60 {
        if b - a <= CROSSING_WIDTH * b {
            break;
        }
        let secant = (a * fb - b * fa) / (fb - fa);
        let c = if secant > a && secant < b {
            secant
        } else {
            0.5 * (a + b)
        };
        if c <= a || c >= b {
            break;
        }
        let fc = f(c);
        if fc < 0.0 {
            (a, fa) = (c, fc);
            if last < 0 {
                fb *= 0.5;
            }
            last = -1;
        } else {
            (b, fb) = (c, fc);
            if fc == 0.0 {
                return c;
            }
            if last > 0 {
                fa *= 0.5;
            }
            last = 1;
        }
    }
    // Then halved down to adjacent floats, where bisection alone ended: ψ comes out as it
    // did (the shipped hysteretic truth's ψ to the bit; its stiffness moved in the 16th
    // digit, `tests/data/diagnosis`).
    for _ in 0..60 {
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            break;
        }
        if f(mid) < 0.0 {
            a = mid;
        } else {
            b = mid;
        }
    }
    0.5 * (a + b)
}

/// Width of the bracket [`crossing`] stops at, relative to its upper end.
const CROSSING_WIDTH: f64 = 1e-14;

/// Calibration passes of ψ and the static stiffness against the truth's own chain, at
/// most: each moves the modes the chain is fitted at less (measured on the shipped case:
/// the static stiffness changes by 2e-3, then 1e-6, then below [`CONVERGED`]).
const MAX_PASSES: usize = 8;

/// Relative change of the static stiffness at which the calibration has converged.
const CONVERGED: f64 = 1e-13;

/// The modes the chain of connection `j` is fitted at ([`System::mode_targets`]) when it
/// is `stage` in `model`, at the default load; none when the system cannot be built.
fn mode_targets(model: &Model, j: usize, stage: &RubberStage) -> Vec<ModeTarget> {
    let mut copy = model.clone();
    copy.connections[j].kind = ConnectionKind::Rubber(stage.clone());
    let Ok(system) = System::nominal(&copy, OperatingPoint::default()) else {
        return Vec::new();
    };
    let index = system.elements.iter().position(|e| e.connection == j);
    index
        .and_then(|i| system.mode_targets().into_iter().nth(i))
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On a convex function, where plain regula falsi keeps one end for ever, and on one
    /// that rises to a peak as the chain's loss factor does, the crossing comes out within
    /// four ulps of the exact root in under 30 evaluations.
    #[test]
    fn the_crossing_is_found_in_few_steps() {
        // (function, bracket's low end, high end, exact root)
        type Case = (fn(f64) -> f64, f64, f64, f64);
        let cases: [Case; 3] = [
            (|x| x.exp() - 10.0, 0.0, 5.0, 10f64.ln()),
            (|x| x * x * x - 2.0, 1.0, 2.0, 2f64.cbrt()),
            // ψ/(1 + ψ²) rises to 0.5 at ψ = 1: its first crossing of 0.4 is at 0.5.
            (|x| x / (1.0 + x * x) - 0.4, 0.05, 0.95, 0.5),
        ];
        for (f, lo, hi, root) in cases {
            let mut calls = 0;
            let x = crossing(
                |x| {
                    calls += 1;
                    f(x)
                },
                (lo, f(lo)),
                (hi, f(hi)),
            );
            assert!(
                (x - root).abs() <= 2.0 * CROSSING_WIDTH * root,
                "{x} against {root}"
            );
            assert!(calls < 30, "{calls} evaluations");
        }
        // No sign change: the bracket's middle, unsearched.
        assert_eq!(
            crossing(|_| panic!("searched"), (1.0, 1.0), (2.0, 3.0)),
            1.5
        );
    }
}
