//! The driveline model as it stands in a model file (`spec/model-format.md`, format 1).
//!
//! These types hold what the user wrote, with names rather than indices, so that the GUI
//! can edit them and the writer can save them back unchanged. Everything here is plain
//! data; [`crate::physics::System`] resolves names, gear ratios and units for computing.
//! All quantities are SI unless the field name says otherwise.

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

/// A linear shaft: `T = k·Δθ + c·Δθ̇` in the shaft's own frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Shaft {
    /// Torsional stiffness, N·m/rad (> 0).
    pub stiffness_nm_per_rad: f64,
    /// Viscous damping, N·m·s/rad (≥ 0, default 0).
    pub damping_nm_s_per_rad: f64,
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
    /// α_f(f), f the vibration frequency in Hz (seed 000 eq. 9).
    pub frequency_poly: Option<Poly>,
    /// α_Tc(T), T in °C (seed 000 eq. 10).
    pub temperature_stiffness_poly: Option<Poly>,
    /// α_Tξ(T), T in °C (seed 000 eq. 11).
    pub temperature_damping_poly: Option<Poly>,
    /// Optional self-heating model (time domain).
    pub thermal: Option<Thermal>,
}

/// `kind = "gear"`: a gear stage.
#[derive(Debug, Clone, PartialEq)]
pub struct Gear {
    /// Speed of `to` divided by speed of `from` (≠ 0; negative reverses direction).
    pub ratio: f64,
    /// Mesh stiffness at the `to` side, N·m/rad; `None` is a rigid constraint.
    pub mesh_stiffness_nm_per_rad: Option<f64>,
    /// Total free play at the `to` side, degrees (default 0).
    pub backlash_deg: f64,
}

/// A cylinder pressure curve over one working cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct PressureCurve {
    /// Crank angle from that cylinder's firing TDC, degrees, strictly increasing.
    pub crank_angle_deg: Vec<f64>,
    /// Gauge pressure at each angle, bar.
    pub pressure_bar: Vec<f64>,
}

/// A pressure curve measured at one engine load.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadPressure {
    /// Engine load 0..1.
    pub load: f64,
    /// The curve at that load.
    pub curve: PressureCurve,
}

/// Where the cylinder pressure comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum Pressure {
    /// `pressure = {...}`: one curve for every load.
    Single(PressureCurve),
    /// `pressure_by_load = [...]`: curves by load, interpolated in load (sorted by load).
    ByLoad(Vec<LoadPressure>),
}

/// `[engine]`: reciprocating engine excitation (seed 001 eq. 3–5).
#[derive(Debug, Clone, PartialEq)]
pub struct Engine {
    /// One node (all cylinders act on it) or one node per cylinder (crank throws).
    pub at: Vec<String>,
    /// Number of cylinders (≥ 1).
    pub cylinders: u32,
    /// 2 or 4 (default 4).
    pub strokes: u32,
    /// Firing TDC of each cylinder after cylinder 1's, degrees; `None`: evenly spaced.
    pub firing_angles_deg: Option<Vec<f64>>,
    /// Bore `d`, m.
    pub bore_m: f64,
    /// Crank radius `r` (half the stroke), m.
    pub crank_radius_m: f64,
    /// Connecting rod length `l`, centre to centre, m.
    pub conrod_length_m: f64,
    /// `m_p + m_A` of seed 001 eq. 3–4, kg per cylinder (default 0).
    pub reciprocating_mass_kg: f64,
    /// `J0/l²` of seed 001 eq. 3–4, kg (default 0).
    pub rod_inertia_correction_kg: f64,
    /// Cylinder gauge pressure.
    pub pressure: Pressure,
}

impl Engine {
    /// Crank angle of one working cycle, degrees: 720 for 4-stroke, 360 for 2-stroke.
    pub fn cycle_deg(&self) -> f64 {
        if self.strokes == 2 { 360.0 } else { 720.0 }
    }

