//! Strategies shared by the property tests (issue 13, deliverable 5): valid models built
//! by construction (a chain of 2–8 inertias joined by shafts, rubber stages and gears,
//! an engine and/or harmonics) and uniform recordings around a positive mean speed.
//!
//! Values are drawn over wide but valid ranges: every model here passes
//! `torsim::model::validate`, every recording `torsim::recording::check_recording`.

#![allow(dead_code)] // each test file uses part of it

use proptest::prelude::*;
use std::f64::consts::TAU;
use torsim::model::{
    Connection, ConnectionKind, CouplingRating, Engine, Gear, Harmonic, HarmonicAmplitude, Inertia,
    Load, LoadPressure, ModalDamping, Model, Operation, Poly, Pressure, PressureCurve, Regime,
    RubberElements, RubberStage, RubberStiffness, Shaft, Thermal,
};
use torsim::recording::{Channel, ChannelKind, Recording, RecordingMeta, RunKind};

/// A positive, finite number over many decades: mantissa 1..10 times 10^`lo`..10^`hi`.
pub fn positive(lo: i32, hi: i32) -> impl Strategy<Value = f64> {
    (1.0..10.0_f64, lo..=hi).prop_map(|(m, e)| m * 10f64.powi(e))
}

/// A name every output format carries: a lowercase letter, then letters, digits and `_`.
fn word() -> impl Strategy<Value = String> {
    "[a-z][a-z0-9_]{0,7}"
}

/// Free text (model name, description, labels): any printable characters, with quotes,
/// backslashes and line breaks.
fn text() -> impl Strategy<Value = String> {
    prop_oneof![
        "[ -~]{0,24}",
        "\\PC{0,12}",
        Just("quote \" backslash \\ tab\t\nline two ü 発".to_string()),
    ]
}

fn poly(non_negative_a2: bool) -> impl Strategy<Value = Poly> {
    let a2 = if non_negative_a2 {
        (0.0..1e-3_f64).boxed()
    } else {
        (-1e-3..1e-3_f64).boxed()
    };
    (
        a2,
        0.5..2.0_f64,
        prop::option::of((-50.0..50.0_f64, 1.0..200.0_f64)),
    )
        .prop_map(|(a2, a0, range)| Poly {
            // a2·x² + a0 with a2 ≥ 0 and a0 > 0 is positive everywhere, as the
            // temperature laws must be (validate.rs).
            coeffs: [a2, 0.0, a0],
            range: range.map(|(lo, width)| [lo, lo + width]),
        })
}

fn rubber() -> impl Strategy<Value = RubberStage> {
    let elements = (2_u32..24, 1.0..1e3_f64, positive(5, 8), 0.05..1.0_f64).prop_map(
        |(count, side, radial, pitch)| {
            RubberStiffness::Elements(RubberElements {
                count,
                per_side: 1 + (side as u32) % (count - 1),
                pitch_diameter_m: pitch,
                radial_stiffness_n_per_m: radial,
            })
        },
    );
    let stiffness = prop_oneof![positive(2, 7).prop_map(RubberStiffness::Direct), elements];
    let thermal =
        (positive(1, 5), positive(-1, 3), -20.0..60.0_f64).prop_map(|(c, g, a)| Thermal {
            capacity_j_per_k: c,
            conductance_w_per_k: g,
            ambient_c: a,
        });
    (
        stiffness,
        0.1..2.0_f64,
        -20.0..120.0_f64,
        prop::option::of(poly(true)),
        prop::option::of(poly(true)),
        prop::option::of(poly(true)),
        prop::option::of(poly(true)),
        prop::option::of(thermal),
        prop::option::of(rating()),
    )
        .prop_map(
            |(stiffness, psi, temp, amp, freq, ts, td, thermal, rating)| {
                let elements = matches!(stiffness, RubberStiffness::Elements(_));
                RubberStage {
                    stiffness,
                    psi,
                    temperature_c: temp,
                    amplitude_poly: amp.filter(|_| elements),
                    amplitude_saturation: None,
                    amplitude_form: Default::default(),
                    frequency_poly: freq,
                    frequency_power_law: None,
                    frequency_zener: None,
                    temperature_stiffness_poly: ts,
                    temperature_damping_poly: td,
                    thermal,
                    rating,
                }
            },
        )
}

