//! Every input of issue 13, in one table: the input, the command, the exit code it must
//! give and words its message must hold. Each case runs the real binary in a scratch
//! directory on files written here (models edited from the presets' text, bench
//! recordings written by hand), and must end: a hang is killed by the guard and fails.
//!
//! Exit codes (`spec/cli.md`): 0 a result, 1 a failed check or a run that could not be
//! done, 2 bad input. Words are matched case-insensitively in stderr.

mod hardening_support;

use hardening_support::*;
use std::path::Path;

/// One row of the table.
struct Case {
    /// Short name (also the scratch directory).
    name: &'static str,
    /// Writes the case's files into the directory and returns the command's arguments.
    setup: fn(&Path) -> Vec<String>,
    /// The exit code it must give.
    exit: i32,
    /// Words that stderr must hold (all of them).
    words: &'static [&'static str],
    /// Checks on the directory afterwards (inputs untouched, nothing left behind).
    after: Option<fn(&Path)>,
}

fn args(list: &[&str]) -> Vec<String> {
    list.iter().map(|s| s.to_string()).collect()
}

/// Runs one case and returns what went wrong, if anything.
fn check(case: &Case) -> Option<String> {
    let dir = scratch(case.name);
    let argv = (case.setup)(&dir);
    let out = run_in(&dir, &argv);
    let mut wrong = Vec::new();
    if out.code != Some(case.exit) {
        wrong.push(format!("exit {:?}, expected {}", out.code, case.exit));
    }
    let stderr = out.stderr.to_lowercase();
    for w in case.words {
        if !stderr.contains(&w.to_lowercase()) {
            wrong.push(format!("no `{w}` in the message"));
        }
    }
    if stderr.contains("panicked") {
        wrong.push("a panic".into());
    }
    // A NaN in a message is a number that was not computed, unless the user typed it.
    let has_nan = |text: &str| {
        text.split(|c: char| !c.is_ascii_alphanumeric())
            .any(|word| word.eq_ignore_ascii_case("nan"))
    };
    let typed_nan = argv.iter().any(|a| has_nan(a));
    if has_nan(&stderr) && !typed_nan || has_nan(&out.stdout) {
        wrong.push("a NaN in the output".into());
    }
    if let Some(after) = case.after
        && let Err(e) = std::panic::catch_unwind(|| after(&dir))
    {
        let text = e
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default();
        wrong.push(format!("after: {text}"));
    }
    (!wrong.is_empty()).then(|| {
        format!(
            "{} (torsim {}): {}\n  stderr: {}",
            case.name,
            argv.join(" "),
            wrong.join("; "),
            out.stderr.trim()
        )
    })
}

