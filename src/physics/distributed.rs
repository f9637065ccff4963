//! A shaft with its own inertia distributed uniformly along it (issue 15 item 4,
//! `[[connection]] kind = "shaft"` with `inertia`).
//!
//! **Exact element.** A uniform shaft of stiffness `k = G·I_p/L` and polar inertia
//! `J = ρ·I_p·L` obeys the wave equation `G·θ'' = ρ·θ̈`. At angular frequency ω its end
//! torques and end angles are related exactly by the dynamic stiffness (Pilkey, *Formulas
//! for Stress, Strain and Structural Matrices*, torsion of a uniform bar; the torsional
//! case of Wittrick & Williams 1971):
//!
//! ```text
//! D(ω) = k·β/sin β · [[cos β, −1], [−1, cos β]],   β = ω·√(J/k) = ω·L/c,  c = √(G/ρ)
//! ```
//!
//! For β → 0 it tends to the static spring less ω² times the consistent mass `J/6·[[2,1],
//! [1,2]]`. A viscous `damping` makes the stiffness complex, `k* = k + iωc`, and β with it.
//! The shaft clamped at both ends has its own frequencies at β = π, 2π, …; those are the
//! `J0` of the Wittrick–Williams count ([`crate::modal::wittrick_williams`]).
//!
//! **Discretized chain.** The matrix analyses (undamped mode shapes, damped modes, the
//! time domain) see the shaft as `n` equal segments: springs `n·k` and `n − 1` internal
//! degrees of freedom of inertia `J/n`, with `J/(2n)` at each end. A lumped chain is
//! ≈ (β/n)²/24 low in frequency, so [`segment_count`] takes `n ≥ 6.5·β` at the top of
//! the model's band: 0.1 %. Natural frequencies are then refined to the exact element's
//! by the Wittrick–Williams count, and the forced response adds to each segment the
//! difference between its exact dynamic stiffness and its lumped one
//! ([`add_exact_correction`]), so modes and response are exact at any `n`.
//!
//! Written here: the element is four lines of complex arithmetic on torsim's own
//! matrices, which no crate provides.

use num_complex::Complex64;

/// Relative frequency error of the lumped chain [`segment_count`] aims for at the top of
/// the band: 0.1 %, the issue's tolerance for modes.
const LUMPED_ERROR: f64 = 1.0e-3;

/// Below this |β| the element is evaluated by its series (β/sin β → 1).
const SERIES_BETA: f64 = 1.0e-4;

/// A distributed shaft of a [`super::System`], referred to the reference shaft.
#[derive(Debug, Clone, PartialEq)]
pub struct DistributedShaft {
    /// Index of the model connection.
    pub connection: usize,
    /// DOF at the `from` end (`None`: ground).
    pub from_dof: Option<usize>,
    /// DOF at the `to` end (`None`: ground).
    pub to_dof: Option<usize>,
    /// Whole-shaft referred stiffness `k·r²`, N·m/rad.
    pub stiffness_nm_per_rad: f64,
    /// Whole-shaft referred viscous damping `c·r²`, N·m·s/rad.
    pub damping_nm_s_per_rad: f64,
    /// Whole-shaft referred inertia `J·r²`, kg·m².
    pub inertia_kg_m2: f64,
    /// Indices of its segment elements in [`super::System::elements`], `from` end first.
    pub elements: std::ops::Range<usize>,
}

impl DistributedShaft {
    /// Number of segments.
    pub fn segments(&self) -> usize {
        self.elements.len()
    }
}

/// The result row of each item of a sequence of connection indices, and whether it is the
/// row's first: consecutive items of one connection (a distributed shaft's segments)
/// share a row. Rows are numbered in order of appearance.
pub fn connection_rows(connections: impl IntoIterator<Item = usize>) -> Vec<(usize, bool)> {
    let mut rows = Vec::new();
    let mut previous = None;
    let mut count = 0;
    for c in connections {
        if previous == Some(c) {
            rows.push((count - 1, false));
        } else {
            rows.push((count, true));
            count += 1;
        }
        previous = Some(c);
    }
    rows
}

impl super::System {
    /// Per DOF, the inertia the distributed shafts' segments lump onto it (half of each
    /// segment's at each of its ends), kg·m²: part of [`super::System::inertia_kg_m2`].
    pub fn segment_inertia_kg_m2(&self) -> Vec<f64> {
        let mut out = vec![0.0; self.dof_count()];
        for e in &self.elements {
            for d in [e.from_dof, e.to_dof].into_iter().flatten() {
                out[d] += 0.5 * e.distributed_inertia();
            }
        }
        out
    }
}

/// What [`expand`] adds to: the referred inertia and damping per DOF, the elements, and
/// the warnings for a person.
pub(super) struct Assembly<'a> {
    pub inertia: &'a mut Vec<f64>,
    pub damping: &'a mut Vec<f64>,
    pub elements: &'a mut Vec<super::Element>,
    pub warnings: &'a mut Vec<String>,
}