/// A coupling rating with every optional value present or not (issue 16).
fn rating() -> impl Strategy<Value = CouplingRating> {
    (
        positive(1, 4),
        prop::option::of(1.0..4.0f64),
        prop::option::of(positive(0, 3)),
        prop::option::of(positive(0, 3)),
        prop::option::of(-20.0..70.0f64),
    )
        .prop_map(
            |(rated, max_factor, vibratory, loss, ambient)| CouplingRating {
                rated_torque_nm: rated,
                max_torque_nm: max_factor.map(|f| f * rated),
                permissible_vibratory_torque_nm: vibratory,
                permissible_power_loss_w: loss,
                ambient_c: ambient.unwrap_or(30.0),
                permissible_temperature_c: 80.0,
            },
        )
}

fn connection_kind() -> impl Strategy<Value = ConnectionKind> {
    // Some shafts carry their own distributed inertia, some with their segments given.
    let shaft = (
        positive(2, 8),
        prop::option::of(positive(-3, 2)),
        prop::option::weighted(0.3, positive(-3, 1)),
        prop::option::of(1u32..40),
    )
        .prop_map(|(k, c, inertia, segments)| {
            ConnectionKind::Shaft(Shaft {
                inertia_kg_m2: inertia.unwrap_or(0.0),
                segments: inertia.and(segments),
                ..Shaft::massless(k, c.unwrap_or(0.0))
            })
        });
    let gear = (
        positive(-1, 0),
        any::<bool>(),
        prop::option::of(positive(4, 8)),
        prop::option::of(0.0..1.0_f64),
    )
        .prop_map(|(ratio, reverse, mesh, backlash)| {
            ConnectionKind::Gear(Gear {
                ratio: if reverse { -ratio } else { ratio },
                mesh_stiffness_nm_per_rad: mesh,
                // a loss factor of 1e-3 at 10 Hz where there is a mesh to damp
                mesh_damping_nm_s_per_rad: mesh.map_or(0.0, |k| 1e-3 * k / (TAU * 10.0)),
                backlash_deg: backlash.unwrap_or(0.0),
                // a softened contact over a fifth of the half play, to cover its key
                backlash_softening_deg: backlash.map_or(0.0, |b| 0.1 * b),
                contact_exponent: 1.0,
                contact_reference_deg: 0.0,
            })
        });
    prop_oneof![shaft, rubber().prop_map(ConnectionKind::Rubber), gear]
}

/// A pressure curve over less than one cycle (`cycle_deg`), 2–12 points.
fn pressure_curve(cycle_deg: f64) -> impl Strategy<Value = PressureCurve> {
    prop::collection::vec(0.0..80.0_f64, 2..12).prop_map(move |bar| {
        let step = (cycle_deg - 1.0) / (bar.len() - 1) as f64;
        PressureCurve {
            crank_angle_deg: (0..bar.len())
                .map(|i| -cycle_deg / 2.0 + i as f64 * step)
                .collect(),
            pressure_bar: bar,
        }
    })
}

