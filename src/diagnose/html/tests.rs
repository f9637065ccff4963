//! The page on hand-made reports: escaping, one heatmap cell per map cell, overlays with
//! gaps, the verdict's row.

use super::super::report::*;
use super::report_html;
use std::collections::BTreeMap;

fn cell(recording: &str, station: &str, order: f64, speed_rpm: f64, z: f64) -> MapCell {
    MapCell {
        recording: recording.into(),
        station: station.into(),
        order,
        speed_rpm,
        z,
    }
}

fn candidate(effect: &str, score: f64) -> Candidate {
    Candidate {
        effect: effect.into(),
        parameters: BTreeMap::from([
            ("a2".to_string(), ParameterValue::Number(0.015)),
            ("scale.coupling".to_string(), ParameterValue::Number(0.97)),
        ]),
        score,
        residual_before: 3.1,
        residual_after: score,
        residual_fitted: 0.9,
        parameter_count: 2,
        signature: "order 2 changes with load".into(),
        verified: true,
        rejected: None,
        rejected_steps: Vec::new(),
        set_aside: None,
    }
}

fn recording(label: &str, kind: &str, speed_rpm: [f64; 2], role: &str) -> RecordingUse {
    RecordingUse {
        label: label.into(),
        kind: kind.into(),
        speed_rpm,
        load: 1.0,
        role: role.into(),
        set_aside: None,
    }
}

/// A report with steady regimes (two at one speed), a long run of three blocks and a
/// 40-bin run-up at station `engine`, and four cells at station `coupling_es`.
fn sample() -> Report {
    let mut map = Vec::new();
    for (label, speed) in [
        ("Regime A", 3000.0),
        ("Regime C", 3960.0),
        ("Regime C, 30 % load", 3960.0),
    ] {
        for order in [1.0, 2.0, 4.0] {
            map.push(cell(label, "engine", order, speed, 1.5 * order - 3.0));
        }
    }
    for block in 0..3 {
        for order in [1.0, 2.0, 4.0] {
            map.push(cell(
                "Long run",
                "engine",
                order,
                3961.0 + block as f64,
                0.5 * block as f64,
            ));
        }
    }
    for bin in 0..40 {
        for order in [1.0, 2.0, 4.0] {
            let speed = 1000.0 + 125.0 * bin as f64;
            map.push(cell(
                "Run-up",
                "engine",
                order,
                speed,
                (speed - 3000.0) / 200.0,
            ));
        }
    }
    for order in [0.5, 1.0, 1.5, 2.0] {
        map.push(cell("Regime A", "coupling_es", order, 3000.0, -order));
    }
    Report {
        format: REPORT_FORMAT,
        verdict: Verdict {
            effect: "coupling_amplitude_nonlinearity".into(),
            confidence: 0.9,
            parameters: BTreeMap::from([
                ("a2".to_string(), ParameterValue::Number(0.015)),
                (
                    "temperature_rise_c".to_string(),
                    ParameterValue::Number(12.0),
                ),
                (
                    "connection".to_string(),
                    ParameterValue::Text("coupling".into()),
                ),
            ]),
            explanation: "The coupling stiffens with twist.".into(),
            equivalent_places: Vec::new(),
        },
        mismatches: vec![Mismatch {
            recording: "Regime A".into(),
            station: "coupling_es".into(),
            order: "2".into(),
            speed_rpm: 3000.0,
            frequency_hz: 100.0,
            measured: 12.1,
            simulated: 7.3,
            quantity: "ias_amplitude_rpm".into(),
            z: 16.0,
        }],
        candidates: vec![
            candidate("coupling_amplitude_nonlinearity", 0.06),
            candidate("parameter_error", 0.4),
            candidate("none", 3.1),
        ],
        fit: Fit {
            metric: "held-out χ² per amplitude".into(),
            before: 3.1,
            after: 0.06,
            validated_on: vec!["Regime C".into(), "Long run (second half)".into()],
            swapped_because: None,
        },
        mismatch_map: map,
        unexplained_resonances: vec![],
        overlays: vec![Overlay {
            recording: "Run-up".into(),
            station: "engine".into(),
            order: "2".into(),
            x_label: "speed [rpm]".into(),
            x: vec![1000.0, 2000.0, 3000.0],
            measured: vec![1.0, 2.0, 1.5],
            sigma: vec![0.1, 0.1, 0.1],
            before: vec![1.2, 2.5, 1.4],
            after: vec![1.0, 2.1, 1.5],
        }],
        recordings: vec![
            recording("Regime A", "steady", [3000.0, 3000.0], "fit"),
            recording("Regime C", "steady", [3960.0, 3960.0], "held out"),
            recording("Regime C, 30 % load", "steady", [3960.0, 3960.0], "fit"),
            recording(
                "Long run",
                "long run",
                [3960.0, 3960.0],
                "fit (first half), held out (second half)",
            ),
            recording("Run-up", "run-up", [1000.0, 6000.0], "fit"),
        ],
        noise_rpm: 0.05,
        not_fitted: Vec::new(),
        elapsed_s: 12.5,
    }
}

