//! What the forced-response tab plots: the quantities, and the lines of one quantity at
//! one station or connection (every order that matters and the totals, labelled for what
//! they are).

use super::mode_color;
use crate::gui::views::plots::series::Series;
use egui::Color32;
use torsim::response::Response;

/// An order is drawn when at some speed it is at least this share of the sum of all
/// orders there…
const SHARE_SHOWN: f64 = 0.05;
/// …and at least this share of the sum's largest value (not for noise at quiet speeds).
const FLOOR_SHOWN: f64 = 0.002;

/// True when an order's `values` matter somewhere next to the `sum` of all orders.
pub fn matters(values: &[f64], sum: &[f64], top: f64) -> bool {
    values
        .iter()
        .zip(sum)
        .any(|(&v, &s)| v >= SHARE_SHOWN * s && v >= FLOOR_SHOWN * top && v > 0.0)
}

/// What the forced-response tab shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// IAS amplitude at a station, rpm.
    Ias,
    /// Torque amplitude in a connection, N·m.
    Torque,
    /// Power dissipated in a connection (rubber: DIN 740; shaft: viscous), W.
    PowerLoss,
}

impl Quantity {
    /// The selector's text.
    pub fn label(self) -> &'static str {
        match self {
            Quantity::Ias => "IAS amplitude per station",
            Quantity::Torque => "torque amplitude per connection",
            Quantity::PowerLoss => "power loss per connection",
        }
    }

    /// The y axis with its unit.
    pub fn y_label(self) -> &'static str {
        match self {
            Quantity::Ias => "IAS amplitude [rpm] (zero-to-peak, own shaft)",
            Quantity::Torque => "torque [N·m] (own shaft)",
            Quantity::PowerLoss => "power loss [W]",
        }
    }

    /// The unit of the values.
    pub fn unit(self) -> &'static str {
        match self {
            Quantity::Ias => "rpm",
            Quantity::Torque => "N·m",
            Quantity::PowerLoss => "W",
        }
    }
}

fn along(speeds: &[f64], values: &[f64]) -> Vec<[f64; 2]> {
    speeds.iter().zip(values).map(|(&n, &v)| [n, v]).collect()
}

/// The lines of `quantity` at `index` (a node for IAS, an entry of `r.connections`
/// otherwise): every order that [`matters`], then the totals. `mean_nm` is the
/// connection's mean torque, drawn with the torque.
pub fn response_series(
    r: &Response,
    quantity: Quantity,
    index: usize,
    mean_nm: Option<f64>,
) -> Vec<Series> {
    let per_order = match quantity {
        Quantity::Ias => r.ias_amplitude_rpm.get(index),
        Quantity::Torque => r.torque_amplitude_nm.get(index),
        Quantity::PowerLoss => r.power_loss_by_order_w.get(index),
    };
    let Some(per_order) = per_order else {
        return Vec::new();
    };
    let what = match quantity {
        Quantity::Ias => "IAS amplitude",
        Quantity::Torque => "torque amplitude",
        Quantity::PowerLoss => "power loss",
    };
    let unit = quantity.unit();
    let n_speeds = r.speeds_rpm.len();
    let sum: Vec<f64> = (0..n_speeds)
        .map(|s| per_order.iter().map(|v| v[s]).sum())
        .collect();
    let top = sum.iter().copied().fold(0.0, f64::max);
    // Colour by the order's rank among the orders drawn (issue 16: by its place in the
    // list of all orders, 1.5, 6.5 and 11.5 shared a colour): the palette's first colours
    // go to the lowest orders shown, so no two lines of a plot share one.
    let mut out: Vec<Series> = r
        .orders
        .iter()
        .zip(per_order)
        .filter(|(_, v)| matters(v, &sum, top))
        .enumerate()
        .map(|(k, (q, v))| {
            Series::new(
                format!("order {q}"),
                format!("order {q} {what} [{unit}]"),
                along(&r.speeds_rpm, v),
            )
            .color(mode_color(k))
        })
        .collect();
    let strong = Color32::from_gray(235);
    match quantity {
        Quantity::Ias => {
            out.push(
                Series::new(
                    "Σ orders (upper bound)",
                    "sum of order amplitudes (upper bound) [rpm]",
                    along(&r.speeds_rpm, &sum),
                )
                .color(Color32::from_gray(150))
                .dashed(),
            );
            if let Some(v) = r.ias_half_peak_to_peak_rpm.get(index) {
                out.push(
                    Series::new(
                        "all orders: (max − min)/2",
                        "all orders synthesized: half peak-to-peak IAS [rpm]",
                        along(&r.speeds_rpm, v),
                    )
                    .color(strong)
                    .width(2.5),
                );
            }
        }
        Quantity::Torque => {
            out.push(
                Series::new(
                    "Σ orders (upper bound of the oscillation)",
                    "sum of order amplitudes (upper bound) [N·m]",
                    along(&r.speeds_rpm, &sum),
                )
                .color(Color32::from_gray(150))
                .dashed(),
            );
            if let Some(v) = r.torque_peak_nm.get(index) {
                out.push(
                    Series::new(
                        "peak |T| over a cycle (mean + all orders)",
                        "peak torque over a cycle, mean and all orders synthesized [N·m]",
                        along(&r.speeds_rpm, v),
                    )
                    .color(strong)
                    .width(2.5),
                );
            }
            if let (Some(m), Some(&n0), Some(&n1)) =
                (mean_nm, r.speeds_rpm.first(), r.speeds_rpm.last())
            {
                out.push(
                    Series::new("mean torque", "mean torque [N·m]", vec![[n0, m], [n1, m]])
                        .color(Color32::from_gray(190))
                        .width(1.0)
                        .dashed(),
                );
            }
        }
        Quantity::PowerLoss => {
            if let Some(v) = r.power_loss_w.get(index) {
                out.push(
                    Series::new(
                        "all orders (sum, exact)",
                        "power loss, all orders [W]",
                        along(&r.speeds_rpm, v),
                    )
                    .color(strong)
                    .width(2.5),
                );
            }
        }
    }
    out
}
