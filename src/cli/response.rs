//! `torsim response MODEL [--from-rpm A --to-rpm B --step-rpm S] [--load L]`: steady
//! forced response order by order (frequency domain).

use super::error::CliError;
use super::format::{emit, numbers, order_key, outln, print_json, print_warnings, table};
use super::input::Sweep;
use serde_json::{Map, Value, json};
use torsim::physics::{Excitation, OperatingPoint, System};
use torsim::response::forced_response;

/// Rows shown in the human-readable table at most.
const MAX_TABLE_ROWS: usize = 41;

/// Runs the command.
pub fn run(sweep: &Sweep, orders: Option<Vec<f64>>, json: bool) -> Result<(), CliError> {
    let (model, speeds, load) = sweep.resolve()?;
    let system = System::new(
        &model,
        OperatingPoint {
            load,
            temperature_c: None,
        },
    )?;
    print_warnings(&system.warnings);
    let orders = orders.unwrap_or_else(|| model.orders());
    if orders.is_empty() {
        return Err(CliError::input(anyhow::anyhow!(
            "no orders to compute: give --orders or `orders` in [operation]"
        )));
    }
    if let Some(bad) = orders.iter().find(|q| !(q.is_finite() && **q > 0.0)) {
        return Err(CliError::input(anyhow::anyhow!(
            "--orders: order {bad} must be > 0"
        )));
    }
    let excitation = Excitation::new(&model, &system, load, &orders);
    let r = forced_response(&system, &excitation, &speeds)?;
    let excited_hz: Vec<f64> = speeds
        .iter()
        .flat_map(|n| orders.iter().map(move |q| q * n / 60.0))
        .collect();
    print_warnings(&system.frequency_range_warnings(&excited_hz));
    let ratings = super::ratings::Ratings::new(&model, &system, &r);
    if json {
        let (rated, beyond) = super::ratings::json(&ratings)?;
        let mut nodes = Map::new();
        for (name, per_order) in system.node_names.iter().zip(&r.ias_amplitude_rpm) {
            let mut by_order = Map::new();
            for (q, values) in orders.iter().zip(per_order) {
                by_order.insert(order_key(*q), numbers(values, "IAS amplitude")?);
            }
            nodes.insert(name.clone(), json!({ "ias_amplitude_rpm": by_order }));
        }
        let mut connections = Map::new();
        for (c, &j) in r.connections.iter().enumerate() {
            let mut by_order = Map::new();
            for (q, values) in orders.iter().zip(&r.torque_amplitude_nm[c]) {
                by_order.insert(order_key(*q), numbers(values, "torque amplitude")?);
            }
            connections.insert(
                system.connection_names[j].clone(),
                json!({
                    "torque_amplitude_nm": by_order,
                    "torque_mean_nm": system.mean_torque_nm[j],
                    "torque_peak_nm": numbers(&r.torque_peak_nm[c], "peak torque")?,
                    "power_loss_w": numbers(&r.power_loss_w[c], "power loss")?,
                }),
            );
        }
        return print_json(&json!({
            "speeds_rpm": numbers(&speeds, "speed")?,
            "load": load,
            "orders": numbers(&orders, "order")?,
            "nodes": Value::Object(nodes),
            "connections": Value::Object(connections),
            "ratings": rated,
            "beyond_linear_range": beyond,
        }));
    }
    let mut text = String::new();
    outln!(
        text,
        "{} — forced response at load {load}, orders {} … {}; IAS: largest order amplitude [rpm] (order); T_peak: mean + all orders over a cycle",
        model.name,
        order_key(orders[0]),
        order_key(orders[orders.len() - 1])
    );
    let mut header = vec!["rpm".to_string()];
    header.extend(system.node_names.iter().map(|n| format!("{n} IAS")));
    for &j in &r.connections {
        header.push(format!("{} T_peak [N·m]", system.connection_names[j]));
        header.push(format!("{} P [W]", system.connection_names[j]));
    }
    let stride = speeds.len().div_ceil(MAX_TABLE_ROWS).max(1);
    let rows: Vec<Vec<String>> = (0..speeds.len())
        .step_by(stride)
        .map(|s| {
            let mut row = vec![format!("{:.0}", speeds[s])];
            for per_order in &r.ias_amplitude_rpm {
                let (q, a) = per_order
                    .iter()
                    .enumerate()
                    .map(|(q, v)| (q, v[s]))
                    .fold((0, 0.0), |best, x| if x.1 > best.1 { x } else { best });
                row.push(format!("{a:.3} ({})", order_key(orders[q])));
            }
            for c in 0..r.connections.len() {
                row.push(format!("{:.1}", r.torque_peak_nm[c][s]));
                row.push(format!("{:.2}", r.power_loss_w[c][s]));
            }
            row
        })
        .collect();
    text += &table(&header, &rows);
    text += &super::ratings::text(&ratings);
    emit(&text)
}
