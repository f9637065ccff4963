//! The driveline model as it stands in a model file (`spec/model-format.md`, format 1).
//!
//! These types hold what the user wrote, with names rather than indices, so that the GUI
//! can edit them and the writer can save them back unchanged. Everything here is plain
//! data; [`crate::physics::System`] resolves names, gear ratios and units for computing.
//! All quantities are SI unless the field name says otherwise.

/// Reserved node name for the frame.
use super::amplitude_form::AmplitudeForm;
use super::engine_types::{Engine, Harmonic};
use super::operation_types::{Expect, Load, Operation};

/// Reserved node name for the frame.
pub const GROUND: &str = "ground";

/// A whole driveline model (one model file).
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    /// Shown in the GUI title and in reports.
    pub name: String,
    /// Free text: where the numbers come from. Empty when absent.
    pub description: String,
    /// Rotating masses (the nodes), in file order.
    pub inertias: Vec<Inertia>,
    /// What joins the nodes, in file order.
    pub connections: Vec<Connection>,
    /// Reciprocating engine excitation, if any.
    pub engine: Option<Engine>,
    /// Prescribed harmonic torques (`[[harmonic]]`).
    pub harmonics: Vec<Harmonic>,
    /// What holds the mean speed (`[load]`), if written.
    pub load: Option<Load>,
    /// Damping ratio per mode (`[modal_damping]`), if written.
    pub modal_damping: Option<super::ModalDamping>,
    /// Speed ranges and orders (`[operation]`).
    pub operation: Operation,
    /// Checks run by `torsim check` (`[expect]`).
    pub expect: Expect,
}

/// `[[inertia]]`: a rotating mass, one node of the driveline.
#[derive(Debug, Clone, PartialEq)]
pub struct Inertia {
    /// Unique node name; `ground` is reserved.
    pub name: String,
    /// Moment of inertia about the shaft axis in the node's own shaft, kg·m² (> 0).
    pub inertia_kg_m2: f64,
    /// Absolute damping to the frame, N·m·s/rad (≥ 0, default 0).
    pub damping_nm_s_per_rad: f64,
}

/// `[[connection]]`: what joins two nodes (or a node and `ground`).
#[derive(Debug, Clone, PartialEq)]
pub struct Connection {
    /// Connection name; the file may omit it, then it is `from-to`.
    pub name: String,
    /// Node name the torque comes from (or `ground`).
    pub from: String,
    /// Node name the torque goes to (or `ground`).
    pub to: String,
    /// The kind of connection and its parameters.
    pub kind: ConnectionKind,
}

impl Connection {
    /// The name a connection gets when the file does not give one: `from-to`.
    pub fn default_name(from: &str, to: &str) -> String {
        format!("{from}-{to}")
    }
}

/// The three kinds of connection of format 1.
// Connections are few and edited in place; boxing the rubber stage is not worth it.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub enum ConnectionKind {
    /// `kind = "shaft"`: linear spring and viscous damper in parallel.
    Shaft(Shaft),
    /// `kind = "rubber"`: a highly flexible rubber coupling stage (seed 000).
    Rubber(RubberStage),
    /// `kind = "gear"`: a gear stage.
    Gear(Gear),
}

impl ConnectionKind {
    /// The `kind` string of the model file.
    pub fn kind_str(&self) -> &'static str {
        match self {
            ConnectionKind::Shaft(_) => "shaft",
            ConnectionKind::Rubber(_) => "rubber",
            ConnectionKind::Gear(_) => "gear",
        }
    }
}

/// A linear shaft: `T = k·Δθ + c·Δθ̇` in the shaft's own frame, massless or with its own
/// inertia distributed uniformly along it (issue 15, [`crate::physics::distributed`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Shaft {
    /// Torsional stiffness `G·I_p/L`, N·m/rad (> 0).
    pub stiffness_nm_per_rad: f64,
    /// Viscous damping, N·m·s/rad (≥ 0, default 0).
    pub damping_nm_s_per_rad: f64,
    /// The shaft's own polar inertia `ρ·I_p·L`, distributed uniformly along it, kg·m²
    /// (≥ 0, default 0: massless, the classic lumped shaft).
    pub inertia_kg_m2: f64,
    /// Segments the time domain and the mode shapes divide a shaft with inertia into
    /// (1..=1000); `None`: enough for 0.1 % in frequency over the model's band
    /// ([`crate::physics::distributed::segment_count`]). Modes and the forced response use
    /// the exact element whatever this is.
    pub segments: Option<u32>,
}

