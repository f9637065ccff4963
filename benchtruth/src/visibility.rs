//! How plainly a campaign shows its concealed effect, measured by the bench on its own
//! truth (issue 14, item 4: a benchmark case must be one whose effect a campaign could
//! show; item 6: what a campaign can tell apart).
//!
//! Every recording is simulated twice without noise: the truth as drawn, and its twin
//! without the effect ([`crate::twin`]). Both are analysed the same way, by the bench's
//! own order analysis ([`crate::order_meter`]). The effect's signature in one
//! observation (recording, window, station, order) is
//!
//! `z = |a_truth − a_twin| / √(σ_a² + (r·max(a_truth, a_twin))²)`
//!
//! with σ_a the white measurement noise through that window (`σ·√(2·Σw²)/Σw`, per
//! Fourier component) and `r` = [`RELATIVE_FLOOR`], the part of an amplitude that the
//! plain parameters' errors (±3 % on every inertia and stiffness of the user's model)
//! already move. The campaign's visibility is the largest `z`, and where it is: a draw
//! below [`MIN_VISIBLE_Z`] is drawn again ([`crate::redraw`]), and `truth.toml` and the
//! scorer's `results.csv` carry it. torsim never reads it.

use crate::draw::Case;
use crate::order_meter::OrderMeter;
use crate::twin::{twin, twin_meter};

/// The relative floor `r` of an amplitude's uncertainty (see the module doc).
pub const RELATIVE_FLOOR: f64 = 0.02;
/// The least largest `z` of a campaign that shows its effect: one order amplitude
/// somewhere moved by five times its uncertainty, 10 % of it where the noise is small
/// beside the relative floor ([`crate::redraw`] draws a case below it again).
pub const MIN_VISIBLE_Z: f64 = 5.0;

/// The campaign's visibility of its effect.
#[derive(Debug, Clone, PartialEq)]
pub struct Visibility {
    /// The largest `z` over the observations.
    pub z_max: f64,
    /// Where: recording stem, window, station node name, order.
    pub at: String,
    /// Observations with `z ≥ 3`, and all observations compared.
    pub above_3: usize,
    pub observations: usize,
}

/// Compares the truth's meters (one per recording, in campaign order) with its twin's.
pub fn compare(case: &Case, truth: &[OrderMeter], twin: &[OrderMeter]) -> Visibility {
    let sigma = case.campaign.noise_rpm;
    let mut best = Visibility {
        z_max: 0.0,
        at: String::new(),
        above_3: 0,
        observations: 0,
    };
    for (r, (a, b)) in truth.iter().zip(twin).enumerate() {
        let stem = &case.campaign.recordings[r].stem;
        for (w, ((unit, ta), (_, tb))) in a.amplitudes().iter().zip(b.amplitudes()).enumerate() {
            let noise = sigma * unit;
            for (s, (sa, sb)) in ta.iter().zip(&tb).enumerate() {
                for (k, (x, y)) in sa.iter().zip(sb).enumerate() {
                    let floor = RELATIVE_FLOOR * x.max(*y);
                    let z = (x - y).abs() / (noise * noise + floor * floor).sqrt().max(1e-300);
                    best.observations += 1;
                    best.above_3 += usize::from(z >= 3.0);
                    if z > best.z_max {
                        let node = &case.truth.nodes[case.campaign.stations[s].node].name;
                        best.z_max = z;
                        best.at =
                            format!("{stem} window {w}, {node}, order {}", 0.5 * (k + 1) as f64);
                    }
                }
            }
        }
    }
    best
}

/// The visibility of `case`'s effect, from the truth's meters of its recordings (campaign
/// order) and its twin's, simulated here in parallel; `None` for a control or a twin
/// that cannot be formed.
pub fn measure(case: &Case, truth: &[OrderMeter]) -> Option<Visibility> {
    let twin = twin(case)?;
    let twin_ref = &twin;
    let meters: Option<Vec<OrderMeter>> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..twin.campaign.recordings.len())
            .map(|i| s.spawn(move || twin_meter(twin_ref, i)))
            .collect();
        handles.into_iter().map(|h| h.join().ok()).collect()
    });
    Some(compare(case, truth, &meters?))
}