    /// Firing angles actually used: the given ones, or evenly spaced over the cycle in
    /// cylinder order (`i · cycle / cylinders`).
    pub fn firing_angles_or_even_deg(&self) -> Vec<f64> {
        match &self.firing_angles_deg {
            Some(angles) => angles.clone(),
            None => {
                let step = self.cycle_deg() / f64::from(self.cylinders);
                (0..self.cylinders).map(|i| f64::from(i) * step).collect()
            }
        }
    }

    /// The node each cylinder acts on (length `cylinders`).
    pub fn node_of_cylinder(&self, cylinder: usize) -> &str {
        if self.at.len() == 1 {
            &self.at[0]
        } else {
            &self.at[cylinder]
        }
    }
}

/// Amplitude of a prescribed harmonic.
#[derive(Debug, Clone, PartialEq)]
pub enum HarmonicAmplitude {
    /// A constant amplitude, N·m.
    Constant(f64),
    /// Amplitude varying with reference speed: linear interpolation, held at the ends.
    BySpeed {
        /// Reference speeds, rpm, strictly increasing.
        speed_rpm: Vec<f64>,
        /// Amplitudes at those speeds, N·m.
        amplitude_nm: Vec<f64>,
    },
}

/// `[[harmonic]]`: `T = amplitude · cos(order · θ* + phase)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Harmonic {
    /// Node it acts on.
    pub at: String,
    /// Multiple of the reference speed (> 0).
    pub order: f64,
    /// Zero-to-peak amplitude in the node's own shaft.
    pub amplitude: HarmonicAmplitude,
    /// Phase, degrees (default 0).
    pub phase_deg: f64,
}

/// `[load]`: what holds the mean speed.
#[derive(Debug, Clone, PartialEq)]
pub struct Load {
    /// Node that takes the mean torque; `None`: the last node.
    pub at: Option<String>,
    /// Extra damping on vibration of that node, N·m·s/rad (default 0).
    pub damping_nm_s_per_rad: f64,
}

/// `[operation]`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Operation {
    /// `[min, max]` for sweeps and Campbell diagrams, rpm of the reference node.
    pub speed_range_rpm: Option<[f64; 2]>,
    /// `[min, max]` band where resonances are not allowed, rpm.
    pub operating_range_rpm: Option<[f64; 2]>,
    /// Orders to draw and sum; `None`: all multiples of 0.5 up to 12 (4-stroke) or of 1
    /// up to 12 (2-stroke).
    pub orders: Option<Vec<f64>>,
}

/// `[expect]`: checks for `torsim check`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Expect {
    /// Mode k (from 1, rigid-body modes not counted) lies in `[min, max]` Hz.
    pub mode_hz: Vec<ModeExpectation>,
    /// The q-th order line crosses some mode in `[min, max]` rpm.
    pub critical_rpm: Vec<CriticalExpectation>,
    /// Orders that must cross no mode inside `operating_range_rpm`.
    pub no_resonance_in_operating_range: Vec<f64>,
}

impl Expect {
    /// True when the model has no checks at all.
    pub fn is_empty(&self) -> bool {
        self.mode_hz.is_empty()
            && self.critical_rpm.is_empty()
            && self.no_resonance_in_operating_range.is_empty()
    }
}

/// `{ mode = k, min = a, max = b }` in `[expect] mode_hz`.
#[derive(Debug, Clone, PartialEq)]
pub struct ModeExpectation {
    /// Mode number, from 1.
    pub mode: u32,
    /// Lower bound, Hz.
    pub min_hz: f64,
    /// Upper bound, Hz.
    pub max_hz: f64,
}

/// `{ order = q, min = a, max = b }` in `[expect] critical_rpm`.
#[derive(Debug, Clone, PartialEq)]
pub struct CriticalExpectation {
    /// Engine order.
    pub order: f64,
    /// Lower bound, rpm.
    pub min_rpm: f64,
    /// Upper bound, rpm.
    pub max_rpm: f64,
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
