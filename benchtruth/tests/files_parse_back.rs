//! The written files parse back with a reader of this test's own (recording-format.md):
//! a `time_s` column printed to the microsecond on a uniform grid, one finite speed
//! column per sensor of the sidecar, and a steady recording's mean reference speed
//! within 0.2 % of the sidecar's `speed_rpm` (the dyno holds the speed; the slow wobble
//! is at most 0.1 %, see `campaign.rs`).

use std::path::Path;

/// A CSV of `time_s` and `<node>_rpm` columns: (header, rows).
fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).expect("csv readable");
    let mut lines = text.lines();
    let header: Vec<String> = lines
        .next()
        .expect("a header")
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|v| v.parse::<f64>().expect("a number"))
                .collect::<Vec<_>>()
        })
        .collect();
    (header, rows)
}

/// `key = value` of the sidecar's top table (before the first `[section]`).
fn sidecar_value(text: &str, key: &str) -> Option<String> {
    text.lines()
        .take_while(|l| !l.starts_with('['))
        .find_map(|l| {
            let (k, v) = l.split_once('=')?;
            (k.trim() == key).then(|| v.trim().trim_matches('"').to_owned())
        })
}

fn check_case(seed: u64, class: Option<&str>) {
    // Removed with its files when the test ends.
    let dir = tempfile::Builder::new()
        .prefix(&format!(
            "benchtruth-parse-{seed}-{}-",
            class.unwrap_or("any")
        ))
        .tempdir()
        .expect("temp dir");
    let files = benchtruth::write_case(seed, class, dir.path()).expect("case written");
    assert!(!files.recordings.is_empty());
    let mut steady = 0;
    for csv in &files.recordings {
        let side = std::fs::read_to_string(csv.with_extension("toml")).expect("sidecar");
        let (header, rows) = read_csv(csv);
        assert_eq!(header[0], "time_s");
        let sensors: Vec<&str> = side
            .lines()
            .filter_map(|l| l.strip_prefix("[sensors.")?.strip_suffix(']'))
            .collect();
        let columns: Vec<String> = sensors.iter().map(|s| format!("{s}_rpm")).collect();
        assert_eq!(header[1..], columns[..], "{}", csv.display());
        assert!(rows.len() > 100);
        // Microsecond time stamps on a uniform grid: every step within 1 µs (the
        // printing's rounding) of the mean step.
        let dt = (rows[rows.len() - 1][0] - rows[0][0]) / (rows.len() - 1) as f64;
        for w in rows.windows(2) {
            assert_eq!(w[1].len(), header.len());
            assert!(
                ((w[1][0] - w[0][0]) - dt).abs() <= 1.001e-6,
                "{}",
                csv.display()
            );
            assert!(w[1].iter().all(|v| v.is_finite()));
        }
        let reference = sidecar_value(&side, "reference").expect("reference");
        let col = header
            .iter()
            .position(|h| *h == format!("{reference}_rpm"))
            .expect("the reference is a station");
        if let Some(speed) = sidecar_value(&side, "speed_rpm") {
            let speed: f64 = speed.parse().expect("speed_rpm a number");
            let mean = rows.iter().map(|r| r[col]).sum::<f64>() / rows.len() as f64;
            assert!(
                (mean / speed - 1.0).abs() < 2e-3,
                "seed {seed} {}: mean {mean} rpm against the sidecar's {speed}",
                csv.display()
            );
            steady += 1;
        }
    }
    assert!(
        steady >= 3,
        "seed {seed}: a campaign has 3–8 steady regimes"
    );
}

#[test]
fn a_none_control_parses_back_and_holds_its_speeds() {
    check_case(0, Some("none"));
}

/// A draw where a node nearly stops or turns backwards is no bench (an engine would stall
/// there), so the seed is drawn again and the set-aside draw is named in `truth.toml`.
/// Seed 100585 (a published case, fixed here as a bench's regression, not a diagnosis'
/// test) reached −56 rpm at the crank in its first draw's run-up; it leaves 25 % of its
/// mean speed 1.25 s into that run-up.
#[test]
fn a_crank_that_turns_backwards_is_drawn_again() {
    let (_dir, files, _truth, first) = redrawn_case(100_585);
    assert_eq!(first.matches("seed 100585 draw").count() as u64, files.draw);
    assert!(
        first.contains("seed 100585 draw 0: node `crank`")
            && first.contains("nearly stops in `run-up`")
            && first.contains("of its mean speed, outside 1 ± 0.75"),
        "{first}"
    );
}

/// Writes the case of `seed`, which must have been drawn again, into a directory removed
/// when the returned guard drops: (guard, files, `truth.toml`, its `redrawn_because`).
/// `truth.toml` names the draw written.
fn redrawn_case(seed: u64) -> (tempfile::TempDir, benchtruth::CaseFiles, String, String) {
    let dir = tempfile::Builder::new()
        .prefix(&format!("benchtruth-redrawn-{seed}-"))
        .tempdir()
        .expect("temp dir");
    let files = benchtruth::write_case(seed, None, dir.path()).expect("redrawn");
    assert!(files.draw >= 1, "draw {}", files.draw);
    let truth = std::fs::read_to_string(&files.truth).expect("truth.toml");
    assert_eq!(
        sidecar_value(&truth, "draw"),
        Some(files.draw.to_string()),
        "{truth}"
    );
    let first = sidecar_value(&truth, "redrawn_because").expect("redrawn_because");
    (dir, files, truth, first)
}

/// A draw whose campaign cannot show its effect is no case for a diagnosis: no reader
/// could name what the recordings do not hold. The bench measures that itself
/// (`visibility.rs`: the effect's truth against its twin without the effect, order by
/// order against the noise) and draws again. Development seed 2104 (the frequency
/// law) changes no order amplitude by more than z = 2.9 in its first draw; the kept
/// draw shows its effect and says so in `[visibility]`.
#[test]
fn a_campaign_that_cannot_show_its_effect_is_drawn_again() {
    let (_dir, files, truth, first) = redrawn_case(2104);
    assert!(
        first.contains("seed 2104 draw 0: the campaign cannot show its effect"),
        "{first}"
    );
    let visible = files.visibility.as_ref().expect("an effect's visibility");
    assert!(
        visible.z_max >= benchtruth::visibility::MIN_VISIBLE_Z,
        "kept draw z = {}",
        visible.z_max
    );
    let section = truth
        .split("[visibility]")
        .nth(1)
        .expect("a [visibility] section");
    let z: f64 = sidecar_value(section, "z_max")
        .expect("z_max")
        .parse()
        .expect("z_max a number");
    assert_eq!(z, visible.z_max);
}
