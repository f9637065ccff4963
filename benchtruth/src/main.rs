//! `benchtruth draw` and `benchtruth bench` (issue 14, item 4).
use anyhow::Result;
use clap::{Parser, Subcommand};
use std::path::PathBuf;

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
        Cmd::Bench { torsim, seeds, out } => {
            let (a, b) = seeds
                .split_once("..")
                .ok_or_else(|| anyhow::anyhow!("--seeds must be A..B"))?;
            let (a, b): (u64, u64) = (a.trim().parse()?, b.trim().parse()?);
            std::fs::create_dir_all(&out)?;
            let mut rows = Vec::new();
            for seed in a..=b {
                let row =
                    benchtruth::bench::run_case(&torsim, seed, &out.join(format!("case-{seed}")));
                match &row.outcome {
                    Ok(o) => eprintln!(
                        "seed {seed}: {} ({}) -> {} [{}] {:.1} s",
                        o.truth,
                        row.form,
                        o.verdict,
                        if o.right { "right" } else { "wrong" },
                        row.seconds
                    ),
                    Err(e) => eprintln!("seed {seed}: error: {e}"),
                }
                rows.push(row);
            }
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
