//! The measurement campaign: which recordings, at which speeds and loads, with which
//! stations, rate, noise and clock (issue 14, item 3: regimes, an optional long run and
//! run-up, 2–4 stations, 1–10 kHz, noise and a slow wobble).

use crate::rng::Rng;

/// One recording of the campaign.
#[derive(Debug, Clone, PartialEq)]
pub struct Recording {
    /// File stem, e.g. `regime-a`.
    pub stem: String,
    pub label: String,
    /// `steady` or `run-up` (recording-format.md).
    pub run_up: bool,
    pub from_rpm: f64,
    pub to_rpm: f64,
    pub load: f64,
    pub duration_s: f64,
}

/// A measuring station: a node, its sensor kind and lines per revolution.
#[derive(Debug, Clone, PartialEq)]
pub struct Station {
    pub node: usize,
    pub kind: &'static str,
    pub lines: u32,
}

/// The whole campaign.
#[derive(Debug, Clone, PartialEq)]
pub struct Campaign {
    pub rate_hz: f64,
    pub stations: Vec<Station>,
    pub noise_rpm: f64,
    /// Relative amplitude of the slow wobble of the held speed, 0.02–0.1 % (a bench
    /// dyno holds its speed within 0.1 %; the sidecar's `speed_rpm` is the set speed).
    pub wobble: f64,
    /// Period of the wobble, s.
    pub wobble_period_s: f64,
    /// The DAQ clock at the first sample, s (0 or a running clock such as 187.6 s).
    pub clock_start_s: f64,
    pub recordings: Vec<Recording>,
}

/// What the draw of the campaign needs to know about the driveline.
pub struct Needs {
    pub speed_lo_rpm: f64,
    pub speed_hi_rpm: f64,
    pub long_run: bool,
    pub part_load: bool,
    /// Candidate station nodes (the crank first).
    pub nodes: Vec<usize>,
    pub crank: usize,
}

/// Draws a campaign.
pub fn draw(rng: &mut Rng, needs: &Needs) -> Campaign {
    let rate_hz = rng.pick(&[
        1000.0, 1024.0, 2000.0, 2048.0, 2560.0, 4096.0, 5000.0, 10000.0,
    ]);
    let mut stations = vec![Station {
        node: needs.crank,
        kind: "encoder",
        lines: 360,
    }];
    let mut others: Vec<usize> = needs
        .nodes
        .iter()
        .copied()
        .filter(|&n| n != needs.crank)
        .collect();
    let count = rng.int(2, 4).min(others.len() + 1);
    while stations.len() < count {
        let i = rng.int(0, others.len() - 1);
        let node = others.remove(i);
        stations.push(Station {
            node,
            kind: "zebra",
            lines: rng.pick(&[78, 94, 120]),
        });
    }
    let (lo, hi) = (needs.speed_lo_rpm, needs.speed_hi_rpm);
    let n_reg = rng.int(3, 8);
    let dur = rng.range(2.0, 6.0).round();
    let mut recordings = Vec::new();
    let letters = "abcdefghijklmnop";
    for i in 0..n_reg {
        let frac = (i as f64 + rng.range(0.3, 0.7)) / n_reg as f64;
        let speed = ((lo + (hi - lo) * frac) / 10.0).round() * 10.0;
        let l = &letters[i..=i];
        recordings.push(Recording {
            stem: format!("regime-{l}"),
            label: format!("Regime {}", l.to_uppercase()),
            run_up: false,
            from_rpm: speed,
            to_rpm: speed,
            load: 1.0,
            duration_s: dur,
        });
    }
    if needs.part_load || rng.chance(0.5) {
        let part = (rng.range(0.3, 0.5) * 10.0).round() / 10.0;
        for k in 0..rng.int(1, 2) {
            let src = recordings[(k * n_reg / 2 + n_reg / 4).min(n_reg - 1)].clone();
            recordings.push(Recording {
                stem: format!("{}-part", src.stem),
                label: format!("{}, {:.0} % load", src.label, part * 100.0),
                load: part,
                ..src
            });
        }
    }
    if needs.long_run || rng.chance(0.5) {
        let speed = ((lo + (hi - lo) * rng.range(0.4, 0.8)) / 10.0).round() * 10.0;
        recordings.push(Recording {
            stem: "long-run".into(),
            label: "Long run, full load".into(),
            run_up: false,
            from_rpm: speed,
            to_rpm: speed,
            load: 1.0,
            duration_s: rng.range(20.0, 40.0).round(),
        });
    }
    if rng.chance(0.5) {
        let down = rng.chance(0.25);
        let (a, b) = if down { (hi, lo) } else { (lo, hi) };
        recordings.push(Recording {
            stem: if down {
                "run-down".into()
            } else {
                "run-up".into()
            },
            label: format!(
                "Run {} {a:.0} to {b:.0} rpm, full load",
                if down { "down" } else { "up" }
            ),
            run_up: true,
            from_rpm: a,
            to_rpm: b,
            load: 1.0,
            duration_s: rng.range(30.0, 60.0).round(),
        });
    }
    Campaign {
        rate_hz,
        stations,
        noise_rpm: rng.log_range(0.05, 0.5),
        wobble: rng.log_range(2e-4, 1e-3),
        wobble_period_s: rng.range(3.0, 10.0),
        clock_start_s: if rng.chance(0.5) {
            (rng.range(10.0, 500.0) * 10.0).round() / 10.0
        } else {
            0.0
        },
        recordings,
    }
}