fn engine(nodes: usize) -> impl Strategy<Value = (Engine, Vec<usize>)> {
    (1_u32..=8, prop_oneof![Just(2_u32), Just(4_u32)]).prop_flat_map(move |(n, strokes)| {
        let cycle = if strokes == 2 { 360.0 } else { 720.0 };
        let count = n as usize;
        let pressure = prop_oneof![
            pressure_curve(cycle).prop_map(Pressure::Single),
            prop::collection::vec(pressure_curve(cycle), 1..4).prop_map(|curves| {
                let k = curves.len();
                Pressure::ByLoad(
                    curves
                        .into_iter()
                        .enumerate()
                        .map(|(i, curve)| LoadPressure {
                            load: (i + 1) as f64 / k as f64,
                            curve,
                        })
                        .collect(),
                )
            }),
        ];
        (
            prop::option::of(prop::collection::vec(-720.0..720.0_f64, count)),
            0.05..0.2_f64,
            0.02..0.1_f64,
            1.5..4.0_f64,
            0.0..2.0_f64,
            prop::option::of(0.0..0.5_f64),
            pressure,
            prop::option::of(prop::collection::vec(0.8..1.2_f64, count)),
            prop_oneof![
                (0..nodes).prop_map(|i| vec![i]),
                prop::collection::vec(0..nodes, count)
            ],
        )
            .prop_map(
                move |(angles, bore, radius, rod_factor, mass, rod, pressure, scale, at)| {
                    let engine = Engine {
                        at: Vec::new(), // names filled in by `model()`
                        cylinders: n,
                        strokes,
                        firing_angles_deg: angles,
                        bore_m: bore,
                        crank_radius_m: radius,
                        conrod_length_m: radius * rod_factor,
                        reciprocating_mass_kg: mass,
                        rod_inertia_correction_kg: rod.unwrap_or(0.0),
                        pressure,
                        pressure_scale: scale,
                    };
                    (engine, at)
                },
            )
    })
}

fn harmonic() -> impl Strategy<Value = (usize, Harmonic)> {
    let amplitude = prop_oneof![
        positive(-1, 4).prop_map(HarmonicAmplitude::Constant),
        prop::collection::vec((1.0..500.0_f64, positive(-1, 3)), 1..6).prop_map(|points| {
            let mut rpm = 0.0;
            let (speed_rpm, amplitude_nm) = points
                .into_iter()
                .map(|(step, a)| {
                    rpm += step;
                    (rpm, a)
                })
                .unzip();
            HarmonicAmplitude::BySpeed {
                speed_rpm,
                amplitude_nm,
            }
        }),
    ];
    (any::<usize>(), 1_u32..48, amplitude, -360.0..360.0_f64).prop_map(
        |(at, half_orders, amplitude, phase)| {
            let harmonic = Harmonic {
                at: String::new(), // filled in by `model()`
                order: f64::from(half_orders) / 2.0,
                amplitude,
                phase_deg: phase,
            };
            (at, harmonic)
        },
    )
}

fn operation() -> impl Strategy<Value = Operation> {
    let range = (0.0..3000.0_f64, 10.0..6000.0_f64).prop_map(|(lo, w)| [lo, lo + w]);
    let regime = ("[A-Z][a-z0-9 ]{0,6}", positive(2, 3), 0.0..=1.0_f64).prop_map(
        |(label, speed_rpm, load)| Regime {
            label,
            speed_rpm,
            load,
        },
    );
    (
        prop::option::of(range.clone()),
        prop::option::of(range),
        prop::option::of(prop::collection::vec(1_u32..48, 1..6)),
        prop::collection::vec(regime, 0..4),
    )
        .prop_map(|(speed, operating, orders, regimes)| Operation {
            speed_range_rpm: speed,
            operating_range_rpm: operating,
            orders: orders.map(|o| o.into_iter().map(|h| f64::from(h) / 2.0).collect()),
            regimes,
        })
}

/// A valid model: 2–8 inertias in a chain, each pair joined by a shaft, rubber stage or
/// gear, optionally the last node to `ground` by a shaft or rubber stage; an engine,
/// harmonics or both; `[load]`, `[modal_damping]` and `[operation]` sometimes.
pub fn model() -> impl Strategy<Value = Model> {
    (2_usize..=8).prop_flat_map(|n| {
        (
            text(),
            text(),
            prop::collection::vec(
                (word(), positive(-3, 2), prop::option::of(positive(-2, 1))),
                n,
            ),
            prop::collection::vec((prop::option::of(word()), connection_kind()), n - 1),
            prop::option::of((positive(2, 7), 0.1..2.0_f64)),
            prop::option::of(engine(n)),
            prop::collection::vec(harmonic(), 0..3),
            prop::option::of((prop::option::of(0..n), prop::option::of(positive(-1, 2)))),
            operation(),
            prop::option::of(prop_oneof![
                (0.0..0.99_f64).prop_map(ModalDamping::All),
                prop::collection::vec(0.0..0.99_f64, 1..4).prop_map(ModalDamping::PerMode),
            ]),
        )
            .prop_map(assemble)
    })
}

