//! `benchtruth draw` and `benchtruth bench` (issue 14, item 4).
use anyhow::Result;
use clap::{Parser, Subcommand};
use std::path::PathBuf;

#[derive(Parser)]
#[command(name = "benchtruth", about = "An independent test bench for torsim's diagnosis")]
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
}

fn main() -> Result<()> {
    match Cli::parse().cmd {
        Cmd::Draw { seed, out, class } => {
            let f = benchtruth::write_case(seed, class.as_deref(), &out)?;
            println!("{} ({}) -> {}: {} recordings", f.class, f.form, out.display(), f.recordings.len());
        }
    }
    Ok(())
}