/// The `<svg class="map" …>` of one station.
fn map_svg<'a>(page: &'a str, station: &str) -> &'a str {
    let start = page
        .find(&format!("<svg class=\"map\" data-station=\"{station}\""))
        .unwrap_or_else(|| panic!("no map of {station}"));
    let end = start + page[start..].find("</svg>").expect("closed");
    &page[start..end]
}

#[test]
fn one_heatmap_cell_per_map_cell() {
    let report = sample();
    let page = report_html(&report, "bench");
    for station in ["engine", "coupling_es"] {
        let expected = report
            .mismatch_map
            .iter()
            .filter(|c| c.station == station)
            .count();
        let svg = map_svg(&page, station);
        assert_eq!(
            svg.matches("<rect class=\"cell\"").count(),
            expected,
            "{station}"
        );
        assert_eq!(svg.matches("<title>").count(), expected + 1, "{station}");
    }
    assert_eq!(page.matches("<svg class=\"map\"").count(), 2);
    // The run-up has its own panel; the steady ones share one, numbered as the table.
    let engine = map_svg(&page, "engine");
    assert!(engine.contains("Run-up [5]: speed bins"));
    assert!(engine.contains("steady regimes and long runs"));
    // A cell's hover title carries its numbers: order 2 at 3000 rpm is 100 Hz.
    assert!(
        engine.contains("<title>Regime A · engine · order 2 · 3000 rpm · 100.0 Hz · z = 0</title>")
    );
}

#[test]
fn every_text_is_escaped() {
    let mut report = sample();
    report.verdict.explanation = "k < 5 & \"x\" > 2 <script>alert(1)</script>".into();
    report.mismatch_map[0].station = "a<b".into();
    report.mismatches[0].recording = "R&D <1>".into();
    report.candidates[1].signature = "\"quoted\" <i>".into();
    report.overlays[0].x_label = "time [s] <&>".into();
    let page = report_html(&report, "<Model & \"Co\">");
    assert!(!page.contains("<script"), "raw markup leaked");
    assert!(!page.contains("<i>") && !page.contains("<1>") && !page.contains("a<b"));
    assert!(page.contains("k &lt; 5 &amp; &quot;x&quot; &gt; 2 &lt;script&gt;"));
    assert!(page.contains("<title>torsim diagnosis — &lt;Model &amp; &quot;Co&quot;&gt;</title>"));
    assert!(page.contains("data-station=\"a&lt;b\""));
    assert!(page.contains("R&amp;D &lt;1&gt;"));
    assert!(page.contains("time [s] &lt;&amp;&gt;"));
    // Every `&` in the page starts an entity.
    for (i, _) in page.match_indices('&') {
        let rest = &page[i..];
        assert!(
            ["&amp;", "&lt;", "&gt;", "&quot;", "&#39;"]
                .iter()
                .any(|e| rest.starts_with(e)),
            "bare & at {}",
            &page[i..(i + 12).min(page.len())]
        );
    }
}

