//! Fixtures for the table-driven hardening test (`tests/hardening.rs`, issue 13): a
//! scratch directory per case, models edited from the shipped presets' text, and bench
//! recordings written here by hand (not by torsim's writer, so the reader is tested on
//! files it did not make), and a runner that kills a case that does not end.
#![allow(dead_code)]

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[path = "../scratch/mod.rs"]
mod scratch;
pub use scratch::Scratch;

/// What one run of the binary gave.
pub struct Outcome {
    /// Exit code (`None`: killed by a signal or by the hang guard).
    pub code: Option<i32>,
    /// Standard error, lossy UTF-8.
    pub stderr: String,
    /// Standard output, lossy UTF-8.
    pub stdout: String,
    /// Wall time of the run.
    pub elapsed: Duration,
}

/// A hang guard, not a speed target: a case still running after this long is killed and
/// fails (the 10 s are for a release build; a debug build may take several times
/// longer, and CI runs two test binaries at once).
pub const HANG_GUARD: Duration = Duration::from_secs(150);

/// Runs `torsim` with `args` in `dir`, killing it after [`HANG_GUARD`].
pub fn run_in(dir: &Path, args: &[String]) -> Outcome {
    let started = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_torsim"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn torsim");
    let mut killed = false;
    loop {
        if child.try_wait().expect("wait").is_some() {
            break;
        }
        if started.elapsed() > HANG_GUARD {
            let _ = child.kill();
            killed = true;
            break;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = child.wait_with_output().expect("output");
    Outcome {
        code: if killed { None } else { out.status.code() },
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        elapsed: started.elapsed(),
    }
}

/// A fresh scratch directory for one case, removed when the returned guard is dropped.
pub fn scratch(case: &str) -> Scratch {
    Scratch::new(&format!("torsim-hardening-{case}-"))
}

/// A shipped preset's text.
pub fn preset(name: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("presets")
        .join(format!("{name}.toml"));
    std::fs::read_to_string(path).expect("preset")
}

/// `text` with each `(from, to)` replaced once; panics when `from` is absent, so a
/// fixture cannot silently stop testing what it says.
pub fn edited(text: &str, edits: &[(&str, &str)]) -> String {
    let mut out = text.to_string();
    for (from, to) in edits {
        assert!(out.contains(from), "fixture edit: `{from}` not in the text");
        out = out.replacen(from, to, 1);
    }
    out
}

/// How a hand-written bench recording looks.
#[derive(Clone)]
pub struct Bench {
    /// Sample rate, Hz.
    pub rate_hz: f64,
    /// Length, s.
    pub duration_s: f64,
    /// Clock at the first sample, s.
    pub t0_s: f64,
    /// Decimals printed in the time column (`None`: Rust's shortest round trip).
    pub time_decimals: Option<usize>,
    /// Timing jitter, s (a deterministic ± pattern, not a random draw).
    pub jitter_s: f64,
    /// Mean engine speed, rpm.
    pub speed_rpm: f64,
    /// A UTF-8 BOM before the header.
    pub bom: bool,
}

impl Default for Bench {
    fn default() -> Self {
        Self {
            rate_hz: 10240.0,
            duration_s: 1.0,
            t0_s: 0.0,
            time_decimals: None,
            jitter_s: 0.0,
            speed_rpm: 3000.0,
            bom: false,
        }
    }
}

impl Bench {
    /// Rows `(time, engine rpm)`: the mean speed with 2nd- and 4th-order ripple of 12 and
    /// 3 rpm (a four-cylinder engine's IAS), as a zebra-tape bench would record it.
    pub fn rows(&self) -> Vec<(f64, f64)> {
        let n = (self.duration_s * self.rate_hz).round() as usize;
        let f_rev = self.speed_rpm / 60.0;
        (0..n)
            .map(|k| {
                let jitter = match k % 4 {
                    1 => self.jitter_s,
                    3 => -self.jitter_s,
                    _ => 0.0,
                };
                let t = k as f64 / self.rate_hz + jitter;
                let phase = std::f64::consts::TAU * f_rev * t;
                let rpm = self.speed_rpm + 12.0 * (2.0 * phase).cos() + 3.0 * (4.0 * phase).sin();
                (self.t0_s + t, rpm)
            })
            .collect()
    }

    /// The CSV text of `rows`.
    pub fn csv(&self, rows: &[(f64, f64)]) -> String {
        let mut out = String::new();
        if self.bom {
            out.push('\u{feff}');
        }
        out.push_str("time_s,engine_rpm\n");
        for (t, n) in rows {
            match self.time_decimals {
                Some(d) => out.push_str(&format!("{t:.d$},{n}\n")),
                None => out.push_str(&format!("{t},{n}\n")),
            }
        }
        out
    }
}

/// A steady run's sidecar for the `engine` node at `speed_rpm`, plus `extra` lines.
pub fn sidecar(speed_rpm: f64, extra: &str) -> String {
    format!(
        "format = 1\nkind = \"steady\"\nreference = \"engine\"\nspeed_rpm = {speed_rpm:.1}\n{extra}"
    )
}

/// Writes `name.csv` and `name.toml` in `dir`; returns the CSV path as an argument.
pub fn write_pair(dir: &Path, name: &str, csv: &str, toml: &str) -> String {
    std::fs::write(dir.join(format!("{name}.csv")), csv).expect("csv");
    std::fs::write(dir.join(format!("{name}.toml")), toml).expect("toml");
    format!("{name}.csv")
}

/// A bench recording with its default sidecar, rows changed by `mutate`.
pub fn recording(
    dir: &Path,
    name: &str,
    bench: &Bench,
    mutate: impl Fn(&mut [(f64, f64)]),
) -> String {
    let mut rows = bench.rows();
    mutate(&mut rows);
    write_pair(dir, name, &bench.csv(&rows), &sidecar(bench.speed_rpm, ""))
}
