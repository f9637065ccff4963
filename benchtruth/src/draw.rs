//! Draws a case from a seed: the truth driveline (3–12 DOF, chain or tree, with or
//! without a gear, one or two rubber stages), its damping, the effect and its form and
//! size, the user's nominal model and the campaign (issue 14, item 3).

use crate::campaign::{self, Campaign, Needs};
use crate::driveline::{Connection, Driveline, Engine, Kind, Node, PressureCurve};
use crate::effects::*;
use crate::engine::{EngineLaw, Kinematics, pressure_curve};
use crate::rng::Rng;
use std::f64::consts::TAU;

/// A drawn case: everything the writer and the simulator need.
#[derive(Debug, Clone)]
pub struct Case {
    pub seed: u64,
    pub class: String,
    pub form: String,
    pub truth: Driveline,
    pub user: Driveline,
    pub effect: Effect,
    /// Effect parameters for `truth.toml`.
    pub params: Vec<(String, f64)>,
    /// Place: the report key and the values counted right (e.g. `connection`, [names]).
    pub place: Option<(String, Vec<String>)>,
    /// Plain parameter errors: (parameter, user / truth).
    pub errors: Vec<(String, f64)>,
    pub campaign: Campaign,
    /// First-mode damping ratio drawn.
    pub zeta1: f64,
    pub modes_hz: Vec<f64>,
    /// Which draw of the seed this is: 0, or the redraw after earlier draws whose truth no
    /// bench could run ([`crate::redraw::write_case`]). Each draw has its own random streams
    /// ([`stream`]), so draw 0 of a seed is the same case whatever the redraw rule.
    pub attempt: u64,
}

/// The random stream `base` of draw `attempt` of a seed: draw 0 keeps the streams every
/// earlier build used (1 the driveline and effect, 2 the campaign, 100 + i recording
/// i's noise), a redraw moves all of them by 2²⁰ per attempt.
pub fn stream(base: u64, attempt: u64) -> u64 {
    base + (attempt << 20)
}

/// The class drawn for a seed when none is forced: `seed mod 11`.
pub fn class_of(seed: u64) -> &'static str {
    CLASSES[(seed % CLASSES.len() as u64) as usize]
}

fn engine(rng: &mut Rng, six: bool, node: usize) -> (Engine, f64, f64) {
    let (bore, r, m, peak, eps) = if six {
        (
            rng.range(0.11, 0.13),
            rng.range(0.06, 0.07),
            rng.range(2.0, 3.5),
            rng.range(70.0, 100.0),
            16.0,
        )
    } else {
        (
            rng.range(0.078, 0.09),
            rng.range(0.04, 0.046),
            rng.range(0.45, 0.7),
            rng.range(40.0, 60.0),
            10.0,
        )
    };
    let lambda = rng.range(0.27, 0.32);
    let mut pressure = Vec::new();
    for (load, k) in [(0.3, 0.3), (0.6, 0.62), (1.0, 1.0)] {
        let (angle_deg, bar) =
            pressure_curve(eps, peak * k, rng.range(10.0, 16.0), -0.6 * (1.0 - k));
        pressure.push(PressureCurve {
            load,
            angle_deg,
            bar,
        });
    }
    let firing_deg = if six {
        vec![0.0, 480.0, 240.0, 600.0, 120.0, 360.0]
    } else {
        vec![0.0, 540.0, 180.0, 360.0]
    };
    let (lo, hi) = if six {
        (
            rng.range(700.0, 1000.0).round(),
            rng.range(2000.0, 2800.0).round(),
        )
    } else {
        (
            rng.range(1000.0, 1600.0).round(),
            rng.range(3800.0, 6000.0).round(),
        )
    };
    let e = Engine {
        node,
        firing_deg,
        bore_m: bore,
        crank_radius_m: r,
        conrod_m: r / lambda,
        reciprocating_kg: m,
        pressure,
    };
    (e, lo, hi)
}