#[test]
fn every_input_of_issue_13_gives_a_result_or_a_located_error() {
    let cases = cases();
    let failures: Vec<String> = std::thread::scope(|s| {
        let handles: Vec<_> = cases
            .chunks(cases.len().div_ceil(2))
            .map(|chunk| s.spawn(move || chunk.iter().filter_map(check).collect::<Vec<_>>()))
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().expect("case thread"))
            .collect()
    });
    assert!(
        failures.is_empty(),
        "{} of {} cases failed:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

/// A model file `m.toml` from a preset with `edits`; returns its name.
fn model(dir: &Path, preset_name: &str, edits: &[(&str, &str)]) -> String {
    std::fs::write(dir.join("m.toml"), edited(&preset(preset_name), edits)).expect("model");
    "m.toml".into()
}

/// A steady bench recording `r.csv` + `r.toml` at 3000 rpm, 10 240 Hz, 1 s, with the
/// sample at `row` (0-based) set to `value`.
fn spiked(dir: &Path, row: usize, value: f64) -> String {
    recording(dir, "r", &Bench::default(), |rows| rows[row].1 = value)
}

fn cases() -> Vec<Case> {
    let mut all = data_loss();
    all.extend(crashes_and_hangs());
    all.extend(valid_files());
    all.extend(wrong_but_silent());
    all.extend(vague_errors());
    all
}

fn data_loss() -> Vec<Case> {
    vec![
        Case {
            name: "simulate-csv-onto-model-sidecar",
            setup: |d| {
                std::fs::write(d.join("run.toml"), preset("test-rig-70sh")).unwrap();
                args(&[
                    "simulate",
                    "run.toml",
                    "--speed-rpm",
                    "3000",
                    "--duration-s",
                    "0.2",
                    "--csv",
                    "run.csv",
                ])
            },
            exit: 2,
            words: &["run.toml", "--csv"],
            after: Some(|d| {
                unchanged(d, "run.toml", &preset("test-rig-70sh"));
                assert!(!d.join("run.csv").exists(), "run.csv written");
            }),
        },
        Case {
            name: "simulate-csv-named-toml",
            setup: |d| {
                let m = model(d, "test-rig-70sh", &[]);
                args(&[
                    "simulate",
                    &m,
                    "--speed-rpm",
                    "3000",
                    "--duration-s",
                    "0.2",
                    "--csv",
                    "out.toml",
                ])
            },
            exit: 2,
            words: &["out.toml", "--csv"],
            after: Some(|d| assert!(!d.join("out.toml").exists(), "out.toml written")),
        },
        Case {
            name: "simulate-csv-onto-model",
            setup: |d| {
                let m = model(d, "test-rig-70sh", &[]);
                args(&[
                    "simulate",
                    &m,
                    "--speed-rpm",
                    "3000",
                    "--duration-s",
                    "0.2",
                    "--csv",
                    &m,
                ])
            },
            exit: 2,
            words: &["m.toml", "--csv"],
            after: Some(|d| unchanged(d, "m.toml", &preset("test-rig-70sh"))),
        },
        Case {
            name: "campbell-csv-onto-model",
            setup: |d| {
                let m = model(d, "test-rig-70sh", &[]);
                args(&["campbell", &m, "--csv", &m])
            },
            exit: 2,
            words: &["m.toml", "--csv"],
            after: Some(|d| unchanged(d, "m.toml", &preset("test-rig-70sh"))),
        },
        Case {
            name: "diagnose-report-onto-recording",
            setup: |d| {
                let m = model(d, "test-rig-70sh", &[]);
                let r = recording(d, "r", &Bench::default(), |_| {});
                args(&["diagnose", &m, &r, "--report", &r])
            },
            exit: 2,
            words: &["r.csv", "--report"],
            after: Some(|d| {
                let b = Bench::default();
                unchanged(d, "r.csv", &b.csv(&b.rows()));
            }),
        },
        Case {
            name: "diagnose-report-onto-sidecar",
            setup: |d| {
                let m = model(d, "test-rig-70sh", &[]);
                let r = recording(d, "r", &Bench::default(), |_| {});
                args(&["diagnose", &m, &r, "--report", "r.toml"])
            },
            exit: 2,
            words: &["r.toml", "--report"],
            after: Some(|d| unchanged(d, "r.toml", &sidecar(3000.0, ""))),
        },
        Case {
            name: "diagnose-report-onto-model",
            setup: |d| {
                let m = model(d, "test-rig-70sh", &[]);
                let r = recording(d, "r", &Bench::default(), |_| {});
                args(&["diagnose", &m, &r, "--report", &m])
            },
            exit: 2,
            words: &["m.toml", "--report"],
            after: Some(|d| unchanged(d, "m.toml", &preset("test-rig-70sh"))),
        },
        Case {
            name: "failed-simulate-writes-nothing",
            setup: |d| {
                std::fs::write(d.join("x.csv"), "old csv").unwrap();
                std::fs::write(d.join("x.toml"), "old toml").unwrap();
                args(&[
                    "simulate",
                    "preset:test-rig-mod1",
                    "--speed-rpm",
                    "300",
                    "--duration-s",
                    "1",
                    "--csv",
                    "x.csv",
                ])
            },
            exit: 1,
            words: &[],
            after: Some(|d| {
                unchanged(d, "x.csv", "old csv");
                unchanged(d, "x.toml", "old toml");
            }),
        },
        Case {
            name: "unwritable-sidecar-leaves-csv",
            setup: |d| {
                std::fs::write(d.join("x.csv"), "old csv").unwrap();
                std::fs::create_dir(d.join("x.toml")).unwrap();
                args(&[
                    "simulate",
                    "preset:test-rig-70sh",
                    "--speed-rpm",
                    "3000",
                    "--duration-s",
                    "0.2",
                    "--csv",
                    "x.csv",
                ])
            },
            exit: 2,
            words: &["x.toml"],
            after: Some(|d| {
                unchanged(d, "x.csv", "old csv");
                let left = std::fs::read_dir(d).unwrap().count();
                assert_eq!(left, 2, "a temporary file was left behind");
            }),
        },
    ]
}

fn crashes_and_hangs() -> Vec<Case> {
    let spike = |name: &'static str, setup: fn(&Path) -> Vec<String>| Case {
        name,
        setup,
        exit: 2,
        words: &["r.csv", "5002", "engine_rpm", "--bad-samples"],
        after: None,
    };
    let mut cases = vec![
        spike("spike-1e300", |d| {
            args(&["analyse", &spiked(d, 5000, 1e300)])
        }),
        spike("spike-9.9e37", |d| {
            args(&["analyse", &spiked(d, 5000, 9.9e37)])
        }),
        spike("spike-1e15", |d| args(&["analyse", &spiked(d, 5000, 1e15)])),
        spike("spike-1e12", |d| args(&["analyse", &spiked(d, 5000, 1e12)])),
    ];
    cases.extend([
        Case {
            name: "response-order-1e9",
            setup: |_| args(&["response", "preset:test-rig-70sh", "--orders", "1e9"]),
            exit: 2,
            words: &["--orders", "100", "--max-order"],
            after: None,
        },
        Case {
            name: "response-order-1e5",
            setup: |_| args(&["response", "preset:test-rig-70sh", "--orders", "1e5"]),
            exit: 2,
            words: &["--orders", "100"],
            after: None,
        },
        Case {
            name: "simulate-duration-1e9",
            setup: |_| {
                args(&[
                    "simulate",
                    "preset:test-rig-70sh",
                    "--speed-rpm",
                    "3000",
                    "--duration-s",
                    "1e9",
                ])
            },
            exit: 2,
            words: &["samples", "--max-samples"],
            after: None,
        },
        Case {
            name: "simulate-rate-1e12",
            setup: |_| {
                args(&[
                    "simulate",
                    "preset:test-rig-70sh",
                    "--speed-rpm",
                    "3000",
                    "--rate-hz",
                    "1e12",
                ])
            },
            exit: 2,
            words: &["samples"],
            after: None,
        },
        Case {
            name: "simulate-run-up-to-1e9",
            setup: |_| {
                args(&[
                    "simulate",
                    "preset:test-rig-70sh",
                    "--run-up",
                    "1000:1e9",
                    "--duration-s",
                    "2",
                ])
            },
            exit: 2,
            words: &["1e9", "--max-speed-rpm"],
            after: None,
        },
        Case {
            name: "thermal-stage-with-tiny-capacity",
            setup: |d| {
                let thermal = "psi = 0.4343\nthermal = { capacity_j_per_k = 1e-9, conductance_w_per_k = 1.0, ambient_c = 25.0 }\n";
                let m = model(d, "test-rig-70sh", &[("psi = 0.4343\n", thermal)]);
                args(&["simulate", &m, "--speed-rpm", "3000", "--duration-s", "0.2"])
            },
            exit: 0,
            words: &["thermal time constant", "quasi-statically"],
            after: None,
        },
        Case {
            name: "explicit-method-on-a-stiff-model",
            setup: |d| {
                let m = model(d, "test-rig-70sh", &[("stiffness = 12684.0", "stiffness = 1e12")]);
                args(&["simulate", &m, "--speed-rpm", "3000", "--duration-s", "0.2", "--method", "explicit"])
            },
            exit: 1,
            words: &["step budget", "connection `a`", "--method implicit"],
            after: None,
        },
        Case {
            name: "cylinders-100000",
            setup: |d| {
                let m = model(
                    d,
                    "diagnosis-bench",
                    &[("cylinders = 4", "cylinders = 100000")],
                );
                args(&["simulate", &m, "--speed-rpm", "3000", "--duration-s", "0.1"])
            },
            exit: 2,
            words: &["m.toml", "cylinders", "64", "--max-cylinders"],
            after: None,
        },
    ]);
    cases
}

