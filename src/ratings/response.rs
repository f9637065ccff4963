//! The ratings on the forced response (issue 16): at each speed of a sweep, the loads of
//! [`StageLoads`] are the linear response's: the static mean torque of the stage, the
//! largest torque over a cycle with every order at its phase, each order's amplitude and
//! the power loss summed over orders.

use super::{StageLoads, StageRating, checks_at, rated_stages};
use crate::model::{CouplingRating, Model};
use crate::physics::System;
use crate::response::Response;

/// The rating checks of every rated rubber stage of `model` over `response` (of `system`,
/// built from `model`). Stages without a rating, or not in the response, are left out.
pub fn check_ratings(model: &Model, system: &System, response: &Response) -> Vec<StageRating> {
    let mut out = Vec::new();
    for (j, stage, rating) in rated_stages(model) {
        let Some(entry) = response.connections.iter().position(|&c| c == j) else {
            continue;
        };
        let s_t = CouplingRating::temperature_factor(stage.temperature_c);
        let mean_nm = system
            .mean_torque_nm
            .get(j)
            .copied()
            .flatten()
            .unwrap_or(0.0);
        let by_speed = response
            .speeds_rpm
            .iter()
            .enumerate()
            .map(|(s, &speed_rpm)| {
                let loads = StageLoads {
                    speed_rpm,
                    mean_nm,
                    peak_nm: response.torque_peak_nm[entry][s],
                    orders_nm: response
                        .orders
                        .iter()
                        .enumerate()
                        .map(|(q, &order)| (order, response.torque_amplitude_nm[entry][q][s]))
                        .collect(),
                    power_loss_w: response.power_loss_w[entry][s],
                };
                checks_at(rating, s_t, &loads)
            })
            .collect();
        out.push(StageRating {
            connection: model.connections[j].name.clone(),
            connection_index: j,
            rating: rating.clone(),
            temperature_factor: s_t,
            by_speed,
        });
    }
    out
}
