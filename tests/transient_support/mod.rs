//! Shared by the time-domain tests: an order's amplitude in a simulated steady record.

use num_complex::Complex64;
use std::f64::consts::TAU;

/// Zero-to-peak amplitude of order `q` in a steady IAS record sampled at `rate_hz` with
/// reference speed `speed_rpm`, over a whole number of cycles (a plain DFT at one bin;
/// exact only when a cycle is a whole number of samples — choose the rate so).
pub fn order_amplitude(signal: &[f64], rate_hz: f64, speed_rpm: f64, q: f64) -> f64 {
    let omega = q * speed_rpm * TAU / 60.0;
    let period_s = 2.0 * 60.0 / speed_rpm; // two revolutions: every order k/2 is periodic
    let cycles = (signal.len() as f64 / rate_hz / period_s).floor();
    let n = (cycles * period_s * rate_hz).round() as usize;
    let sum: Complex64 = signal[..n]
        .iter()
        .enumerate()
        .map(|(k, v)| v * Complex64::from_polar(1.0, -omega * k as f64 / rate_hz))
        .sum();
    2.0 * sum.norm() / n as f64
}

/// Asserts that a steady record's order amplitudes at every node (`time_rpm[node]`,
/// sampled at `rate_hz`) agree with the frequency domain's
/// (`ias_amplitude_rpm[node][order][0]`, the first speed of a sweep at `speed_rpm`)
/// within `tolerance` relative, for each of `orders`.
#[allow(dead_code)] // not every test binary that shares this module compares orders
pub fn assert_orders_match(
    time_rpm: &[Vec<f64>],
    rate_hz: f64,
    speed_rpm: f64,
    ias_amplitude_rpm: &[Vec<Vec<f64>>],
    orders: &[f64],
    tolerance: f64,
) {
    for (node, record) in time_rpm.iter().enumerate() {
        for (q_index, &q) in orders.iter().enumerate() {
            let time = order_amplitude(record, rate_hz, speed_rpm, q);
            let freq = ias_amplitude_rpm[node][q_index][0];
            let err = (time - freq).abs() / freq;
            assert!(
                err < tolerance,
                "node {node} order {q}: time {time} vs frequency {freq} ({:.3} %)",
                100.0 * err
            );
        }
    }
}