fn valid_files() -> Vec<Case> {
    vec![
        Case {
            name: "microsecond-timestamps-10240",
            setup: |d| {
                let b = Bench {
                    time_decimals: Some(6),
                    ..Bench::default()
                };
                args(&["analyse", &recording(d, "r", &b, |_| {})])
            },
            exit: 0,
            words: &[],
            after: None,
        },
        Case {
            name: "ten-microsecond-timestamps-48k",
            setup: |d| {
                let b = Bench {
                    rate_hz: 48000.0,
                    time_decimals: Some(5),
                    duration_s: 0.5,
                    ..Bench::default()
                };
                args(&["analyse", &recording(d, "r", &b, |_| {})])
            },
            exit: 0,
            words: &[],
            after: None,
        },
        Case {
            name: "jitter-20-microseconds",
            setup: |d| {
                let b = Bench {
                    time_decimals: Some(6),
                    jitter_s: 20e-6,
                    ..Bench::default()
                };
                args(&["analyse", &recording(d, "r", &b, |_| {})])
            },
            exit: 0,
            words: &[],
            after: None,
        },
        Case {
            name: "clock-starts-at-187.648",
            setup: |d| {
                let b = Bench {
                    t0_s: 187.648,
                    time_decimals: Some(6),
                    ..Bench::default()
                };
                args(&["analyse", &recording(d, "r", &b, |_| {})])
            },
            exit: 0,
            words: &[],
            after: None,
        },
        Case {
            name: "utf8-bom",
            setup: |d| {
                let b = Bench {
                    bom: true,
                    ..Bench::default()
                };
                args(&["analyse", &recording(d, "r", &b, |_| {})])
            },
            exit: 0,
            words: &[],
            after: None,
        },
        Case {
            name: "sidecar-inline-tables",
            setup: |d| {
                let b = Bench::default();
                let extra = "sensors = { engine = { kind = \"encoder\", lines_per_rev = 360 } }\n";
                args(&[
                    "analyse",
                    &write_pair(d, "r", &b.csv(&b.rows()), &sidecar(3000.0, extra)),
                ])
            },
            exit: 0,
            words: &[],
            after: None,
        },
    ]
}