/// Expands shaft `(connection index, name, shaft)` with inertia into its segments (given,
/// or [`segment_count`] for `band_top_hz`) along new internal DOFs appended to the
/// assembly; `ends` are its DOFs and the |speed ratio| of its own shaft. Warns when the
/// segments fall short of the band. Returns the shaft as [`super::System::distributed`]
/// keeps it.
pub(super) fn expand(
    (connection, name, shaft): (usize, &str, &crate::model::Shaft),
    (from_dof, to_dof, ratio): (Option<usize>, Option<usize>, f64),
    band_top_hz: f64,
    into: Assembly<'_>,
) -> DistributedShaft {
    let (k_own, j_own) = (shaft.stiffness_nm_per_rad, shaft.inertia_kg_m2);
    let n = shaft
        .segments
        .map_or_else(|| segment_count(k_own, j_own, band_top_hz), |n| n as usize)
        .max(1);
    let valid_hz = lumped_valid_to_hz(k_own, j_own, n);
    if valid_hz < band_top_hz {
        into.warnings.push(format!(
            "shaft `{name}`: its {n} segments follow the exact element within 0.1 % up to \
             {valid_hz:.1} Hz, below the band's {band_top_hz:.1} Hz; natural frequencies and \
             the forced response stay exact, damping ratios and the time domain are lumped \
             above (set `segments`)"
        ));
    }
    let Assembly {
        inertia,
        damping,
        elements,
        ..
    } = into;
    let ends = (from_dof, to_dof);
    let r2 = ratio * ratio;
    let (k, c, j) = (
        shaft.stiffness_nm_per_rad * r2,
        shaft.damping_nm_s_per_rad * r2,
        shaft.inertia_kg_m2 * r2,
    );
    let mut chain = vec![ends.0];
    for _ in 1..n {
        inertia.push(0.0);
        damping.push(0.0);
        chain.push(Some(inertia.len() - 1));
    }
    chain.push(ends.1);
    let first = elements.len();
    let per_segment = j / n as f64;
    for pair in chain.windows(2) {
        for d in pair.iter().flatten() {
            inertia[*d] += 0.5 * per_segment;
        }
        elements.push(super::Element {
            connection,
            from_dof: pair[0],
            to_dof: pair[1],
            torque_ratio: ratio,
            law: super::ElementLaw::Linear {
                stiffness_nm_per_rad: n as f64 * k,
                damping_nm_s_per_rad: n as f64 * c,
                distributed_inertia_kg_m2: per_segment,
            },
        });
    }
    DistributedShaft {
        connection,
        from_dof: ends.0,
        to_dof: ends.1,
        stiffness_nm_per_rad: k,
        damping_nm_s_per_rad: c,
        inertia_kg_m2: j,
        elements: first..elements.len(),
    }
}

/// Most segments [`segment_count`] chooses by itself: every segment is a DOF of the damped
/// modes and the time domain (the damped modes of a 1000-segment shaft took 20 s). A
/// model that needs more says so with `segments`.
pub const AUTO_MAX_SEGMENTS: usize = 64;

/// Segments for a shaft of stiffness `k` (N·m/rad) and inertia `j` (kg·m², both in one
/// shaft) so that the lumped chain is within 0.1 % in frequency up to `band_top_hz`:
/// `n = ⌈β/√(24·0.001)⌉`, 1 … [`AUTO_MAX_SEGMENTS`].
pub fn segment_count(stiffness_nm_per_rad: f64, inertia_kg_m2: f64, band_top_hz: f64) -> usize {
    let n = (beta_at(stiffness_nm_per_rad, inertia_kg_m2, band_top_hz)
        / (24.0 * LUMPED_ERROR).sqrt())
    .ceil();
    if n.is_finite() {
        (n as usize).clamp(1, AUTO_MAX_SEGMENTS)
    } else {
        1
    }
}

/// `β = ω·√(J/k)` of a shaft at `frequency_hz`.
fn beta_at(stiffness_nm_per_rad: f64, inertia_kg_m2: f64, frequency_hz: f64) -> f64 {
    std::f64::consts::TAU * frequency_hz * (inertia_kg_m2 / stiffness_nm_per_rad).sqrt()
}

/// The highest frequency, Hz, up to which `segments` lumped segments of a shaft (`k`, `j`)
/// stay within 0.1 % of the exact element: `√(24·0.001)·n / (2π·√(J/k))`.
pub fn lumped_valid_to_hz(stiffness_nm_per_rad: f64, inertia_kg_m2: f64, segments: usize) -> f64 {
    (24.0 * LUMPED_ERROR).sqrt() * segments as f64
        / beta_at(stiffness_nm_per_rad, inertia_kg_m2, 1.0)
}