#[test]
fn overlays_with_gaps_or_no_data_keep_the_page_whole() {
    let mut report = sample();
    let mut gappy = report.overlays[0].clone();
    gappy.x = vec![1000.0, f64::NAN, 3000.0, 4000.0];
    gappy.measured = vec![f64::NAN, 2.0, f64::INFINITY, 1.0];
    gappy.sigma = vec![0.1];
    gappy.before = vec![1.0, 2.0];
    gappy.after = vec![];
    let mut empty = report.overlays[0].clone();
    empty.x.clear();
    empty.measured.clear();
    empty.sigma.clear();
    empty.before.clear();
    empty.after.clear();
    let mut all_nan = report.overlays[0].clone();
    all_nan.measured = vec![f64::NAN; 3];
    all_nan.before = vec![f64::NAN; 3];
    all_nan.after = vec![f64::NAN; 3];
    report.overlays.extend([gappy, empty, all_nan]);
    report.fit.after = f64::NAN;
    report
        .mismatch_map
        .push(cell("Regime A", "engine", 8.0, 3000.0, f64::NAN));
    let page = report_html(&report, "bench");
    assert_eq!(page.matches("<svg class=\"overlay\"").count(), 4);
    assert_eq!(page.matches("<svg").count(), page.matches("</svg>").count());
    assert_eq!(
        page.matches("no data").count(),
        2,
        "the empty and the all-NaN overlay"
    );
    for bad in ["NaN", "=\"inf", "=\"-inf", "inf rpm"] {
        assert!(!page.contains(bad), "`{bad}` in the page");
    }
    assert!(page.trim_end().ends_with("</html>"));
    // The gappy overlay: measured points only where x and the value are finite (one).
    let start = page
        .match_indices("<svg class=\"overlay\"")
        .nth(1)
        .expect("second")
        .0;
    let svg = &page[start..start + page[start..].find("</svg>").expect("closed")];
    assert_eq!(
        svg.matches("<circle").count(),
        2,
        "the legend's and one point"
    );
}

#[test]
fn the_verdict_row_is_highlighted() {
    let mut report = sample();
    report.verdict.effect = "parameter_error".into();
    let page = report_html(&report, "bench");
    assert_eq!(page.matches("<tr class=\"verdict\">").count(), 1);
    let row = page.split("<tr class=\"verdict\">").nth(1).expect("row");
    let row = &row[..row.find("</tr>").expect("closed")];
    assert!(row.contains("<code>parameter_error</code>"), "{row}");
    assert!(row.starts_with("<td class=\"num\">2</td>"), "rank 2: {row}");
    // No candidate of the verdict's effect: nothing highlighted.
    report.verdict.effect = "gear_backlash".into();
    assert!(!report_html(&report, "bench").contains("<tr class=\"verdict\">"));
}

#[test]
fn the_page_is_self_contained_and_complete() {
    let page = report_html(&sample(), "bench");
    for forbidden in ["<script", "http://", "https://", "src=", "<link", "@import"] {
        let hits = page.matches(forbidden).count();
        let allowed = if forbidden == "http://" {
            page.matches("xmlns=\"http://www.w3.org/2000/svg\"").count()
        } else {
            0
        };
        assert_eq!(hits, allowed, "{forbidden}");
    }
    for needle in [
        "The rubber stiffness depends on the deflection",
        "held-out χ² per amplitude: <b>3.10 → 0.0600</b> (52× lower) on held-out data: Regime C; Long run (second half)",
        "k·ln(n)/n",
        "<td><code>temperature_rise_c</code></td><td class=\"num\">12.00</td><td>°C</td>",
        "<td><code>connection</code></td><td class=\"num\">coupling</td>",
        "a2 = 0.01500<br>scale.coupling = 0.9700",
        "<td class=\"num\">1000 → 6000</td>",
        "None: every resonance",
        "before: your model",
    ] {
        assert!(page.contains(needle), "missing {needle}");
    }
}

#[test]
fn a_recording_set_aside_shows_its_reason_and_keeps_the_numbering() {
    let mut report = sample();
    let mut aside = recording("Regime 0", "steady", [1150.0, 1150.0], "set aside");
    aside.set_aside = Some("the reference speed is not > 0 at 0.021484 s".into());
    report.recordings.insert(0, aside);
    let page = report_html(&report, "bench");
    assert!(
        page.contains("<td>set aside: the reference speed is not &gt; 0 at 0.021484 s</td>"),
        "the row gives the reason"
    );
    // The map numbers the runs as the table does: the run-up is now the sixth.
    assert!(map_svg(&page, "engine").contains("Run-up [6]: speed bins"));
}
