//! Where the linear response leaves its range (issue 16): IAS above a tenth of the mean
//! speed, where a rubber coupling's amplitude dependence and the twist the linear model
//! assumes small no longer hold; and a stage's twist beyond the measured range of its
//! amplitude law.

use crate::model::{ConnectionKind, Model};
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

/// Where a stage's twist leaves the measured range of its amplitude law
/// (`amplitude_poly_range`, mm of radial deformation of an element, seed 000 eq. 1): the
/// law is held at its end value there, so the response is an extrapolation.
#[derive(Debug, Clone, PartialEq)]
pub struct OutsideAmplitudeLaw {
    /// The rubber stage.
    pub connection: String,
    /// The speed range where it happens, rpm (engine speed).
    pub speeds_rpm: [f64; 2],
    /// The largest radial deformation reached there, mm: static twist plus the sum of
    /// the orders' twist amplitudes (an upper bound over the cycle).
    pub deformation_mm: f64,
    /// The law's measured range, mm.
    pub range_mm: [f64; 2],
}

impl std::fmt::Display for OutsideAmplitudeLaw {
    /// The note for a person, as `response` and the window give it.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} deforms its elements by up to {:.2} mm ({:.0}–{:.0} rpm), outside its amplitude \
             law's measured {}–{} mm: the law is held at its end value there",
            self.connection,
            self.deformation_mm,
            self.speeds_rpm[0],
            self.speeds_rpm[1],
            self.range_mm[0],
            self.range_mm[1]
        )
    }
}

/// The rubber stages whose twist in `response` (of `system`, built from `model`) reaches
/// beyond the stated range of their amplitude law. Each order's twist amplitude is its
/// torque over the stage's dynamic stiffness at the order's frequency,
/// `|T_q| / (k(f_q)·√(1 + η²))` in the stage's own shaft.
pub fn beyond_amplitude_law(
    model: &Model,
    system: &System,
    response: &Response,
) -> Vec<OutsideAmplitudeLaw> {
    let mut out = Vec::new();
    for (entry, &j) in response.connections.iter().enumerate() {
        let Some(ConnectionKind::Rubber(stage)) = model.connections.get(j).map(|c| &c.kind) else {
            continue;
        };
        let (Some(range_mm), Some(element)) = (
            stage.amplitude_poly.as_ref().and_then(|p| p.range),
            system.elements.iter().find(|e| e.connection == j),
        ) else {
            continue;
        };
        if stage.pitch_radius_m().is_none() {
            continue;
        }
        let static_rad = system.static_twist_rad[j].unwrap_or(0.0).abs();
        let mut found: Option<OutsideAmplitudeLaw> = None;
        for (s, &n) in response.speeds_rpm.iter().enumerate() {
            let vibration_rad: f64 = response
                .orders
                .iter()
                .enumerate()
                .map(|(q, &order)| {
                    let (k_referred, eta) = element.stiffness_at(order * n / 60.0);
                    let k_own = k_referred / element.torque_ratio.powi(2);
                    response.torque_amplitude_nm[entry][q][s] / (k_own * eta.hypot(1.0))
                })
                .sum();
            let largest_mm = stage.radial_deformation_mm(static_rad + vibration_rad);
            let smallest_mm = stage.radial_deformation_mm((static_rad - vibration_rad).max(0.0));
            if largest_mm <= range_mm[1] && smallest_mm >= range_mm[0] {
                continue;
            }
            let b = found.get_or_insert(OutsideAmplitudeLaw {
                connection: model.connections[j].name.clone(),
                speeds_rpm: [n, n],
                deformation_mm: largest_mm,
                range_mm,
            });
            b.speeds_rpm[1] = n;
            b.deformation_mm = b.deformation_mm.max(largest_mm);
        }
        out.extend(found);
    }
    out
}
