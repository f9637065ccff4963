//! The driveline as the bench knows it: nodes in their own shafts, connections, the
//! engine and the load. Both the truth and the user's nominal model are one of these;
//! the truth adds an [`crate::effects::Effect`]. Quantities follow model-format.md (SI,
//! own-shaft values, gear ratio = speed of `to` / speed of `from`).

use nalgebra::{DMatrix, DVector, SymmetricEigen};
use std::f64::consts::TAU;

/// A rotating mass.
#[derive(Debug, Clone)]
pub struct Node {
    pub name: String,
    /// kg·m² in its own shaft.
    pub inertia_kg_m2: f64,
    /// Absolute damping to the frame, N·m·s/rad.
    pub damping_nm_s: f64,
}

/// What a connection is (model-format.md `[[connection]]`).
#[derive(Debug, Clone, PartialEq)]
pub enum Kind {
    /// Linear spring and viscous damper.
    Shaft { stiffness: f64, damping: f64 },
    /// Rubber stage: static stiffness N·m/rad and relative damping ψ (DIN 740).
    Rubber { stiffness: f64, psi: f64 },
    /// Gear stage: ratio (to/from speed), mesh stiffness at the `to` side, mesh damping.
    Gear {
        ratio: f64,
        mesh_stiffness: f64,
        mesh_damping: f64,
    },
}

impl Kind {
    /// The spring and viscous dashpot a user models a rubber stage of static stiffness
    /// `stiffness` (N·m/rad) and relative damping `psi` by: seed 001 eq. 2,
    /// c = k·ψ/(2π·ω) at the first mode `f1_hz` (N·m·s/rad).
    pub fn user_dashpot(stiffness: f64, psi: f64, f1_hz: f64) -> Kind {
        Kind::Shaft {
            stiffness,
            damping: stiffness * psi / (TAU * TAU * f1_hz),
        }
    }
}

/// A connection between two nodes (indices).
#[derive(Debug, Clone)]
pub struct Connection {
    pub name: String,
    pub from: usize,
    pub to: usize,
    pub kind: Kind,
}

impl Connection {
    /// The kinematic factor of `from` in the twist: the gear ratio, else 1.
    pub fn lever(&self) -> f64 {
        match self.kind {
            Kind::Gear { ratio, .. } => ratio,
            _ => 1.0,
        }
    }

    /// The linear stiffness of the connection (N·m/rad at the `to` side).
    pub fn stiffness(&self) -> f64 {
        match self.kind {
            Kind::Shaft { stiffness, .. } | Kind::Rubber { stiffness, .. } => stiffness,
            Kind::Gear { mesh_stiffness, .. } => mesh_stiffness,
        }
    }
}

/// A pressure curve of one load: gauge bar against crank angle from firing TDC, −360…360°.
#[derive(Debug, Clone)]
pub struct PressureCurve {
    pub load: f64,
    pub angle_deg: Vec<f64>,
    pub bar: Vec<f64>,
}

/// A four-stroke reciprocating engine on one node (model-format.md `[engine]`).
#[derive(Debug, Clone)]
pub struct Engine {
    pub node: usize,
    pub firing_deg: Vec<f64>,
    pub bore_m: f64,
    pub crank_radius_m: f64,
    pub conrod_m: f64,
    pub reciprocating_kg: f64,
    /// Sorted by load.
    pub pressure: Vec<PressureCurve>,
}

/// A whole driveline.
#[derive(Debug, Clone)]
pub struct Driveline {
    pub name: String,
    pub nodes: Vec<Node>,
    pub connections: Vec<Connection>,
    pub engine: Engine,
    pub load_node: usize,
    /// Load damping on vibration of the load node, N·m·s/rad (spec `[load] damping`).
    pub load_damping_nm_s: f64,
}

/// Natural frequencies and shapes of the linearised driveline.
#[derive(Debug, Clone)]
pub struct Modes {
    /// Hz, ascending, rigid-body mode removed.
    pub freq_hz: Vec<f64>,
    /// Mass-normalised shapes (own-shaft angles), one column per mode.
    pub shapes: DMatrix<f64>,
}

impl Driveline {
    /// Mean speed of each node over the engine speed (product of gear ratios crossed).
    pub fn speed_ratios(&self) -> Vec<f64> {
        let mut r = vec![f64::NAN; self.nodes.len()];
        r[self.engine.node] = 1.0;
        for _ in 0..self.nodes.len() {
            for c in &self.connections {
                let g = self.lever_speed(c);
                if r[c.from].is_finite() && !r[c.to].is_finite() {
                    r[c.to] = r[c.from] * g;
                } else if r[c.to].is_finite() && !r[c.from].is_finite() {
                    r[c.from] = r[c.to] / g;
                }
            }
        }
        r
    }

    fn lever_speed(&self, c: &Connection) -> f64 {
        c.lever()
    }