/// The topology: nodes, connections; returns the truth driveline before damping.
fn topology(rng: &mut Rng, n: usize, six: bool, gear: bool) -> (Driveline, f64, f64) {
    let j_crank = if six {
        rng.range(0.8, 2.0)
    } else {
        rng.range(0.15, 0.4)
    };
    let (eng, lo, hi) = engine(rng, six, 0);
    let mut nodes = vec![Node {
        name: "crank".into(),
        inertia_kg_m2: j_crank,
        damping_nm_s: rng.range(0.05, 0.5),
    }];
    // Main line length: the rest hang as branches.
    let branches = if n >= 5 && rng.chance(0.5) {
        rng.int(1, (n - 3).min(3))
    } else {
        0
    };
    let main = n - branches;
    let gear_at = if gear {
        rng.int(0, main - 2)
    } else {
        usize::MAX
    };
    let ratio = if gear {
        (rng.range(0.3, 3.5) * 100.0).round() / 100.0
    } else {
        1.0
    };
    let rubbers = if main >= 4 && rng.chance(0.4) { 2 } else { 1 };
    let mut rubber_at: Vec<usize> = Vec::new();
    while rubber_at.len() < rubbers {
        let k = rng.int(0, main - 2);
        if k != gear_at && !rubber_at.contains(&k) {
            rubber_at.push(k);
        }
    }
    let mut conns = Vec::new();
    for i in 1..main {
        let last = i == main - 1;
        let name = if last {
            "brake".to_string()
        } else {
            format!("mass{i}")
        };
        let scale = if last {
            rng.range(1.0, 5.0)
        } else {
            rng.log_range(0.03, 0.8)
        };
        nodes.push(Node {
            name,
            inertia_kg_m2: j_crank * scale,
            damping_nm_s: 0.0,
        });
        let k = i - 1;
        let kind = if k == gear_at {
            Kind::Gear {
                ratio,
                mesh_stiffness: rng.log_range(3e5, 2e6),
                mesh_damping: 0.0,
            }
        } else if rubber_at.contains(&k) {
            Kind::Rubber {
                stiffness: rng.log_range(5e3, 4e4),
                psi: 1.0,
            }
        } else {
            Kind::Shaft {
                stiffness: rng.log_range(5e4, 5e5),
                damping: 0.0,
            }
        };
        let cname = match kind {
            Kind::Gear { .. } => "gearbox".to_string(),
            Kind::Rubber { .. } => format!(
                "coupling{}",
                rubber_at.iter().position(|&r| r == k).unwrap_or(0) + 1
            ),
            Kind::Shaft { .. } => format!("shaft{i}"),
        };
        conns.push(Connection {
            name: cname,
            from: k,
            to: i,
            kind,
        });
    }
    for b in 0..branches {
        let host = rng.int(0, main - 2);
        let idx = nodes.len();
        nodes.push(Node {
            name: format!("aux{}", b + 1),
            inertia_kg_m2: j_crank * rng.log_range(0.05, 0.5),
            damping_nm_s: 0.0,
        });
        conns.push(Connection {
            name: format!("aux_shaft{}", b + 1),
            from: host,
            to: idx,
            kind: Kind::Shaft {
                stiffness: rng.log_range(2e4, 2e5),
                damping: 0.0,
            },
        });
    }
    let load_node = main - 1;
    let d = Driveline {
        name: String::new(),
        nodes,
        connections: conns,
        engine: eng,
        load_node,
        load_damping_nm_s: rng.range(2.0, 20.0),
    };
    (d, lo, hi)
}

