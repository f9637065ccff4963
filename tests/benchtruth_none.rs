//! benchtruth's `none` control (issue 14, item 4): the user's model is the bench's
//! truth up to the noise. For two fixed seeds, `torsim simulate` of the written model at
//! each steady regime's speed and load must give the order amplitudes that `torsim
//! analyse` reads from the bench's recording, station by station.

use std::path::Path;
use std::process::Command;

fn torsim_json(args: &[&str]) -> serde_json::Value {
    let out = Command::new(env!("CARGO_BIN_EXE_torsim"))
        .args(args)
        .output()
        .expect("torsim runs");
    assert!(
        out.status.success(),
        "torsim {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

fn sidecar_value(path: &Path, key: &str) -> Option<String> {
    let text = std::fs::read_to_string(path).ok()?;
    text.lines()
        .take_while(|l| !l.starts_with('['))
        .find_map(|l| {
            let (k, v) = l.split_once('=')?;
            (k.trim() == key).then(|| v.trim().trim_matches('"').to_owned())
        })
}

/// Worst relative difference over the orders above 1 rpm (≥ 20× the bench's largest
/// noise level of 0.05 rpm after averaging) at the recording's stations.
fn worst_difference(seed: u64) -> f64 {
    let scratch = tempfile::Builder::new()
        .prefix(&format!("torsim-bt-none-{seed}-"))
        .tempdir()
        .expect("temp dir");
    let dir = scratch.path();
    let files = benchtruth::write_case(seed, Some("none"), dir).expect("case written");
    let model = files.model.to_string_lossy().into_owned();
    let mut worst: f64 = 0.0;
    let mut compared = 0;
    for csv in files.recordings.iter().take(3) {
        let side = csv.with_extension("toml");
        let Some(speed) = sidecar_value(&side, "speed_rpm") else {
            continue;
        };
        let load = sidecar_value(&side, "load").unwrap_or_else(|| "1".into());
        let sim = dir.join("sim.csv");
        let sim_s = sim.to_string_lossy().into_owned();
        let _ = torsim_json(&[
            "simulate",
            &model,
            "--speed-rpm",
            &speed,
            "--load",
            &load,
            "--duration-s",
            "1",
            "--rate-hz",
            "4096",
            "--csv",
            &sim_s,
            "--json",
        ]);
        let bench = torsim_json(&["analyse", &csv.to_string_lossy(), "--json"]);
        let model_run = torsim_json(&["analyse", &sim_s, "--json"]);
        let stations = bench["orders"].as_object().expect("orders");
        for (station, orders) in stations {
            for (order, amp) in orders.as_object().expect("orders of a station") {
                let measured = amp.as_f64().unwrap_or(0.0);
                let simulated = model_run["orders"][station][order].as_f64().unwrap_or(0.0);
                if measured > 1.0 {
                    let d = (simulated / measured - 1.0).abs();
                    eprintln!(
                        "seed {seed} {} {station} order {order}: bench {measured:.3}, model {simulated:.3}",
                        csv.display()
                    );
                    worst = worst.max(d);
                    compared += 1;
                }
            }
        }
    }
    assert!(compared > 0, "seed {seed}: nothing above 1 rpm compared");
    worst
}

/// The bench fits its truth rubbers by the model's own rule (one causal chain per stage,
/// fitted over the model's band and at its nominal modes weighted by strain-energy
/// share), implemented independently in `benchtruth/src/{fitpoints,visco,nnls}.rs`; its
/// chains' deviations from the law at seed 0's modes are within 0.1 points of those
/// `torsim modes` reports (coupling1 at the first mode: −0.54 against −0.55 % in
/// stiffness). Measured: worst 1.56 % for seed 0 (`regime-b` at 1290 rpm, order 3 at
/// 64.5 Hz, 9 % above the 59 Hz mode, where a difference in that mode's frequency is
/// amplified about 12-fold: brake 11.048 against 10.876 rpm; mass3 37.571 against
/// 37.078 rpm, 1.3 %), 0.66 % for seed 2 (`regime-c` crank order 8: 1.059 against
/// 1.052 rpm); away from resonance under 0.5 %. It does not come from torsim's
/// integrator (`--rtol 1e-7` moves it by 0.01 %) nor from the bench's wobble or noise
/// (the same run without either: 37.68 rpm at mass3). 2 % bounds it.
#[test]
fn none_controls_agree_with_the_model_order_by_order() {
    for seed in [0, 2] {
        let worst = worst_difference(seed);
        assert!(
            worst < 0.02,
            "seed {seed}: worst relative difference {worst}"
        );
    }
}
