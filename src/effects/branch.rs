//! `unmodelled_mode`, branch form: a local mode hanging on a node (issue 14: "a local mode
//! at any node, not only a coupling half"). A part the user lumped into a node is really
//! elastic against it — a torsional damper's ring on the crank, a pulley on a rubber hub,
//! a flywheel's ring gear, a brake disc on a soft hub — so the node carries a branch: an
//! inertia on a spring of its own, whose mode against the held node is the missing
//! degree of freedom.
//!
//! The branch is seed 001's two-mass picture applied at one node: the host `J_h` and the
//! branch `J_b = r·J_h` joined by `k = J_b·(2π f)²` with viscous damping
//! `c = 2ζ·J_b·2π f`. With the host held, the branch rings at `f`; free, the pair splits
//! into an anti-resonance of the host at `f` and the classic absorber pair
//! (Den Hartog), which the unit test checks against the closed form.

use super::EffectError;
use super::effect::{EffectSpec, Params};
use super::truth::Applied;
use crate::model::{Connection, ConnectionKind, GROUND, Inertia, Model, Shaft};
use std::f64::consts::TAU;

/// Default share of the host's inertia that is really on the branch.
pub const DEFAULT_INERTIA_RATIO: f64 = 0.15;
/// Default damping ratio of the branch's own mode: a rubber-bushed ring (seed 000's
/// ψ ≈ 0.1–0.3 gives ζ = ψ/4π ≈ 0.01–0.03).
pub const DEFAULT_DAMPING_RATIO: f64 = 0.02;

/// `unmodelled_mode` with `form = branch`: node `node` (required) carries a branch of
/// inertia `inertia_ratio` × its own (default [`DEFAULT_INERTIA_RATIO`], 0.005–0.5; taken
/// from it, so the total inertia is unchanged) on a spring tuned to `frequency_hz` (1 Hz
/// – 10 kHz, default 100) with damping ratio `damping_ratio` (0–0.5, default
/// [`DEFAULT_DAMPING_RATIO`]). The new node is `<node>_branch`, its spring
/// `<node>_branch_spring` (a shaft: spring and viscous damper).
pub(crate) fn branch_mode(model: &mut Model, spec: &EffectSpec) -> Result<Applied, EffectError> {
    let mut p = Params::new(
        spec,
        &[
            "form",
            "node",
            "frequency_hz",
            "inertia_ratio",
            "damping_ratio",
        ],
    )?;
    p.text("form", Some("branch".into()))?;
    let host = p.text("node", None)?;
    let f_hz = p.number("frequency_hz", 100.0, 1.0, 1.0e4)?;
    let ratio = p.number("inertia_ratio", DEFAULT_INERTIA_RATIO, 0.005, 0.5)?;
    let zeta = p.number("damping_ratio", DEFAULT_DAMPING_RATIO, 0.0, 0.5)?;
    let Some(h) = model.node_index(&host) else {
        return Err(p.bad("node", format!("no node `{host}`")));
    };
    let name = format!("{host}_branch");
    if model.node_index(&name).is_some() || name == GROUND {
        return Err(p.bad("node", format!("`{name}` is already a node")));
    }
    let j_b = ratio * model.inertias[h].inertia_kg_m2;
    model.inertias[h].inertia_kg_m2 -= j_b;
    let omega = TAU * f_hz;
    model.inertias.push(Inertia {
        name: name.clone(),
        inertia_kg_m2: j_b,
        damping_nm_s_per_rad: 0.0,
    });
    model.connections.push(Connection {
        name: format!("{name}_spring"),
        from: host.clone(),
        to: name.clone(),
        kind: ConnectionKind::Shaft(Shaft::massless(
            j_b * omega * omega,
            2.0 * zeta * j_b * omega,
        )),
    });
    let summary = format!(
        "node `{host}` carries a branch `{name}` of {j_b:.4e} kg·m² ({:.1} % of its inertia, \
         which the user had lumped into it) on a spring tuned to {f_hz:.1} Hz, damping \
         ratio {zeta}",
        100.0 * ratio
    );
    Ok((p.resolved, summary))
}

