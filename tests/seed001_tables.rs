//! Seed 001's tables as a test of prediction (issue 15, item 3). The 70 Sh preset is
//! calibrated to Table 8(c) and Table 9 (`examples/seed001_tables.rs calibrate`); the MOD
//! presets change only what §3.4 states, sized by Table 7's FE mode shifts. These tests
//! hold the shipped presets to what the calibration and the sizing measured, and the time
//! domain to Table 13's ranking at Regime A.

use torsim::calibrate::{Target, evaluate};
use torsim::compare::{compare_regimes, model_regimes};
use torsim::model::{Model, parse_model, presets};
use torsim::transient::RunOptions;

fn preset(name: &str) -> Model {
    let p = presets::preset(name).expect("preset");
    parse_model(p.text, name).expect("model")
}

fn modes_hz(m: &Model) -> Vec<f64> {
    let targets: Vec<Target> = (1..=3)
        .map(|mode| Target::ModeHz {
            mode,
            hz: 1.0,
            tolerance_pct: 1.0,
        })
        .collect();
    evaluate(m, &targets).expect("modes")
}

#[test]
fn the_70sh_preset_has_table_8c_modes() {
    // Table 8(c): 4.5 / 24.9 / 58.2 % of f_max = 200 Hz. Fitted to 0.5 % (measured
    // 0.22 %, 0.24 %, 0.08 %).
    for (f, want) in modes_hz(&preset("test-rig-70sh"))
        .iter()
        .zip([9.0, 49.8, 116.4])
    {
        assert!((f / want - 1.0).abs() < 0.005, "{f} Hz against {want} Hz");
    }
}

#[test]
fn the_70sh_preset_has_table_9_irregularity_within_its_calibration() {
    let table_9 = [
        ("engine", [4.5, 3.5, 2.9, 2.5, 2.1, 1.3]),
        ("coupling_es", [4.9, 2.0, 2.2, 2.7, 3.0, 3.4]),
        ("middle_flange", [10.3, 3.3, 2.0, 1.7, 1.4, 4.0]),
    ];
    let mut targets = Vec::new();
    for (station, values) in table_9 {
        for (regime, pct) in ["A", "B", "C", "D", "E", "F"].iter().zip(values) {
            targets.push(Target::Irregularity {
                station: station.into(),
                regime: (*regime).into(),
                pct,
                tolerance_pct: 10.0,
            });
        }
    }
    let got = evaluate(&preset("test-rig-70sh"), &targets).expect("IR");
    let logs: Vec<f64> = targets
        .iter()
        .zip(&got)
        .map(|(t, g)| match t {
            Target::Irregularity { pct, .. } => (g / pct).ln(),
            Target::ModeHz { .. } => unreachable!(),
        })
        .collect();
    let rms = (logs.iter().map(|l| l * l).sum::<f64>() / logs.len() as f64).sqrt();
    let worst = logs.iter().fold(0.0_f64, |a, l| a.max(l.abs()));
    // The calibration measured an RMS of 0.185 in ln IR and a worst cell of ln 1.51
    // (coupling_es at Regime E, 1.99 % against 3.0 %).
    assert!(rms < 0.19, "RMS ln error {rms}");
    assert!(worst < 1.52_f64.ln(), "worst ln error {worst}");
    // Regime A is the resonant one at the middle flange (§3.5), F the second.
    let flange = &got[12..18];
    assert!(
        flange[0] > 2.0 * flange[5] && flange[5] > flange[1..5].iter().cloned().fold(0.0, f64::max)
    );
}

#[test]
fn the_mod_presets_move_their_modes_as_table_7_says() {
    let lp70 = modes_hz(&preset("test-rig-70sh"));
    let lp45 = modes_hz(&preset("test-rig-45sh"));
    // FE torsional modes, % of f_max: Tables 5(b), 6(b) and 7(a)-(c).
    let fe45 = [2.9, 14.9, 44.0];
    let fe70 = [5.1, 25.7, 60.2];
    let cases = [
        ("test-rig-mod1", &lp45, fe45, [2.5, 8.0, 72.2]),
        ("test-rig-mod2", &lp70, fe70, [4.5, 24.3, 80.4]),
        ("test-rig-mod3", &lp70, fe70, [3.7, 24.9, 77.6]),
    ];
    for (name, lp, fe_base, fe_mod) in cases {
        let got = modes_hz(&preset(name));
        for i in 0..3 {
            let ratio = got[i] / (lp[i] * fe_mod[i] / fe_base[i]);
            // MOD 1 and 3 are met to rounding of the shipped values; MOD 2's mode 2 cannot
            // be (a lighter flange raises it), measured +14.5 %, and its other modes
            // follow within 3 %.
            let (lo, hi) = match (name, i) {
                ("test-rig-mod2", 1) => (1.13, 1.16),
                ("test-rig-mod2", _) => (0.97, 1.03),
                _ => (0.999, 1.001),
            };
            assert!((lo..hi).contains(&ratio), "{name} mode {}: {ratio}", i + 1);
        }
    }
}

#[test]
fn the_time_domain_ranks_the_mods_as_table_13_at_regime_a() {
    let mut loss_w = Vec::new();
    let mut flange_ir = Vec::new();
    for name in ["test-rig-mod1", "test-rig-mod2", "test-rig-mod3"] {
        let m = preset(name);
        let regime_a = model_regimes(&m).swap_remove(0);
        let r = compare_regimes(&m, &[regime_a], 1.0, RunOptions::default(), &mut |_| true)
            .expect("compare");
        loss_w.push(r.power_loss_w.iter().map(|s| s[0]).sum::<f64>());
        let node = r
            .nodes
            .iter()
            .position(|n| n == "middle_flange")
            .expect("node");
        flange_ir.push(r.irregularity_pct[node][0]);
    }
    // Table 13 at A: MOD 2 (31.87 W) > MOD 3 (19.14 W) > MOD 1 (1.03 W); Tables 10-12,
    // IR at the middle flange: MOD 1 (0.30) < MOD 3 (2.82) < MOD 2 (3.24).
    assert!(loss_w[1] > loss_w[2] && loss_w[2] > loss_w[0], "{loss_w:?}");
    assert!(
        flange_ir[0] < flange_ir[2] && flange_ir[2] < flange_ir[1],
        "{flange_ir:?}"
    );
}
