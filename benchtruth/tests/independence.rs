//! benchtruth must not depend on the torsim crate (issue 14, item 3): its truths reach
//! torsim only through files. Checked on cargo's resolved dependency graph.

use std::process::Command;

#[test]
fn benchtruth_does_not_depend_on_torsim() {
    // The host's platform only: other platforms' optional crates (the GUI's iOS
    // accessibility, say) need not be downloaded to resolve benchtruth's graph.
    let rustc = Command::new("rustc")
        .arg("-vV")
        .output()
        .expect("rustc -vV runs");
    let host = String::from_utf8_lossy(&rustc.stdout)
        .lines()
        .find_map(|l| l.strip_prefix("host: ").map(str::to_string))
        .expect("rustc names its host");
    let out = Command::new(env!("CARGO"))
        .args([
            "metadata",
            "--format-version",
            "1",
            "--offline",
            "--filter-platform",
            &host,
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo metadata runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let meta: serde_json::Value = serde_json::from_slice(&out.stdout).expect("metadata is JSON");
    let packages = meta["packages"].as_array().expect("packages");
    let id_of = |name: &str| {
        packages
            .iter()
            .find(|p| p["name"] == name)
            .and_then(|p| p["id"].as_str())
            .map(str::to_string)
    };
    let bench = id_of("benchtruth").expect("benchtruth is in the workspace");
    let torsim = id_of("torsim").expect("torsim is in the workspace");
    let nodes = meta["resolve"]["nodes"].as_array().expect("resolve");
    // Walk benchtruth's normal and build dependencies (not dev-dependencies of others).
    let mut seen = vec![bench.clone()];
    let mut stack = vec![bench];
    while let Some(id) = stack.pop() {
        let node = nodes.iter().find(|n| n["id"] == id.as_str()).expect("node");
        for d in node["deps"].as_array().into_iter().flatten() {
            let dev_only = d["dep_kinds"]
                .as_array()
                .is_some_and(|k| k.iter().all(|k| k["kind"] == "dev"));
            let dep = d["pkg"].as_str().unwrap_or_default().to_string();
            if !dev_only && !seen.contains(&dep) {
                seen.push(dep.clone());
                stack.push(dep);
            }
        }
    }
    assert!(
        !seen.contains(&torsim),
        "benchtruth's dependency graph contains torsim"
    );
    assert!(
        seen.len() > 3,
        "the walk found benchtruth's own dependencies"
    );
}
