//! `benchtruth draw` and `benchtruth bench` (issue 14, item 4).
use anyhow::Result;
use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

#[derive(Parser)]
#[command(
    name = "benchtruth",
    about = "An independent test bench for torsim's diagnosis"
)]
struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
}

#[derive(Subcommand)]
enum Cmd {
    /// Draws one case (model, recordings, truth.toml) into DIR.
    Draw {
        #[arg(long)]
        seed: u64,
        #[arg(long)]
        out: PathBuf,
        /// Forces the effect class (a spec/diagnosis.md name); default: seed mod 11.
        #[arg(long)]
        class: Option<String>,
    },
    /// Draws the cases of seeds A..B (inclusive), diagnoses each with `torsim diagnose`,
    /// prints the confusion matrix and writes summary.md and results.csv into DIR.
    Bench {
        #[arg(long)]
        torsim: PathBuf,
        /// A..B, inclusive
        #[arg(long)]
        seeds: String,
        #[arg(long)]
        out: PathBuf,
        /// Cases drawn and diagnosed at once (default 1). Above 1 the cases share the
        /// cores, so the time per case printed is no longer that of an idle machine.
        #[arg(long, default_value_t = 1)]
        jobs: usize,
    },
}

fn main() -> Result<()> {
    match Cli::parse().cmd {
        Cmd::Draw { seed, out, class } => {
            let f = benchtruth::write_case(seed, class.as_deref(), &out)?;
            println!(
                "{} ({}) -> {}: {} recordings",
                f.class,
                f.form,
                out.display(),
                f.recordings.len()
            );
        }
        Cmd::Bench {
            torsim,
            seeds,
            out,
            jobs,
        } => {
            let (a, b) = seeds
                .split_once("..")
                .ok_or_else(|| anyhow::anyhow!("--seeds must be A..B"))?;
            let (a, b): (u64, u64) = (a.trim().parse()?, b.trim().parse()?);
            std::fs::create_dir_all(&out)?;
            let seeds: Vec<u64> = (a..=b).collect();
            let next = AtomicUsize::new(0);
            let rows = Mutex::new(Vec::new());
            std::thread::scope(|scope| {
                for _ in 0..jobs.max(1) {
                    scope.spawn(|| {
                        while let Some(&seed) = seeds.get(next.fetch_add(1, Ordering::Relaxed)) {
                            let dir = out.join(format!("case-{seed}"));
                            let row = benchtruth::bench::run_case(&torsim, seed, &dir);
                            report(&row);
                            if let Ok(mut rows) = rows.lock() {
                                rows.push(row);
                            }
                        }
                    });
                }
            });
            let mut rows = rows.into_inner().unwrap_or_default();
            rows.sort_by_key(|r| r.seed);
            let md = benchtruth::bench::summary(&rows, a, b);
            std::fs::write(out.join("summary.md"), &md)?;
            std::fs::write(
                out.join("results.csv"),
                benchtruth::bench::results_csv(&rows),
            )?;
            println!("{md}");
        }
    }
    Ok(())
}

/// One progress line per finished case, on stderr.
fn report(row: &benchtruth::bench::Row) {
    match &row.outcome {
        Ok(o) => eprintln!(
            "seed {}: {} ({}) -> {} [{}] {:.1} s{}{}",
            row.seed,
            o.truth,
            row.form,
            o.verdict,
            if o.right { "right" } else { "wrong" },
            row.seconds,
            row.exercised
                .map_or(String::new(), |v| format!(", exercised {v:.3}")),
            row.visible_z
                .map_or(String::new(), |v| format!(", visible z {v:.1}"))
        ),
        Err(e) => eprintln!("seed {}: error: {e}", row.seed),
    }
}