type Parts = (
    String,
    String,
    Vec<(String, f64, Option<f64>)>,
    Vec<(Option<String>, ConnectionKind)>,
    Option<(f64, f64)>,
    Option<(Engine, Vec<usize>)>,
    Vec<(usize, Harmonic)>,
    Option<(Option<usize>, Option<f64>)>,
    Operation,
    Option<ModalDamping>,
);

fn assemble(parts: Parts) -> Model {
    let (
        name,
        description,
        nodes,
        links,
        ground,
        engine,
        harmonics,
        load,
        operation,
        modal_damping,
    ) = parts;
    // Names are made unique by their index; connection names likewise.
    let inertias: Vec<Inertia> = nodes
        .into_iter()
        .enumerate()
        .map(|(i, (word, j, c))| Inertia {
            name: format!("{word}_{i}"),
            inertia_kg_m2: j,
            damping_nm_s_per_rad: c.unwrap_or(0.0),
        })
        .collect();
    let node = |i: usize| inertias[i % inertias.len()].name.clone();
    // Referred to one shaft, a gear train multiplies inertias by the square of its
    // ratio product. Each gear is turned the way that walks the running product back
    // towards 1, which keeps it within 0.1…10: referred inertias then stay within
    // 1e6 (the inertia range) × 1e2² = 1e10 < 1e12 of each other, inside the
    // round-off bound validate_scale.rs enforces.
    let mut decades = 0.0_f64;
    let links: Vec<_> = links
        .into_iter()
        .map(|(word, mut kind)| {
            if let ConnectionKind::Gear(gear) = &mut kind {
                let step = gear.ratio.abs().log10();
                if (decades + step).abs() > (decades - step).abs() {
                    gear.ratio = 1.0 / gear.ratio;
                }
                decades += gear.ratio.abs().log10();
            }
            (word, kind)
        })
        .collect();
    let mut connections: Vec<Connection> = links
        .into_iter()
        .enumerate()
        .map(|(i, (word, kind))| {
            let (from, to) = (node(i), node(i + 1));
            Connection {
                name: word.map_or_else(
                    || Connection::default_name(&from, &to),
                    |w| format!("{w}_c{i}"),
                ),
                from,
                to,
                kind,
            }
        })
        .collect();
    if let Some((k, psi)) = ground {
        connections.push(Connection {
            name: "to_ground".into(),
            from: node(inertias.len() - 1),
            to: "ground".into(),
            kind: ConnectionKind::Rubber(RubberStage {
                stiffness: RubberStiffness::Direct(k),
                psi,
                temperature_c: 25.0,
                amplitude_poly: None,
                amplitude_saturation: None,
                amplitude_form: Default::default(),
                frequency_poly: None,
                frequency_power_law: None,
                frequency_zener: None,
                temperature_stiffness_poly: None,
                temperature_damping_poly: None,
                thermal: None,
                rating: None,
            }),
        });
    }
    let engine = engine.map(|(mut e, at)| {
        e.at = at.into_iter().map(node).collect();
        e
    });
    let mut harmonics: Vec<Harmonic> = harmonics
        .into_iter()
        .map(|(at, mut h)| {
            h.at = node(at);
            h
        })
        .collect();
    if engine.is_none() && harmonics.is_empty() {
        harmonics.push(Harmonic {
            at: node(0),
            order: 1.0,
            amplitude: HarmonicAmplitude::Constant(100.0),
            phase_deg: 0.0,
        });
    }
    let load = load.map(|(at, damping)| Load {
        at: at.map(node),
        damping_nm_s_per_rad: damping.unwrap_or(0.0),
    });
    Model {
        name,
        description,
        inertias,
        connections,
        engine,
        harmonics,
        load,
        modal_damping,
        operation,
        expect: Default::default(),
    }
}