impl Shaft {
    /// A massless shaft of stiffness `k` (N·m/rad) and damping `c` (N·m·s/rad).
    pub fn massless(stiffness_nm_per_rad: f64, damping_nm_s_per_rad: f64) -> Self {
        Self {
            stiffness_nm_per_rad,
            damping_nm_s_per_rad,
            inertia_kg_m2: 0.0,
            segments: None,
        }
    }
}

/// How a rubber stage's static stiffness is given.
#[derive(Debug, Clone, PartialEq)]
pub enum RubberStiffness {
    /// `stiffness = k`: static torsional stiffness at 25 °C, N·m/rad.
    Direct(f64),
    /// `elements = {...}`: assembled from rubber elements (seed 000 eq. 12).
    Elements(RubberElements),
}

/// Rubber elements of a coupling stage (seed 000 §3.4).
#[derive(Debug, Clone, PartialEq)]
pub struct RubberElements {
    /// Total number of elements `n`.
    pub count: u32,
    /// Number of elements on one side `n1` (0 < n1 < n).
    pub per_side: u32,
    /// Pitch diameter `D` of the element centres, m.
    pub pitch_diameter_m: f64,
    /// Radial stiffness of one unloaded element `c_R0`, N/m.
    pub radial_stiffness_n_per_m: f64,
}

impl RubberElements {
    /// Static torsional stiffness of the assembled coupling, seed 000 eq. 12:
    /// `c_Tstat = c_R0 · (D/2)² · n1·(n − n1)/n`, N·m/rad.
    pub fn torsional_stiffness_nm_per_rad(&self) -> f64 {
        let n = f64::from(self.count);
        let n1 = f64::from(self.per_side);
        let radius_m = self.pitch_diameter_m / 2.0;
        self.radial_stiffness_n_per_m * radius_m * radius_m * n1 * (n - n1) / n
    }
}

/// A quadratic correction polynomial `a2·x² + a1·x + a0` with an optional validity range.
#[derive(Debug, Clone, PartialEq)]
pub struct Poly {
    /// Coefficients as written in the file: `[a2, a1, a0]`.
    pub coeffs: [f64; 3],
    /// `[lo, hi]`: the range the polynomial was measured over; outside it the factor is
    /// held at the end value (and a warning is raised).
    pub range: Option<[f64; 2]>,
}

/// Self-heating of a rubber stage (time domain): a lumped thermal mass.
#[derive(Debug, Clone, PartialEq)]
pub struct Thermal {
    /// Heat capacity of the rubber, J/K (> 0).
    pub capacity_j_per_k: f64,
    /// Conductance to ambient, W/K (> 0).
    pub conductance_w_per_k: f64,
    /// Ambient temperature, °C.
    pub ambient_c: f64,
}

/// `kind = "rubber"`: one stage of a highly flexible coupling.
#[derive(Debug, Clone, PartialEq)]
pub struct RubberStage {
    /// Static stiffness at 25 °C, directly or from elements.
    pub stiffness: RubberStiffness,
    /// Relative damping ψ (DIN 740) at 25 °C; loss factor `ξ = ψ/2π` (> 0).
    pub psi: f64,
    /// Rubber temperature, °C (default 25).
    pub temperature_c: f64,
    /// α_x(x), x the element's radial deformation in mm (seed 000 eq. 1); needs elements.
    pub amplitude_poly: Option<Poly>,
    /// A saturating α_x in place of `amplitude_poly` (issue 14,
    /// [`super::amplitude_saturation`]): `1 + s·tanh((x/x_s)²)`; needs elements.
    pub amplitude_saturation: Option<super::AmplitudeSaturation>,
    /// What α_x scales (`amplitude_form`, default [`AmplitudeForm::Whole`]).
    pub amplitude_form: AmplitudeForm,
    /// α_f(f), f the vibration frequency in Hz (seed 000 eq. 9).
    pub frequency_poly: Option<Poly>,
    /// A causal power law in place of `frequency_poly` (issue 14,
    /// [`super::frequency_law`]): storage `(f/f_ref)^n`, loss factor `max(ψ/2π, tan(nπ/2))`.
    pub frequency_power_law: Option<super::PowerLaw>,
    /// A fractional Zener law in place of `frequency_poly` (issue 14,
    /// [`super::frequency_zener`]): an S-curve from the rubbery to `1 + Δ` times its
    /// stiffness, with the loss Kramers–Kronig ties to it.
    pub frequency_zener: Option<super::ZenerLaw>,
    /// α_Tc(T), T in °C (seed 000 eq. 10).
    pub temperature_stiffness_poly: Option<Poly>,
    /// α_Tξ(T), T in °C (seed 000 eq. 11).
    pub temperature_damping_poly: Option<Poly>,
    /// Optional self-heating model (time domain).
    pub thermal: Option<Thermal>,
    /// The catalogue's ratings (`rating = { … }`, [`super::rating`]), if given.
    pub rating: Option<super::rating::CouplingRating>,
}