    /// Mass matrix diagonal with the engine's cycle-mean reciprocating inertia
    /// (first order in λ: m·r²·(1/2 + λ²/8) per cylinder, model-format.md `[engine]`).
    pub fn mass_diag(&self) -> Vec<f64> {
        let mut m: Vec<f64> = self.nodes.iter().map(|n| n.inertia_kg_m2).collect();
        let e = &self.engine;
        let lam = e.crank_radius_m / e.conrod_m;
        m[e.node] += e.firing_deg.len() as f64
            * e.reciprocating_kg
            * e.crank_radius_m.powi(2)
            * (0.5 + lam * lam / 8.0);
        m
    }

    /// Stiffness matrix in own-shaft coordinates (a gear of ratio r and mesh stiffness k
    /// couples as k·(r·θ_from − θ_to)²/2).
    pub fn stiffness_matrix(&self, scale: impl Fn(usize) -> f64) -> DMatrix<f64> {
        let n = self.nodes.len();
        let mut k = DMatrix::zeros(n, n);
        for (i, c) in self.connections.iter().enumerate() {
            let (g, s) = (c.lever(), c.stiffness() * scale(i));
            k[(c.from, c.from)] += s * g * g;
            k[(c.from, c.to)] -= s * g;
            k[(c.to, c.from)] -= s * g;
            k[(c.to, c.to)] += s;
        }
        k
    }

    /// The static angle of every node (own shaft, rad) under the engine's mean torque
    /// `t_mean` (N·m) with the load node held at zero: the linear static solution; all
    /// zeros when it is singular.
    pub fn static_angles(&self, t_mean: f64) -> Vec<f64> {
        let k = self.stiffness_matrix(|_| 1.0);
        let keep: Vec<usize> = (0..self.nodes.len())
            .filter(|&i| i != self.load_node)
            .collect();
        let kr = DMatrix::from_fn(keep.len(), keep.len(), |r, c| k[(keep[r], keep[c])]);
        let mut f = DVector::zeros(keep.len());
        if let Some(p) = keep.iter().position(|&i| i == self.engine.node) {
            f[p] = t_mean;
        }
        let mut x = vec![0.0; self.nodes.len()];
        if let Some(sol) = kr.lu().solve(&f) {
            for (r, &i) in keep.iter().enumerate() {
                x[i] = sol[r];
            }
        }
        x
    }

    /// Undamped modes (the rigid-body mode dropped).
    pub fn modes(&self) -> Modes {
        self.modes_scaled(|_| 1.0)
    }

    /// Undamped modes with connection `i`'s stiffness times `scale(i)` (the rigid-body
    /// mode dropped).
    pub fn modes_scaled(&self, scale: impl Fn(usize) -> f64) -> Modes {
        let m = self.mass_diag();
        let k = self.stiffness_matrix(scale);
        let n = m.len();
        let a = DMatrix::from_fn(n, n, |i, j| k[(i, j)] / (m[i] * m[j]).sqrt());
        let eig = SymmetricEigen::new(a);
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&i, &j| eig.eigenvalues[i].total_cmp(&eig.eigenvalues[j]));
        let keep: Vec<usize> = order.into_iter().skip(1).collect();
        let freq_hz = keep
            .iter()
            .map(|&i| eig.eigenvalues[i].max(0.0).sqrt() / TAU)
            .collect();
        let shapes = DMatrix::from_fn(n, keep.len(), |r, c| {
            eig.eigenvectors[(r, keep[c])] / m[r].sqrt()
        });
        Modes { freq_hz, shapes }
    }

    /// Modal damping ratio of mode `j`: rubber stages count as hysteretic with loss
    /// factor ψ/2π (strain-energy weighted), viscous terms as c/(2ω).
    pub fn modal_damping(&self, modes: &Modes, j: usize) -> f64 {
        let phi = modes.shapes.column(j);
        let w = modes.freq_hz[j] * TAU;
        let mut num = 0.0;
        for c in &self.connections {
            let d = c.lever() * phi[c.from] - phi[c.to];
            num += match c.kind {
                Kind::Shaft { damping, .. } => damping * w * d * d,
                Kind::Rubber { stiffness, psi } => stiffness * psi / TAU * d * d,
                Kind::Gear { mesh_damping, .. } => mesh_damping * w * d * d,
            };
        }
        for (i, n) in self.nodes.iter().enumerate() {
            num += n.damping_nm_s * w * phi[i] * phi[i];
        }
        num += self.load_damping_nm_s * w * phi[self.load_node].powi(2);
        // φᵀKφ = ω² for mass-normalised shapes: ζ = (energy lost per radian)/(2 φᵀKφ).
        num / (2.0 * w * w)
    }

    /// Index of a node by name.
    pub fn node_index(&self, name: &str) -> Option<usize> {
        self.nodes.iter().position(|n| n.name == name)
    }
}