/// Scales stiffness so mode 1 sits at `f1`, then the damping so mode 1 has `zeta`.
fn tune(d: &mut Driveline, f1: f64, zeta: f64) {
    let m = d.modes();
    let s = (f1 / m.freq_hz[0]).powi(2);
    for c in &mut d.connections {
        match &mut c.kind {
            Kind::Shaft { stiffness, .. } | Kind::Rubber { stiffness, .. } => *stiffness *= s,
            Kind::Gear { mesh_stiffness, .. } => *mesh_stiffness *= s,
        }
    }
    // Shafts and meshes: stiffness-proportional damping, 1 % at mode 1 before scaling.
    let w1 = TAU * f1;
    for c in &mut d.connections {
        match &mut c.kind {
            Kind::Shaft { stiffness, damping } => *damping = 0.02 * *stiffness / w1,
            Kind::Gear {
                mesh_stiffness,
                mesh_damping,
                ..
            } => *mesh_damping = 0.02 * *mesh_stiffness / w1,
            Kind::Rubber { .. } => {}
        }
    }
    let m = d.modes();
    let z = d.modal_damping(&m, 0);
    let g = zeta / z;
    for c in &mut d.connections {
        match &mut c.kind {
            Kind::Shaft { damping, .. } => *damping *= g,
            Kind::Gear { mesh_damping, .. } => *mesh_damping *= g,
            Kind::Rubber { psi, .. } => *psi *= g,
        }
    }
    for n in &mut d.nodes {
        n.damping_nm_s *= g;
    }
    d.load_damping_nm_s *= g;
}

fn rubbers(d: &Driveline) -> Vec<usize> {
    (0..d.connections.len())
        .filter(|&i| matches!(d.connections[i].kind, Kind::Rubber { .. }))
        .collect()
}

/// Mean torque through connection `c` at full load (N·m, in its `to` shaft).
pub fn through_torque(d: &Driveline, c: usize) -> f64 {
    let t = EngineLaw::new(&d.engine, 1.0, Kinematics::FirstOrder).mean_torque();
    t / d.speed_ratios()[d.connections[c].to]
}

/// Draws the case of `seed`; `class` forces the effect class.
pub fn draw_case(seed: u64, class: Option<&str>) -> Result<Case, String> {
    draw_attempt(seed, class, 0)
}

