//! A gear mesh's tooth contact: the free play's dead zone ([`super::dead_zone`]) and the
//! contact's own law once the flanks touch, linear or Hertzian.
//!
//! The mesh torque is `T = k·c(δ)`, δ the twist across the mesh (rad at its `to` side),
//! `k` the mesh stiffness and `c` the equivalent deflection:
//!
//! - **linear contact** (exponent n = 1, the default): `c = s(δ)`, the dead zone;
//! - **power-law contact** (n > 1): `c = s·(|s|/s_ref)^(n−1)`. Hertz's law for two
//!   elastic bodies pressed together gives n = 3/2 (point contact: Johnson, *Contact
//!   Mechanics*, 1985, eq. 4.23, δ ∝ P^(2/3)); a tooth's line contact lies between 1 and
//!   3/2 once crowning and profile errors are counted. `s_ref` is the deflection at which
//!   the contact's secant stiffness is the mesh stiffness `k` — the deflection at the load
//!   the mesh stiffness was quoted for. Below it the contact is softer, beyond it stiffer;
//!   its tangent there is n·k.
//!
//! Every view takes the same law: the time domain applies `c` ([`crate::transient`]); the
//! linear views take its tangent at the static torque ([`ToothContact::working_point`],
//! [`super::static_twist`]). Written by hand: a one-line law and a bisection, which no
//! crate offers for this form.

use super::dead_zone::{contact_point, dead_zone};

/// Least share of the mesh stiffness a power-law contact keeps in the linear views: a
/// contact that carries no mean torque has no tangent stiffness at all (c' = 0 at s = 0),
/// which would make the mesh a second rigid-body mode. 1 % keeps the mesh mode finite and
/// far below its loaded frequency; the time domain applies the law itself.
pub const MIN_SHARE: f64 = 0.01;

/// The contact law of one gear mesh. Angles in rad at the mesh's `to` side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToothContact {
    /// Half the free play (0: none).
    pub half_gap_rad: f64,
    /// Width ε of the dead zone's softening (0: a hard edge).
    pub softening_rad: f64,
    /// Exponent n of the contact law (1: linear; 1.5: Hertzian).
    pub exponent: f64,
    /// Deflection s_ref at which the secant stiffness is the mesh stiffness (used when
    /// n ≠ 1; > 0).
    pub reference_rad: f64,
}

impl ToothContact {
    /// A linear contact with free play `half_gap_rad` softened over `softening_rad`.
    pub fn linear(half_gap_rad: f64, softening_rad: f64) -> Self {
        Self {
            half_gap_rad,
            softening_rad,
            exponent: 1.0,
            reference_rad: 1.0,
        }
    }

    /// True when `c(δ) = δ`: no play and a linear contact.
    pub fn is_linear(&self) -> bool {
        self.half_gap_rad == 0.0 && self.exponent == 1.0
    }

    /// The power law's factor `(|s|/s_ref)^(n−1)` for dead-zone output `s`.
    fn factor(&self, s: f64) -> f64 {
        if self.exponent == 1.0 {
            1.0
        } else {
            (s.abs() / self.reference_rad).powf(self.exponent - 1.0)
        }
    }

    /// The equivalent deflection `c(δ)` for twist `d`: the mesh torque over the mesh
    /// stiffness, rad.
    #[inline]
    pub fn deflection(&self, d: f64) -> f64 {
        let s = dead_zone(d, self.half_gap_rad, self.softening_rad);
        s * self.factor(s)
    }

    /// Where the contact works when it passes a mean equivalent deflection `x` = T/k
    /// (rad): the twist δ with c(δ) = x, and the share c'(δ) of the mesh stiffness that
    /// acts on small vibrations about it, floored at [`MIN_SHARE`] for a power-law contact.
    /// `None` for a hard linear contact, whose tangent is the mesh stiffness once the
    /// flanks touch (its linear views take the mesh stiffness at the torque's twist).
    pub fn working_point(&self, x: f64) -> Option<(f64, f64)> {
        if self.exponent == 1.0 {
            return contact_point(x, self.half_gap_rad, self.softening_rad);
        }
        if !x.is_finite() {
            return None;
        }
        // c = s·|s/s_ref|^(n−1) inverts in closed form for s; the dead zone then by its
        // own inversion (softened) or by adding the half play (hard).
        let n = self.exponent;
        let s = x.signum() * (x.abs() * self.reference_rad.powf(n - 1.0)).powf(1.0 / n);
        let (d, slope) = contact_point(s, self.half_gap_rad, self.softening_rad)
            .unwrap_or((s + self.half_gap_rad * s.signum(), 1.0));
        let share = (n * self.factor(s) * slope).max(MIN_SHARE);
        Some((d, share))
    }
}

#[cfg(test)]
mod tests {
    use super::{MIN_SHARE, ToothContact};

    const H: f64 = 1e-3;

    fn hertz(eps: f64) -> ToothContact {
        ToothContact {
            half_gap_rad: H,
            softening_rad: eps,
            exponent: 1.5,
            reference_rad: 2e-3,
        }
    }

    /// A linear contact is the dead zone itself; a power law meets the mesh stiffness's
    /// line at s = s_ref and is n·k steep there (hard edge: s = δ − h exactly).
    #[test]
    fn the_power_law_meets_the_mesh_stiffness_at_its_reference() {
        let lin = ToothContact::linear(H, 0.0);
        assert_eq!(lin.deflection(3.0 * H), 2.0 * H);
        let c = hertz(0.0);
        assert_eq!(c.deflection(0.5 * H), 0.0);
        assert!((c.deflection(3.0 * H) - 2e-3).abs() < 1e-18);
        assert!((c.deflection(-3.0 * H) + 2e-3).abs() < 1e-18);
        // At s = s_ref/4 the secant is √(1/4) = ½ of the mesh stiffness.
        assert!((c.deflection(1.5 * H) - 0.5e-3 * 0.5).abs() < 1e-18);
        let (d, share) = c.working_point(2e-3).unwrap();
        assert!((d - 3.0 * H).abs() < 1e-15);
        assert!((share - 1.5).abs() < 1e-12);
    }

    /// The working point inverts the law and its share is the law's slope (central
    /// difference of step 1e-9 rad; its truncation error is ~(1e-9/ε)² ≤ 1e-8 here).
    #[test]
    fn the_working_point_inverts_the_law_with_its_slope() {
        let c = hertz(2e-4);
        for x in [-3e-3, -1e-4, 1e-6, 4e-4, 5e-3] {
            let (d, share) = c.working_point(x).unwrap();
            assert!(
                (c.deflection(d) - x).abs() < 1e-12 * x.abs().max(1e-9),
                "x = {x}"
            );
            let numeric = (c.deflection(d + 1e-9) - c.deflection(d - 1e-9)) / 2e-9;
            assert!(
                (share - numeric.max(MIN_SHARE)).abs() < 1e-5,
                "{share} against {numeric}"
            );
        }
        // An unloaded power-law contact keeps the floor, not zero.
        assert_eq!(c.working_point(0.0).unwrap().1, MIN_SHARE);
        assert!(ToothContact::linear(0.0, 0.0).is_linear());
        assert!(!c.is_linear());
    }
}
