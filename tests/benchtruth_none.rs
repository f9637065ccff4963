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
    let dir = std::env::temp_dir().join(format!("torsim-bt-none-{seed}-{}", std::process::id()));
    let files = benchtruth::write_case(seed, Some("none"), &dir).expect("case written");
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
    let _ = std::fs::remove_dir_all(&dir);
    worst
}

/// Before the bench held its rubbers' static stiffness and fitted them over each
/// recording's band, seed 0's order 3 differed by 32 % at the brake (1.81 against 2.39 rpm
/// at 1510 rpm); now by 0.3 % there. Near a resonance the two causal fits' small
/// difference is amplified: at 1290 rpm (order 3 within 9 % of the 59 Hz mode) seed 0
/// differs by up to 5.3 % (mass3 order 6: 1.808 against 1.711 rpm); 6 % bounds that.
#[test]
fn none_controls_agree_with_the_model_order_by_order() {
    for seed in [0, 2] {
        let worst = worst_difference(seed);
        assert!(
            worst < 0.06,
            "seed {seed}: worst relative difference {worst}"
        );
    }
}