/// `kind = "gear"`: a gear stage.
#[derive(Debug, Clone, PartialEq)]
pub struct Gear {
    /// Speed of `to` divided by speed of `from` (≠ 0; negative reverses direction).
    pub ratio: f64,
    /// Mesh stiffness at the `to` side, N·m/rad; `None` is a rigid constraint.
    pub mesh_stiffness_nm_per_rad: Option<f64>,
    /// Viscous mesh damping at the `to` side, N·m·s/rad (default 0), on the rate of the
    /// mesh twist. It acts whether or not the teeth are in contact, as in the classical
    /// gear-pair model of Kahraman & Singh (*J. Sound Vib.* 142(1), 1990, eq. 1: linear
    /// viscous damping beside the piecewise stiffness), so that without backlash the mesh
    /// is a spring and dashpot in every view. Needs `mesh_stiffness`.
    pub mesh_damping_nm_s_per_rad: f64,
    /// Total free play at the `to` side, degrees (default 0).
    pub backlash_deg: f64,
    /// Width ε of the tooth contact's softening, degrees at the `to` side (default 0: a
    /// hard contact). The mesh deflection is then the softened dead zone
    /// s(δ) = ½[(δ−h) + √((δ−h)² + ε²)] + ½[(δ+h) − √((δ+h)² + ε²)], h the half play:
    /// the contact stiffness rises from half to 95 % of the mesh stiffness over 2ε after
    /// the play closes, as Hertzian contact and profile errors make it. Ignored without
    /// backlash.
    pub backlash_softening_deg: f64,
    /// Exponent n of the tooth contact's law once the flanks touch (default 1: linear;
    /// 1.5: Hertzian), [`crate::physics::tooth_contact`]. torsim's extension.
    pub contact_exponent: f64,
    /// Deflection at the `to` side, degrees, at which a power-law contact's secant
    /// stiffness is `mesh_stiffness` (the deflection at the load the stiffness was quoted
    /// for). Needed when `contact_exponent` ≠ 1 (default 0: none).
    pub contact_reference_deg: f64,
}

impl Model {
    /// Index of the node with this name, if any.
    pub fn node_index(&self, name: &str) -> Option<usize> {
        self.inertias.iter().position(|n| n.name == name)
    }

    /// The node that takes the mean torque: `[load] at`, or the last node.
    pub fn load_node(&self) -> Option<&str> {
        match self.load.as_ref().and_then(|l| l.at.as_deref()) {
            Some(at) => Some(at),
            None => self.inertias.last().map(|n| n.name.as_str()),
        }
    }

    /// True when some connection goes to `ground`.
    pub fn is_grounded(&self) -> bool {
        self.connections
            .iter()
            .any(|c| c.from == GROUND || c.to == GROUND)
    }

    /// Strokes of the engine, or 4 when there is none (orders in steps of 0.5).
    pub fn strokes(&self) -> u32 {
        self.engine.as_ref().map_or(4, |e| e.strokes)
    }

    /// Orders to draw and sum: `[operation] orders`, or every multiple of 0.5 (4-stroke)
    /// or 1 (2-stroke) up to 12.
    pub fn orders(&self) -> Vec<f64> {
        match &self.operation.orders {
            Some(orders) => orders.clone(),
            None => default_orders(self.strokes(), 12.0),
        }
    }
}

/// Every multiple of 0.5 (4-stroke) or 1 (2-stroke) from the first up to `max_order`.
pub fn default_orders(strokes: u32, max_order: f64) -> Vec<f64> {
    let step = if strokes == 2 { 1.0 } else { 0.5 };
    let count = (max_order / step).round() as usize;
    (1..=count).map(|k| k as f64 * step).collect()
}
