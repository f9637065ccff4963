//! The cheap results of one request of the simulation thread ([`super::worker`]), sent
//! one by one as each is ready, before the time run: modes and the Campbell diagram, the
//! forced response and the coupling ratings on it, and the engine's working cycle.

use crate::gui::session::messages::{Modal, PanelError, Payload, RatingsResult, SimResult};
use std::sync::Arc;
use torsim::modal::{campbell, damped_modes, speed_grid};
use torsim::model::Model;
use torsim::physics::{Excitation, OperatingPoint, System};
use torsim::response::forced_response;

/// Computes one request's cheap results (modes, Campbell, forced response) and returns
/// the system for the time run, or `None` when the model fails or the request is stale.
pub fn compute(
    generation: u64,
    model: &Model,
    stale: &dyn Fn() -> bool,
    send: &dyn Fn(SimResult),
) -> Option<System> {
    let system = match System::new(model, OperatingPoint::default()) {
        Ok(s) => s,
        Err(e) => {
            send(SimResult::new(
                generation,
                Payload::Error(PanelError {
                    panel: "modes",
                    message: e.to_string(),
                }),
            ));
            send(SimResult::new(
                generation,
                Payload::Error(PanelError {
                    panel: "trace",
                    message: format!("no time run: {e}"),
                }),
            ));
            return None;
        }
    };
    let [from, to] = model.operation.speed_range_rpm.unwrap_or([100.0, 3000.0]);
    let speeds = speed_grid(from, to, (to - from) / 200.0);
    let orders = model.orders();
    match campbell(&system, &speeds, &orders) {
        Ok(c) => {
            let damped = damped_modes(&system, &c.modes);
            send(SimResult::new(
                generation,
                Payload::Modal(Arc::new(Modal {
                    system: system.clone(),
                    campbell: c,
                    damped,
                })),
            ));
        }
        Err(e) => send(SimResult::new(
            generation,
            Payload::Error(PanelError {
                panel: "modes",
                message: e.to_string(),
            }),
        )),
    }
    if stale() {
        return None;
    }
    let excitation = Excitation::new(model, &system, 1.0, &orders);
    match forced_response(&system, &excitation, &speeds) {
        Ok(r) => {
            let ratings = RatingsResult {
                stages: torsim::ratings::check_ratings(model, &system, &r),
                beyond: torsim::ratings::beyond_linear_range(&system, &r),
                outside_law: torsim::ratings::beyond_amplitude_law(model, &system, &r),
            };
            send(SimResult::new(generation, Payload::Response(Arc::new(r))));
            send(SimResult::new(
                generation,
                Payload::Ratings(Arc::new(ratings)),
            ));
        }
        Err(e) => send(SimResult::new(
            generation,
            Payload::Error(PanelError {
                panel: "response",
                message: e.to_string(),
            }),
        )),
    }
    // After the plots an edit is waiting for: the editor's cycle drawing can come later.
    if let Some(engine) = &model.engine
        && !stale()
    {
        let cycle = torsim::physics::engine_cycle::engine_cycle(engine, 1.0);
        send(SimResult::new(
            generation,
            Payload::EngineCycle(Arc::new(cycle)),
        ));
    }
    (!stale()).then_some(system)
}