/// Draw `attempt` of a seed ([`Case::attempt`]); [`draw_case`] is draw 0.
pub fn draw_attempt(seed: u64, class: Option<&str>, attempt: u64) -> Result<Case, String> {
    let class = class.unwrap_or(class_of(seed)).to_string();
    if !CLASSES.contains(&class.as_str()) {
        return Err(format!(
            "unknown class `{class}`; one of {}",
            CLASSES.join(", ")
        ));
    }
    let mut rng = Rng::new(seed, stream(1, attempt));
    let six = class == "cylinder_imbalance" || rng.chance(0.5);
    let gear = class == "gear_backlash" || rng.chance(0.4);
    let extra = (class == "unmodelled_mode") as usize;
    let (mut truth, lo, hi, zeta1) = loop {
        let n = rng.int(3, 12 - extra);
        let (mut d, lo, hi) = topology(&mut rng, n, six, gear);
        let cyl = d.engine.firing_deg.len() as f64;
        let q = rng.pick(&[cyl / 2.0, cyl / 2.0, 1.0, 0.5 * cyl + 1.0]);
        let f1 = q * rng.range(lo * 1.05, lo + 0.6 * (hi - lo)) / 60.0;
        let zeta = rng.log_range(0.005, 0.10);
        tune(&mut d, f1, zeta);
        let m = d.modes();
        if m.freq_hz.iter().all(|f| f.is_finite()) && m.freq_hz.last().is_some_and(|&f| f < 1500.0)
        {
            break (d, lo, hi, zeta);
        }
    };
    truth.name = format!("benchtruth case {seed}");
    let mut user = truth.clone();
    let mut errors = Vec::new();
    let mut params: Vec<(String, f64)> = Vec::new();
    let mut place = None;
    let mut effect = Effect::None;
    let mut form = "none".to_string();
    let rub = rubbers(&truth);
    let pick_rubber = |rng: &mut Rng| rub[rng.int(0, rub.len() - 1)];
    let modes = truth.modes();
    let f1 = modes.freq_hz[0];
    match class.as_str() {
        "parameter_error" => form = "plain".into(),
        "coupling_amplitude_nonlinearity" => {
            let c = pick_rubber(&mut rng);
            let ts = through_torque(&truth, c) / truth.connections[c].stiffness();
            let g = rng.range(0.15, 0.4);
            let law = if rng.chance(0.5) {
                let p = rng.pick(&[1.0, 2.0, 3.0]);
                form = format!("power_p{p}");
                AmplitudeLaw::Power {
                    a: g / ts.abs().powf(p),
                    p,
                }
            } else {
                form = "tanh".into();
                let theta_s = ts.abs() * rng.range(0.8, 1.5);
                AmplitudeLaw::Tanh {
                    a: g / (ts / theta_s).powi(2).tanh(),
                    theta_s,
                }
            };
            params.push(("stiffening_at_full_load".into(), g));
            effect = Effect::AmplitudeNonlinearity { conn: c, law };
            place = Some(("connection".into(), vec![truth.connections[c].name.clone()]));
        }
        "coupling_frequency_dependence" => {
            let c = pick_rubber(&mut rng);
            let law = if rng.chance(0.5) {
                form = "power_law".into();
                let n = rng.range(0.08, 0.15);
                params.push(("exponent".into(), n));
                FrequencyLaw::PowerLaw { n, f0_hz: f1 }
            } else {
                form = "fractional_zener".into();
                let delta = rng.range(0.3, 0.8);
                params.push(("delta".into(), delta));
                FrequencyLaw::FractionalZener {
                    delta,
                    alpha: rng.range(0.3, 0.6),
                    f_relax_hz: f1 * rng.range(1.0, 4.0),
                    f0_hz: f1,
                }
            };
            effect = Effect::FrequencyDependence { conn: c, law };
            place = Some(("connection".into(), vec![truth.connections[c].name.clone()]));
        }
        "coupling_thermal_drift" => {
            let c = pick_rubber(&mut rng);
            let softening = if rng.chance(0.5) {
                form = "exponential".into();
                Softening::Exponential {
                    beta_per_k: rng.range(0.005, 0.012),
                }
            } else {
                form = "linear".into();
                Softening::Linear {
                    beta_per_k: rng.range(0.004, 0.01),
                }
            };
            // Sized after the campaign is drawn (needs the loss power).
            effect = Effect::ThermalDrift {
                conn: c,
                law: Thermal {
                    capacity_j_per_k: 1.0,
                    conductance_w_per_k: 0.0,
                    softening,
                },
            };
            place = Some(("connection".into(), vec![truth.connections[c].name.clone()]));
        }
        "hysteretic_damping" => {
            let c = pick_rubber(&mut rng);
            let (k, psi) = match truth.connections[c].kind {
                Kind::Rubber { stiffness, psi } => (stiffness, psi),
                _ => (1.0, 1.0),
            };
            // The user's model: seed 001 eq. 2, c = k·γ/(2π·ω) at the first mode.
            user.connections[c].kind = Kind::user_dashpot(k, psi, f1);
            let law = if rng.chance(0.5) {
                form = "structural".into();
                HystereticLaw::Structural
            } else {
                form = "dahl".into();
                HystereticLaw::Dahl {
                    f_c_nm: 0.0,
                    sigma_nm_per_rad: 3.0 * k,
                    twist_rate_rad_s: 0.0,
                }
            };
            effect = Effect::Hysteretic { conn: c, law };
            place = Some(("connection".into(), vec![truth.connections[c].name.clone()]));
        }
        "unmodelled_mode" => {
            let host = rng.int(0, truth.nodes.len() - 1);
            let jh = truth.nodes[host].inertia_kg_m2;
            let jx = jh * rng.range(0.05, 0.3);
            let f_hi = (8.0 * hi / 60.0 * 0.7).min(600.0);
            let fx = rng.log_range((1.2 * f1).min(f_hi * 0.8), f_hi);
            let kx = jx * (TAU * fx).powi(2);
            let zx = rng.range(0.01, 0.04);
            let name = format!("{}_local", truth.nodes[host].name);
            truth.nodes.push(Node {
                name: name.clone(),
                inertia_kg_m2: jx,
                damping_nm_s: 0.0,
            });
            let idx = truth.nodes.len() - 1;
            let damping = 2.0 * zx * jx * TAU * fx;
            form = if rng.chance(0.5) {
                "branch_viscous".into()
            } else {
                "branch_rubber".into()
            };
            let kind = if form == "branch_viscous" {
                Kind::Shaft {
                    stiffness: kx,
                    damping,
                }
            } else {
                Kind::Rubber {
                    stiffness: kx,
                    psi: 2.0 * zx * TAU,
                }
            };
            truth.connections.push(Connection {
                name: format!("{name}_spring"),
                from: host,
                to: idx,
                kind,
            });
            user.nodes[host].inertia_kg_m2 += jx;
            params.push(("inertia_kg_m2".into(), jx));
            params.push(("frequency_hz".into(), fx));
            effect = Effect::UnmodelledMode { host };
            let near: Vec<String> = truth
                .connections
                .iter()
                .filter(|c| c.from == host || c.to == host)
                .map(|c| c.name.clone())
                .chain(std::iter::once(truth.nodes[host].name.clone()))
                .collect();
            place = Some(("connection".into(), near));
        }
        "crank_variable_inertia" => {
            let exact = rng.chance(0.5);
            form = if exact {
                "exact_slider_crank".into()
            } else {
                "first_order_lambda".into()
            };
            let e = &truth.engine;
            let lam = e.crank_radius_m / e.conrod_m;
            let mean = e.firing_deg.len() as f64
                * e.reciprocating_kg
                * e.crank_radius_m.powi(2)
                * (0.5 + lam * lam / 8.0);
            user.engine.reciprocating_kg = 0.0;
            user.nodes[e.node].inertia_kg_m2 += mean;
            params.push(("reciprocating_mass_kg".into(), e.reciprocating_kg));
            effect = Effect::CrankVariableInertia { exact };
        }
        "gear_backlash" => {
            let c = (0..truth.connections.len())
                .find(|&i| matches!(truth.connections[i].kind, Kind::Gear { .. }))
                .unwrap_or(0);
            let b_deg = rng.range(0.05, 0.3);
            let h = b_deg.to_radians() / 2.0;
            let eps = h * rng.range(0.1, 0.3);
            let law = if rng.chance(0.5) {
                form = "softened_dead_zone".into();
                BacklashLaw::Softened {
                    half_rad: h,
                    eps_rad: eps,
                }
            } else {
                form = "hertzian".into();
                let s_ref = (through_torque(&truth, c) / truth.connections[c].stiffness())
                    .abs()
                    .max(h);
                BacklashLaw::Hertzian {
                    half_rad: h,
                    eps_rad: eps,
                    s_ref_rad: s_ref,
                }
            };
            params.push(("backlash_deg".into(), b_deg));
            effect = Effect::GearBacklash { conn: c, law };
            place = Some(("connection".into(), vec![truth.connections[c].name.clone()]));
        }
        "cylinder_imbalance" => {
            let cyl = rng.int(0, truth.engine.firing_deg.len() - 1);
            let law = match rng.int(0, 2) {
                0 => {
                    form = "pressure_scale".into();
                    CylinderLaw::Scale {
                        scale: 1.0 + rng.sign() * rng.range(0.05, 0.15),
                    }
                }
                1 => {
                    form = "misfire".into();
                    CylinderLaw::Misfire {
                        residual: rng.range(0.0, 0.2),
                    }
                }
                _ => {
                    form = "late_combustion".into();
                    CylinderLaw::Late {
                        delay_deg: rng.range(4.0, 10.0),
                        scale: rng.range(0.85, 1.0),
                    }
                }
            };
            params.push(("cylinder".into(), (cyl + 1) as f64));
            effect = Effect::CylinderImbalance { cylinder: cyl, law };
            place = Some(("cylinder".into(), vec![(cyl + 1).to_string()]));
        }
        _ => {}
    }
    // Plain parameter errors of the user's model.
    let n_user = user.nodes.len();
    let n_conn = user.connections.len();
    if class == "parameter_error" {
        for _ in 0..rng.int(1, 2) {
            let f = 1.0 + rng.sign() * rng.range(0.05, 0.15);
            perturb(&mut user, &mut rng, n_user, n_conn, f, &mut errors);
        }
    } else if class != "none" {
        for i in 0..n_user {
            let f = 1.0 + rng.range(-0.03, 0.03);
            user.nodes[i].inertia_kg_m2 *= f;
            errors.push((format!("inertia.{}", user.nodes[i].name), f));
        }
        for c in 0..n_conn {
            let f = 1.0 + rng.range(-0.03, 0.03);
            scale_stiffness(&mut user.connections[c].kind, f);
            errors.push((
                format!("connection.{}.stiffness", user.connections[c].name),
                f,
            ));
        }
    }
    // Unmodelled mode: the user's model has no local node or spring.
    if class == "unmodelled_mode" {
        user.connections.truncate(truth.connections.len() - 1);
    }
    let needs = Needs {
        speed_lo_rpm: lo,
        speed_hi_rpm: hi,
        long_run: class == "coupling_thermal_drift",
        part_load: class == "coupling_amplitude_nonlinearity" || class == "gear_backlash",
        nodes: (0..n_user).collect(),
        crank: truth.engine.node,
    };
    let mut crng = Rng::new(seed, stream(2, attempt));
    let campaign = campaign::draw(&mut crng, &needs);
    if class == "sensor_artifact" {
        let s = rng.int(0, campaign.stations.len() - 1);
        let st = &campaign.stations[s];
        let angle_rad = rng.range(0.0, TAU);
        let law = if st.kind == "zebra" && rng.chance(0.6) {
            form = "tape_joint".into();
            SensorLaw::TapeJoint {
                fraction: rng.sign() * rng.range(0.03, 0.1),
                lines: st.lines,
                angle_rad,
            }
        } else if rng.chance(0.5) {
            form = "eccentricity".into();
            SensorLaw::Eccentricity {
                e_rad: rng.range(5e-4, 2e-3),
                phase_rad: angle_rad,
            }
        } else {
            form = "missing_tooth".into();
            SensorLaw::MissingTooth {
                fraction: rng.range(0.1, 0.3),
                lines: st.lines,
                angle_rad,
            }
        };
        effect = Effect::SensorArtifact { station: s, law };
        place = Some(("station".into(), vec![truth.nodes[st.node].name.clone()]));
    }
    user.name = format!(
        "Bench {seed}: {} nodes, {} connections",
        user.nodes.len(),
        user.connections.len()
    );
    let mut case = Case {
        seed,
        class,
        form,
        truth,
        user,
        effect,
        params,
        place,
        errors,
        campaign,
        zeta1,
        modes_hz: modes.freq_hz.clone(),
        attempt,
    };
    crate::sizing::size_effect(&mut case, &mut rng);
    Ok(case)
}

fn scale_stiffness(k: &mut Kind, f: f64) {
    match k {
        Kind::Shaft { stiffness, .. } | Kind::Rubber { stiffness, .. } => *stiffness *= f,
        Kind::Gear { mesh_stiffness, .. } => *mesh_stiffness *= f,
    }
}

fn perturb(
    user: &mut Driveline,
    rng: &mut Rng,
    n: usize,
    nc: usize,
    f: f64,
    errors: &mut Vec<(String, f64)>,
) {
    if rng.chance(0.5) {
        let i = rng.int(0, n - 1);
        user.nodes[i].inertia_kg_m2 *= f;
        errors.push((format!("inertia.{}", user.nodes[i].name), f));
    } else {
        let c = rng.int(0, nc - 1);
        scale_stiffness(&mut user.connections[c].kind, f);
        errors.push((
            format!("connection.{}.stiffness", user.connections[c].name),
            f,
        ));
    }
}