/// The exact element's `(D_aa, D_ab)` for complex stiffness `k` (N·m/rad) and inertia `j`
/// (kg·m²) at `omega_rad_s`: `D = [[D_aa, D_ab], [D_ab, D_aa]]`.
pub fn exact_ends(k: Complex64, inertia_kg_m2: f64, omega_rad_s: f64) -> (Complex64, Complex64) {
    let w2j = omega_rad_s * omega_rad_s * inertia_kg_m2;
    let beta = (Complex64::new(w2j, 0.0) / k).sqrt();
    if beta.norm() < SERIES_BETA {
        return (k - w2j / 3.0, -k - w2j / 6.0);
    }
    let scale = k * beta / beta.sin();
    (scale * beta.cos(), -scale)
}

/// Clamped–clamped frequencies of a shaft (`k`, `j`, real) strictly below `omega_rad_s`:
/// β = π, 2π, … (the element's `J0` in the Wittrick–Williams count).
pub fn clamped_below(stiffness_nm_per_rad: f64, inertia_kg_m2: f64, omega_rad_s: f64) -> usize {
    let beta = omega_rad_s * (inertia_kg_m2 / stiffness_nm_per_rad).sqrt();
    let ratio = beta / std::f64::consts::PI;
    if !ratio.is_finite() || ratio <= 0.0 {
        return 0;
    }
    (ratio.ceil() as usize).saturating_sub(1)
}

/// Adds to the dynamic stiffness `out` what a segment (`a`, `b` its DOFs, `None` ground)
/// lacks as a lumped spring `k*` with `J/2` at each end: `D_exact − (k*·[[1,−1],[−1,1]] −
/// ω²·J/2·I)`. `k` is complex (`k + iωc`), `j` the segment's inertia, kg·m².
pub fn add_exact_correction(
    out: &mut nalgebra::DMatrix<Complex64>,
    a: Option<usize>,
    b: Option<usize>,
    k: Complex64,
    inertia_kg_m2: f64,
    omega_rad_s: f64,
) {
    let (d_aa, d_ab) = exact_ends(k, inertia_kg_m2, omega_rad_s);
    let half = 0.5 * omega_rad_s * omega_rad_s * inertia_kg_m2;
    super::matrices::add_two_port(out, a, b, d_aa - k + half, d_ab + k);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The exact element at small β is the consistent-mass element to O(β⁴).
    #[test]
    fn small_beta_is_the_consistent_mass_element() {
        let (k, j) = (1.0e5_f64, 2.0);
        let omega = 0.01 * (k / j).sqrt(); // β = 0.01
        let (aa, ab) = exact_ends(Complex64::new(k, 0.0), j, omega);
        let w2j = omega * omega * j;
        // Next terms are O(k·β⁴) = 1e-3 N·m/rad.
        assert!((aa.re - (k - w2j / 3.0)).abs() < 1e-2 && aa.im == 0.0);
        assert!((ab.re - (-k - w2j / 6.0)).abs() < 1e-2 && ab.im == 0.0);
    }

    /// At β = π/2 a shaft clamped at one end is at resonance (D_aa = 0); at β = π the
    /// clamped–clamped count steps.
    #[test]
    fn quarter_wave_and_clamped_count() {
        let (k, j) = (3.0e4_f64, 5.0);
        let omega = std::f64::consts::FRAC_PI_2 * (k / j).sqrt();
        let (aa, _) = exact_ends(Complex64::new(k, 0.0), j, omega);
        assert!(aa.norm() < 1e-9 * k, "{aa}");
        let w_pi = std::f64::consts::PI * (k / j).sqrt();
        assert_eq!(clamped_below(k, j, 0.999 * w_pi), 0);
        assert_eq!(clamped_below(k, j, 1.001 * w_pi), 1);
        assert_eq!(clamped_below(k, j, 2.5 * w_pi), 2);
    }

    #[test]
    fn segments_meet_the_lumped_error_at_the_band_top() {
        let (k, j) = (1.0e4_f64, 10.0);
        let n = segment_count(k, j, 20.0);
        let beta = std::f64::consts::TAU * 20.0 * (j / k).sqrt();
        let per = beta / n as f64;
        assert!(per * per / 24.0 <= LUMPED_ERROR && n > 1 && n < AUTO_MAX_SEGMENTS);
        // n is the fewest that reach 20 Hz.
        assert!(lumped_valid_to_hz(k, j, n) >= 20.0 && lumped_valid_to_hz(k, j, n - 1) < 20.0);
        assert_eq!(segment_count(1.0e9, 1e-6, 10.0), 1);
        assert_eq!(segment_count(k, j, 1.0e4), AUTO_MAX_SEGMENTS);
    }
}
