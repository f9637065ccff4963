//! What holds a run back, named for a person (issue 13: "the step size collapsed … at
//! t = 0" must name the element): the state behind an error estimate, the fastest rate of
//! each element, the step budget that stops a run which would not end, the check that
//! stops a run whose state diverges, and the bound on a rubber stage's thermal time
//! constant.

use super::TransientError;
use super::plant::{Plant, PlantElement, PlantLaw, Temperature};
use super::speed::SpeedProfile;
use super::stepper::Stepper;

/// Steps a well-posed run may take before any time has passed (start-up, the first
/// cycles' rejections), added to the steps its duration needs.
const STARTUP_STEPS: f64 = 1000.0;

/// A person's name for state `i` of `plant`: the node of an angle or speed, the rubber
/// stage of a Maxwell arm or a temperature.
pub fn state_name(plant: &Plant, i: usize) -> String {
    let n = plant.n_dof;
    let node_of = |d: usize| {
        let names: Vec<&str> = plant
            .system
            .dof_of_node
            .iter()
            .enumerate()
            .filter(|(_, x)| **x == d)
            .map(|(k, _)| plant.system.node_names[k].as_str())
            .collect();
        if names.is_empty() {
            // An internal DOF of a distributed shaft.
            let sys = &plant.system;
            let shaft = sys.distributed.iter().find(|s| {
                s.elements
                    .clone()
                    .any(|e| sys.elements[e].from_dof == Some(d))
            });
            return shaft.map_or_else(
                || format!("#{d}"),
                |s| format!("inside shaft {}", sys.connection_names[s.connection]),
            );
        }
        names.join("+")
    };
    if i < n {
        return format!("the vibration angle of node `{}` (rad)", node_of(i));
    }
    if i < 2 * n {
        return format!("the vibration speed of node `{}` (rad/s)", node_of(i - n));
    }
    for e in &plant.elements {
        if let PlantLaw::Rubber(r) = &e.law {
            let name = connection_name(plant, e);
            if (r.arm_offset..r.arm_offset + r.chain.arms.len()).contains(&i) {
                let (_, tau) = r.chain.arms[i - r.arm_offset];
                return format!(
                    "Maxwell arm {} of rubber stage `{name}` (τ = {tau:.3e} s)",
                    i - r.arm_offset + 1
                );
            }
            if let Temperature::Thermal { state, .. } = r.temperature
                && state == i
            {
                return format!("the temperature of rubber stage `{name}` (°C)");
            }
        }
    }
    format!("state #{i}")
}

fn connection_name<'a>(plant: &'a Plant, e: &PlantElement) -> &'a str {
    plant
        .system
        .connection_names
        .get(e.connection)
        .map_or("?", String::as_str)
}

/// The fastest rate of element `e`, rad/s, and what sets it: `√(k·(1/J_from + 1/J_to))`
/// of its stiffness referred to the DOFs it joins, `1/τ` of its fastest Maxwell arm, `G/C`
/// of its temperature — the rate that bounds an explicit method's step (stable to
/// `h·rate ≈ 3.3` for Dormand–Prince).
pub fn element_rate(plant: &Plant, e: &PlantElement) -> (f64, String) {
    let inverse_inertia = [e.from_dof, e.to_dof]
        .iter()
        .flatten()
        .map(|&d| 1.0 / plant.inertia_kg_m2[d])
        .sum::<f64>();
    let spring = |k_ref: f64| (k_ref * inverse_inertia).max(0.0).sqrt();
    let name = connection_name(plant, e);
    match &e.law {
        PlantLaw::Linear { stiffness, .. } => (
            spring(*stiffness),
            format!("connection `{name}` (stiffness {stiffness:.3e} N·m/rad, referred)"),
        ),
        // A power-law contact is n·k steep at its reference deflection.
        PlantLaw::Backlash {
            stiffness_own,
            contact,
            ..
        } => (
            spring(stiffness_own * contact.exponent * e.ratio * e.ratio),
            format!("gear mesh `{name}` (stiffness {stiffness_own:.3e} N·m/rad)"),
        ),
        PlantLaw::Rubber(r) => {
            let k = r.static_stiffness_nm_per_rad
                * (r.chain.equilibrium + r.chain.arms.iter().map(|(k, _)| k).sum::<f64>());
            let mut best = (
                spring(k * e.ratio * e.ratio),
                format!("rubber stage `{name}` (stiffness {k:.3e} N·m/rad)"),
            );
            if let Some(&(_, tau)) = r.chain.arms.iter().min_by(|a, b| a.1.total_cmp(&b.1))
                && 1.0 / tau > best.0
            {
                best = (
                    1.0 / tau,
                    format!("rubber stage `{name}` (Maxwell arm τ = {tau:.3e} s)"),
                );
            }
            if let Temperature::Thermal {
                capacity_j_per_k: c,
                conductance_w_per_k: g,
                ..
            } = r.temperature
                && g / c > best.0
            {
                best = (
                    g / c,
                    format!(
                        "the temperature of rubber stage `{name}` (C/G = {:.3e} s)",
                        c / g
                    ),
                );
            }
            best
        }
    }
}

