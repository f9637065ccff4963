//! Where the linear response leaves its range (issue 16): IAS above a tenth of the mean
//! speed, where a rubber coupling's amplitude dependence and the twist the linear model
//! assumes small no longer hold.

use crate::physics::System;
use crate::response::Response;

/// IAS above this share of a node's mean speed is beyond what the linear response
/// describes: 0.1 (issue 16).
pub const LINEAR_IAS_SHARE: f64 = 0.1;

/// Where the linear response goes beyond its range: a node whose half peak-to-peak IAS
/// exceeds [`LINEAR_IAS_SHARE`] of its own mean speed.
#[derive(Debug, Clone, PartialEq)]
pub struct BeyondLinear {
    /// The node.
    pub node: String,
    /// The speed range where it happens, rpm (engine speed).
    pub speeds_rpm: [f64; 2],
    /// The largest IAS there over the node's mean speed.
    pub worst_share: f64,
}

/// The nodes and speed ranges where the linear response is beyond its range.
pub fn beyond_linear_range(system: &System, response: &Response) -> Vec<BeyondLinear> {
    let mut out = Vec::new();
    for (k, ias) in response.ias_half_peak_to_peak_rpm.iter().enumerate() {
        let ratio = system.speed_ratio.get(k).copied().unwrap_or(1.0).abs();
        let mut found: Option<BeyondLinear> = None;
        for (s, &n) in response.speeds_rpm.iter().enumerate() {
            let share = ias[s] / (n * ratio).max(f64::MIN_POSITIVE);
            if share <= LINEAR_IAS_SHARE {
                continue;
            }
            let b = found.get_or_insert(BeyondLinear {
                node: system.node_names.get(k).cloned().unwrap_or_default(),
                speeds_rpm: [n, n],
                worst_share: share,
            });
            b.speeds_rpm[1] = n;
            b.worst_share = b.worst_share.max(share);
        }
        out.extend(found);
    }
    out
}