/// A uniform recording's parameters: the samples follow from them by a small PRNG, so a
/// case is cheap to draw and shrinks by its parameters, not sample by sample.
#[derive(Debug, Clone)]
pub struct RecordingCase {
    /// Sampling rate, Hz.
    pub rate_hz: f64,
    /// Mean speed of the reference (`engine`), rpm.
    pub mean_rpm: f64,
    /// Working cycles recorded (4 strokes: 2 revolutions each); ≥ 2 is the minimum.
    pub cycles: f64,
    /// Random speed deviation per sample, as a fraction of the mean (uniform ±).
    pub noise: f64,
    /// Periodic deviation of order 2, as a fraction of the mean.
    pub order2: f64,
    /// Run-up: the speed ramps from `mean_rpm` to `(1 + ramp)·mean_rpm`.
    pub ramp: Option<f64>,
    /// A second station `hub` at this fraction of the reference speed.
    pub second: Option<f64>,
    /// First time stamp, s (a DAQ's clock starts anywhere).
    pub t0_s: f64,
    /// PRNG seed.
    pub seed: u64,
}

/// Recording parameters: 500 Hz–10 kHz, 300–6000 rpm, 2.2–6 working cycles, at most
/// 60 000 samples (a debug-build analysis of each stays well under a second).
pub fn recording_case() -> impl Strategy<Value = RecordingCase> {
    (
        500.0..10_000.0_f64,
        300.0..6000.0_f64,
        2.2..6.0_f64,
        prop_oneof![Just(0.0), 0.0..0.02_f64, 0.0..0.5_f64],
        0.0..0.2_f64,
        prop::option::of(-0.5..2.0_f64),
        prop::option::of(prop_oneof![0.1..3.0_f64, Just(1.0)]),
        prop_oneof![Just(0.0), 0.0..1000.0_f64],
        any::<u64>(),
    )
        .prop_map(
            |(rate_hz, mean_rpm, cycles, noise, order2, ramp, second, t0_s, seed)| RecordingCase {
                rate_hz,
                mean_rpm,
                cycles,
                noise,
                order2,
                ramp,
                second,
                t0_s,
                seed,
            },
        )
        .prop_filter("at most 60 000 samples", |c| c.samples() <= 60_000)
}

impl RecordingCase {
    /// Samples per channel.
    pub fn samples(&self) -> usize {
        let duration_s = self.cycles * 2.0 * 60.0 / self.mean_rpm;
        (duration_s * self.rate_hz).ceil() as usize + 1
    }

    /// The recording: `time_s`, `engine_rpm` (the reference) and perhaps `hub_rpm`.
    pub fn recording(&self) -> Recording {
        let n = self.samples();
        let mut state = self.seed | 1;
        let mut uniform = move || {
            // xorshift64: deterministic, good enough for noise.
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let dt = 1.0 / self.rate_hz;
        let time_s: Vec<f64> = (0..n).map(|i| self.t0_s + i as f64 * dt).collect();
        let mut angle_rev = 0.0;
        let engine: Vec<f64> = (0..n)
            .map(|i| {
                let progress = i as f64 / n as f64;
                let mean = self.mean_rpm * (1.0 + self.ramp.unwrap_or(0.0) * progress);
                let wave = self.order2 * (2.0 * std::f64::consts::TAU * angle_rev).sin();
                let rpm = mean * (1.0 + wave + self.noise * uniform());
                angle_rev += rpm / 60.0 * dt;
                rpm
            })
            .collect();
        let mut channels = vec![Channel::new(
            ChannelKind::SpeedRpm {
                node: "engine".into(),
            },
            engine.clone(),
        )];
        if let Some(ratio) = self.second {
            channels.push(Channel::new(
                ChannelKind::SpeedRpm { node: "hub".into() },
                engine.iter().map(|v| v * ratio).collect(),
            ));
        }
        let kind = if self.ramp.is_some() {
            RunKind::RunUp
        } else {
            RunKind::Steady
        };
        let mut meta = RecordingMeta::new(kind, "engine");
        if kind == RunKind::Steady {
            meta.speed_rpm = Some(self.mean_rpm);
        }
        Recording {
            time_s,
            channels,
            meta,
        }
    }
}
