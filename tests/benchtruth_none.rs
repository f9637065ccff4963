//! The independent bench's truths against torsim, order by order (issue 14, item 4):
//! for fixed seeds, `torsim simulate` of a model of the bench's truth at each steady
//! regime's speed and load must give the order amplitudes that `torsim analyse` reads
//! from the bench's recording, station by station.
//! - The `none` control: the user's model is the truth up to the noise.
//! - A softened-backlash case: the truth's gear, with its mesh damping and its play, in
//!   torsim's keys (`mesh_damping`, `backlash_deg`, `backlash_softening_deg`), which the
//!   bench's model files do not write. Two simulators written apart agree on a gear
//!   rattling in its play only if they read the spec alike; this one found that the
//!   bench took the nodes' damping to the frame as a drag on the mean speed
//!   (`benchtruth/src/plant.rs`).

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

/// `(bench, model)` amplitudes of every order above 1 rpm (≥ 20× the bench's largest
/// noise level of 0.05 rpm after averaging) at the recording's stations, at the first
/// three recordings with a steady speed.
/// `model_of` gives the model file to simulate from the case's folder (default: the
/// user's model the bench wrote).
fn compared_amplitudes(
    seed: u64,
    class: &str,
    model_of: &dyn Fn(&Path, &benchtruth::CaseFiles) -> std::path::PathBuf,
) -> Vec<(f64, f64)> {
    let scratch = tempfile::Builder::new()
        .prefix(&format!("torsim-bt-{class}-{seed}-"))
        .tempdir()
        .expect("temp dir");
    let dir = scratch.path();
    let files = benchtruth::write_case(seed, Some(class), dir).expect("case written");
    let model = model_of(dir, &files).to_string_lossy().into_owned();
    let mut compared = Vec::new();
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
                    eprintln!(
                        "seed {seed} {} {station} order {order}: bench {measured:.3}, model {simulated:.3}",
                        csv.display()
                    );
                    compared.push((measured, simulated));
                }
            }
        }
    }
    assert!(
        !compared.is_empty(),
        "seed {seed}: nothing above 1 rpm compared"
    );
    compared
}

/// The bench fits its truth rubbers by the model's own rule (one causal chain per stage,
/// fitted over the model's band and at its nominal modes weighted by strain-energy
/// share), implemented independently in `benchtruth/src/{fitpoints,visco,nnls}.rs`; its
/// chains' deviations from the law at seed 0's modes are within 0.1 points of those
/// `torsim modes` reports (coupling1 at the first mode: −0.54 against −0.55 % in
/// stiffness). Measured: worst 0.72 % for seed 0 (`regime-b` at 1290 rpm, brake order 3
/// at 64.5 Hz, 9 % above the 59 Hz mode, where a difference in that mode's frequency is
/// amplified about 12-fold: 11.048 against 10.968 rpm), 0.57 % for seed 2 (`regime-c`
/// crank order 8: 1.058 against 1.052 rpm). Until the bench stopped taking the nodes'
/// damping to the frame as a drag on the mean speed (2026-11-29) they were 1.56 % and
/// 0.66 %. It does not come from torsim's integrator (`--rtol 1e-7` moves it by 0.01 %)
/// nor from the bench's wobble or noise. 2 % bounds it.
#[test]
fn none_controls_agree_with_the_model_order_by_order() {
    for seed in [0, 2] {
        let worst = compared_amplitudes(seed, "none", &|_, files| files.model.clone())
            .iter()
            .map(|(bench, model)| (model / bench - 1.0).abs())
            .fold(0.0, f64::max);
        assert!(
            worst < 0.02,
            "seed {seed}: worst relative difference {worst}"
        );
    }
}

/// The truth of a softened-backlash case as a torsim model: the bench's nominal data
/// (no plain errors) with its gear's mesh damping, play and softening.
fn backlash_truth(seed: u64, dir: &Path) -> std::path::PathBuf {
    use benchtruth::driveline::Kind;
    use benchtruth::effects::{BacklashLaw, Effect};
    let case = benchtruth::draw::draw_case(seed, Some("gear_backlash")).expect("drawn");
    let Effect::GearBacklash {
        conn,
        law: BacklashLaw::Softened { half_rad, eps_rad },
    } = case.effect
    else {
        panic!("seed {seed}: not a softened backlash: {:?}", case.effect);
    };
    let Kind::Gear { mesh_damping, .. } = case.truth.connections[conn].kind else {
        panic!("seed {seed}: connection {conn} is no gear");
    };
    let (lo, hi) = benchtruth::fitpoints::speed_range_rpm(&case.campaign);
    let text = benchtruth::model_file::model_toml(&case.truth, lo, hi);
    let name = format!("name = \"{}\"\n", case.truth.connections[conn].name);
    let at = text.find(&name).expect("the gear's section") + name.len();
    let keys = format!(
        "mesh_damping = {mesh_damping:e}\nbacklash_deg = {:e}\nbacklash_softening_deg = {:e}\n",
        (2.0 * half_rad).to_degrees(),
        eps_rad.to_degrees()
    );
    let path = dir.join("truth-model.toml");
    std::fs::write(&path, format!("{}{keys}{}", &text[..at], &text[at..])).expect("written");
    path
}

/// Development seed 2087: a 3-node driveline whose 1.54 gear has 0.195° of play softened
/// over 0.021°. At the three regimes compared its teeth rattle through the play (Regime
/// A, 12 % of the time inside it), sit half in it (B, 58 %) and float in it on the
/// softening (C, 100 %). Where the teeth separate, the small orders are sensitive to
/// everything: Regime A's order 6 at `mass1` is 1.48 rpm on the bench and 1.97 in torsim.
/// So the check is on the amplitude-weighted difference Σ|model − bench| / Σ bench over
/// the orders above 1 rpm: 0.87 % over 42 orders. With the bench's former drag on the
/// mean speed it was 5.3 % (43 orders), so 2 % bounds it and tells the two apart.
#[test]
fn a_softened_backlash_truth_agrees_with_the_model_order_by_order() {
    let pairs = compared_amplitudes(2087, "gear_backlash", &|dir, _| backlash_truth(2087, dir));
    let off: f64 = pairs.iter().map(|(b, m)| (m - b).abs()).sum();
    let total: f64 = pairs.iter().map(|(b, _)| b).sum();
    eprintln!(
        "{} orders, weighted difference {}",
        pairs.len(),
        off / total
    );
    assert!(
        off / total < 0.02,
        "weighted relative difference {}",
        off / total
    );
}