/// The element with the fastest rate ([`element_rate`]), if any.
pub fn stiffest_element(plant: &Plant) -> Option<(f64, String)> {
    plant
        .elements
        .iter()
        .map(|e| element_rate(plant, e))
        .max_by(|a, b| a.0.total_cmp(&b.0))
}

/// The step budget of a run: by simulated time `t` from its start, at most
/// `factor × (t / h_max + 1000)` steps, accepted and rejected ([`crate::limits::Limits::step_budget_factor`]).
#[derive(Debug, Clone, Copy)]
pub struct StepBudget {
    /// Multiple of the steps a well-posed run needs.
    pub factor: f64,
    /// The largest step the excitation allows, s.
    pub h_max_s: f64,
}

impl StepBudget {
    /// `Err` when `solver` has used more steps than the budget allows at its time (never
    /// for a fixed step, [`Stepper::adapts_step`]).
    pub fn check(&self, plant: &Plant, solver: &Stepper) -> Result<(), TransientError> {
        if !solver.adapts_step() {
            return Ok(());
        }
        let (accepted, rejected) = solver.steps();
        let steps = accepted + rejected;
        let needed = solver.t() / self.h_max_s + STARTUP_STEPS;
        if (steps as f64) <= self.factor * needed {
            return Ok(());
        }
        let held_by = state_name(plant, solver.worst_state());
        let cause = match (solver.is_explicit(), stiffest_element(plant)) {
            (true, Some((rate, element))) if rate * self.h_max_s > 3.3 => {
                format!(
                    "The explicit method is held by stability: the fastest element is {element}, rate {rate:.3e} rad/s; use `--method implicit` (RunOptions::method = Implicit). The error estimate is dominated by {held_by}"
                )
            }
            _ => format!(
                "The error estimate is dominated by {held_by} (the model is too stiff or discontinuous there)"
            ),
        };
        Err(TransientError::StepBudget {
            time_s: solver.t(),
            step_s: solver.h(),
            steps,
            needed,
            cause,
        })
    }
}

/// Names the state of a [`TransientError::StepCollapse`] from an integrator (which only
/// knows its index).
pub fn name_collapse(plant: &Plant, solver: &Stepper, error: TransientError) -> TransientError {
    match error {
        TransientError::StepCollapse { time_s, step_s, .. } => TransientError::StepCollapse {
            time_s,
            step_s,
            state: state_name(plant, solver.worst_state()),
        },
        other => other,
    }
}

/// Bounds each thermal rubber stage's time constant `C/G` below by `tau_min_s` (the
/// largest step of the run), raising its heat capacity to `G·tau_min_s`; returns a
/// warning per stage changed. A real rubber part's `C/G` is seconds to minutes (its mass ×
/// ~1.7 kJ/(kg·K) over a few W/K); one below a step of 2° of crank makes the temperature
/// equation stiff (issue 13: a tiny heat capacity hung the run) while its temperature only
/// follows the power loss within the step: the mean temperature (`ambient + P/G`) is
/// unchanged, the ripple lags by at most one step.
pub fn bound_thermal_time_constants(plant: &mut Plant, tau_min_s: f64) -> Vec<String> {
    let mut warnings = Vec::new();
    let names = plant.system.connection_names.clone();
    for e in &mut plant.elements {
        if let PlantLaw::Rubber(r) = &mut e.law
            && let Temperature::Thermal {
                capacity_j_per_k: c,
                conductance_w_per_k: g,
                ..
            } = &mut r.temperature
            && *c / *g < tau_min_s
        {
            let raised = *g * tau_min_s;
            warnings.push(format!(
                "rubber stage `{}`: thermal time constant C/G = {:.3e} s is shorter than one step ({tau_min_s:.3e} s); the temperature follows the power loss quasi-statically, run with C = {raised:.3e} J/K",
                names.get(e.connection).map_or("?", String::as_str),
                *c / *g
            ));
            *c = raised;
        }
    }
    warnings
}

/// Stops a run whose state is not finite or beyond any physical bound.
pub(super) fn check_state(
    plant: &Plant,
    t: f64,
    y: &[f64],
    profile: &SpeedProfile,
) -> Result<(), TransientError> {
    let n = plant.n_dof;
    let speed_limit = 10.0 * profile.at(t).1 + 1000.0;
    for (i, &v) in y.iter().enumerate() {
        let bad = !v.is_finite()
            || (i >= n && i < 2 * n && v.abs() > speed_limit)
            || (i < n && v.abs() > 1.0e3);
        if bad {
            return Err(TransientError::Diverged {
                time_s: t,
                state: state_name(plant, i),
                value: v,
            });
        }
    }
    Ok(())
}