fn wrong_but_silent() -> Vec<Case> {
    vec![
        Case {
            name: "node-name-with-comma",
            setup: |d| {
                let m = model(
                    d,
                    "test-rig-70sh",
                    &[("\"middle_flange\"", "\"middle,flange\"")],
                );
                args(&["modes", &m])
            },
            exit: 2,
            words: &["m.toml", "name", "middle,flange"],
            after: None,
        },
        Case {
            name: "node-name-with-newline",
            setup: |d| {
                let m = model(
                    d,
                    "test-rig-70sh",
                    &[("\"middle_flange\"", "\"middle\\nflange\"")],
                );
                args(&["modes", &m])
            },
            exit: 2,
            words: &["m.toml", "U+000A"],
            after: None,
        },
        Case {
            name: "node-name-only-spaces",
            setup: |d| {
                let m = model(d, "test-rig-70sh", &[("\"middle_flange\"", "\"   \"")]);
                args(&["modes", &m])
            },
            exit: 2,
            words: &["m.toml", "name"],
            after: None,
        },
        Case {
            name: "empty-orders",
            setup: |d| {
                let m = model(
                    d,
                    "test-rig-70sh",
                    &[("[operation]", "[operation]\norders = []")],
                );
                args(&["response", &m])
            },
            exit: 2,
            words: &["m.toml", "orders"],
            after: None,
        },
        Case {
            name: "coupling-frequency-factor-below-zero",
            setup: |d| {
                let poly = "psi = 0.4343\nfrequency_poly = [0.0, -0.02, 1.0]\n";
                let m = model(d, "test-rig-70sh", &[("psi = 0.4343\n", poly)]);
                args(&["coupling", &m, "--frequency-hz", "100"])
            },
            exit: 2,
            words: &["rubber stage `b`", "frequency_poly", "100.0 Hz"],
            after: None,
        },
        Case {
            name: "simulate-frequency-factor-below-zero",
            setup: |d| {
                let poly = "psi = 0.4343\nfrequency_poly = [0.0, -0.02, 1.0]\n";
                let m = model(d, "test-rig-70sh", &[("psi = 0.4343\n", poly)]);
                args(&["simulate", &m, "--speed-rpm", "3000", "--duration-s", "0.2"])
            },
            exit: 2,
            words: &["rubber stage `b`", "frequency_poly"],
            after: None,
        },
        Case {
            name: "missing-harmonic-phase",
            setup: |d| {
                let m = model(d, "test-rig-70sh", &[("phase_deg = 0.0\n", "")]);
                args(&["modes", &m])
            },
            exit: 2,
            words: &["m.toml", "harmonic[0].phase_deg", "missing"],
            after: None,
        },
        Case {
            name: "simulate-1e6-rpm",
            setup: |_| {
                args(&[
                    "simulate",
                    "preset:test-rig-70sh",
                    "--speed-rpm",
                    "1e6",
                    "--duration-s",
                    "0.1",
                ])
            },
            exit: 2,
            words: &["--speed-rpm", "--max-speed-rpm"],
            after: None,
        },
        Case {
            name: "recording-1e6-rpm-spike",
            setup: |d| args(&["analyse", &spiked(d, 3000, 1e6)]),
            exit: 2,
            words: &["r.csv", "3002", "engine_rpm"],
            after: None,
        },
        Case {
            name: "diagnose-one-recording",
            setup: |d| {
                let m = model(d, "test-rig-70sh", &[]);
                args(&[
                    "diagnose",
                    &m,
                    &recording(d, "r", &Bench::default(), |_| {}),
                ])
            },
            exit: 2,
            words: &["r.csv", "held out"],
            after: None,
        },
        Case {
            name: "column-of-1e308",
            setup: |d| {
                let b = Bench::default();
                let rows: Vec<(f64, f64)> = b.rows().into_iter().map(|(t, _)| (t, 1e308)).collect();
                args(&[
                    "analyse",
                    &write_pair(d, "r", &b.csv(&rows), &sidecar(3000.0, "")),
                ])
            },
            exit: 2,
            words: &["r.csv", "engine_rpm"],
            after: None,
        },
        Case {
            name: "modes-speed-nan",
            setup: |_| args(&["modes", "preset:test-rig-70sh", "--speed-rpm", "nan"]),
            exit: 2,
            words: &["--speed-rpm"],
            after: None,
        },
        Case {
            name: "modes-speed-negative",
            setup: |_| args(&["modes", "preset:test-rig-70sh", "--speed-rpm=-5"]),
            exit: 2,
            words: &["--speed-rpm"],
            after: None,
        },
        Case {
            name: "modes-speed-zero",
            setup: |_| args(&["modes", "preset:test-rig-70sh", "--speed-rpm", "0"]),
            exit: 2,
            words: &["--speed-rpm"],
            after: None,
        },
        Case {
            name: "modes-speed-1e300",
            setup: |_| args(&["modes", "preset:test-rig-70sh", "--speed-rpm", "1e300"]),
            exit: 2,
            words: &["--speed-rpm"],
            after: None,
        },
        Case {
            name: "coupling-temperature-minus-300",
            setup: |_| args(&["coupling", "preset:cng-genset", "--temperature-c=-300"]),
            exit: 2,
            words: &["--temperature-c", "absolute zero"],
            after: None,
        },
        Case {
            name: "sidecar-temperature-minus-300",
            setup: |d| {
                let b = Bench::default();
                args(&[
                    "analyse",
                    &write_pair(
                        d,
                        "r",
                        &b.csv(&b.rows()),
                        &sidecar(3000.0, "temperature_c = -300.0\n"),
                    ),
                ])
            },
            exit: 2,
            words: &["r.toml", "temperature_c"],
            after: None,
        },
        Case {
            name: "sidecar-speed-6000-on-3000",
            setup: |d| {
                let b = Bench::default();
                args(&[
                    "analyse",
                    &write_pair(d, "r", &b.csv(&b.rows()), &sidecar(6000.0, "")),
                ])
            },
            exit: 2,
            words: &["r.toml", "speed_rpm", "6000"],
            after: None,
        },
        Case {
            name: "rtol-1e-20",
            setup: |_| {
                args(&[
                    "simulate",
                    "preset:test-rig-70sh",
                    "--speed-rpm",
                    "3000",
                    "--rtol",
                    "1e-20",
                ])
            },
            exit: 2,
            words: &["--rtol", "1e-12"],
            after: None,
        },
    ]
}