#[cfg(test)]
mod tests {
    use crate::effects::{Effect, EffectSpec, build_truth};
    use crate::model::parse_model;
    use crate::physics::{OperatingPoint, System};

    const J_HOST: f64 = 2.0;
    const K_GROUND: f64 = 8.0e4;

    fn host_on_ground() -> crate::model::Model {
        let text = format!(
            "format = 1\nname = \"absorber\"\n[[inertia]]\nname = \"host\"\ninertia = \
             {J_HOST}\n[[connection]]\nkind = \"shaft\"\nname = \"mount\"\nfrom = \
             \"host\"\nto = \"ground\"\nstiffness = {K_GROUND}\n"
        );
        parse_model(&text, "absorber.toml").unwrap()
    }

    /// The classic absorber: host `J_h` on `k_1` to ground, branch `J_b` on `k_2`. Its
    /// natural frequencies are the roots of
    /// `J_h·J_b·ω⁴ − (J_h·k_2 + J_b·(k_1 + k_2))·ω² + k_1·k_2 = 0`.
    fn absorber_hz(j_h: f64, j_b: f64, k1: f64, k2: f64) -> [f64; 2] {
        let a = j_h * j_b;
        let b = -(j_h * k2 + j_b * (k1 + k2));
        let c = k1 * k2;
        let d = (b * b - 4.0 * a * c).sqrt();
        let w2 = [(-b - d) / (2.0 * a), (-b + d) / (2.0 * a)];
        w2.map(|w| w.sqrt() / std::f64::consts::TAU)
    }

    #[test]
    fn branch_has_the_absorber_frequencies_and_keeps_the_inertia() {
        let user = host_on_ground();
        let (ratio, f_b) = (0.1, 25.0);
        let spec = EffectSpec::new(Effect::UnmodelledMode)
            .with("form", "branch")
            .with("node", "host")
            .with("frequency_hz", f_b)
            .with("inertia_ratio", ratio)
            .with("damping_ratio", 0.0);
        let truth = build_truth(&user, &spec, 0.0, 0).unwrap();
        let m = &truth.model;
        let total: f64 = m.inertias.iter().map(|n| n.inertia_kg_m2).sum();
        assert!((total - J_HOST).abs() < 1e-12 * J_HOST, "{total}");
        let j_b = ratio * J_HOST;
        let k2 = j_b * (std::f64::consts::TAU * f_b).powi(2);
        let want = absorber_hz(J_HOST - j_b, j_b, K_GROUND, k2);
        let system = System::new(m, OperatingPoint::default()).unwrap();
        let got: Vec<f64> = crate::modal::modes(&system)
            .unwrap()
            .iter()
            .map(|m| m.frequency_hz)
            .collect();
        assert_eq!(got.len(), 2, "{got:?}");
        // An eigenvalue solver on a 2×2 system: agreement to 1e-9 relative.
        for (g, w) in got.iter().zip(want) {
            assert!((g / w - 1.0).abs() < 1e-9, "{got:?} against {want:?}");
        }
        // The pair straddles the branch's own tuning and the host's alone.
        let host_alone = (K_GROUND / J_HOST).sqrt() / std::f64::consts::TAU;
        assert!(got[0] < f_b.min(host_alone) && got[1] > f_b.max(host_alone));
        assert!(truth.effect.summary.contains("host_branch"));
    }

    #[test]
    fn branch_refuses_what_it_cannot_build() {
        let user = host_on_ground();
        let base = EffectSpec::new(Effect::UnmodelledMode).with("form", "branch");
        assert!(
            build_truth(&user, &base, 0.0, 0).is_err(),
            "node is required"
        );
        let nowhere = base.clone().with("node", "nowhere");
        assert!(build_truth(&user, &nowhere, 0.0, 0).is_err());
        let heavy = base.with("node", "host").with("inertia_ratio", 0.9);
        assert!(build_truth(&user, &heavy, 0.0, 0).is_err());
    }
}