fn vague_errors() -> Vec<Case> {
    vec![
        Case {
            name: "analyse-missing-csv",
            setup: |_| args(&["analyse", "nope.csv"]),
            exit: 2,
            words: &["nope.csv"],
            after: None,
        },
        Case {
            name: "under-two-cycles-after-the-margins",
            setup: |d| {
                let b = Bench {
                    duration_s: 0.0815,
                    ..Bench::default()
                };
                args(&["analyse", &recording(d, "r", &b, |_| {})])
            },
            exit: 2,
            words: &["r.csv", "working cycles", "margins"],
            after: None,
        },
        Case {
            name: "gap-of-100-ms",
            setup: |d| {
                let b = Bench::default();
                let rows: Vec<(f64, f64)> = b
                    .rows()
                    .into_iter()
                    .filter(|(t, _)| !(0.4..0.5).contains(t))
                    .collect();
                args(&[
                    "analyse",
                    &write_pair(d, "r", &b.csv(&rows), &sidecar(3000.0, "")),
                ])
            },
            exit: 2,
            words: &["r.csv", "0.5", "gap"],
            after: None,
        },
        Case {
            name: "duplicate-toml-key",
            setup: |d| {
                let m = model(
                    d,
                    "test-rig-70sh",
                    &[(
                        "[operation]",
                        "[operation]\nreference = \"engine\"\nreference = \"engine\"",
                    )],
                );
                args(&["modes", &m])
            },
            exit: 2,
            words: &["m.toml", "reference"],
            after: None,
        },
        Case {
            name: "invalid-utf8-model",
            setup: |d| {
                let mut bytes = preset("test-rig-70sh").into_bytes();
                let at = bytes.iter().position(|b| *b == b'\n').unwrap() + 1;
                bytes.splice(at..at, [b'#', 0xff, 0xfe, b'\n']);
                std::fs::write(d.join("m.toml"), bytes).unwrap();
                args(&["modes", "m.toml"])
            },
            exit: 2,
            words: &["m.toml", "line 2", "utf-8"],
            after: None,
        },
        Case {
            name: "gear-ratio-1e-300",
            setup: |d| {
                let m = model(
                    d,
                    "test-rig-70sh",
                    &[("ratio = 0.3333333333333333", "ratio = 1e-300")],
                );
                args(&["modes", &m])
            },
            exit: 2,
            words: &["m.toml", "ratio", "1e-300"],
            after: None,
        },
        Case {
            name: "stiffness-1e-308",
            setup: |d| {
                let m = model(
                    d,
                    "test-rig-70sh",
                    &[("stiffness = 12684.0", "stiffness = 1e-308")],
                );
                args(&["modes", &m])
            },
            exit: 2,
            words: &["m.toml", "stiffness", "round-off"],
            after: None,
        },
        Case {
            name: "model-without-nodes",
            setup: |d| {
                std::fs::write(d.join("m.toml"), "format = 1\nname = \"empty\"\n").unwrap();
                args(&["modes", "m.toml"])
            },
            exit: 2,
            words: &["m.toml", "inertia"],
            after: None,
        },
    ]
}

#[allow(dead_code)]
fn unchanged(dir: &Path, file: &str, text: &str) {
    let now = std::fs::read_to_string(dir.join(file)).unwrap_or_default();
    assert!(now == text, "{file} was changed");
}
