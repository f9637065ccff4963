#!/usr/bin/env bash
# The diagnosis benchmark of issue 14, item 4: builds torsim and benchtruth in release,
# draws N independent cases from FIRST_SEED on (default 100000, a range never used for
# tuning; development uses seeds < 1000), diagnoses each and prints the confusion
# matrix. Writes summary.md and results.csv into target/diagnosis-benchmark/.
# Usage: [JOBS=2] scripts/diagnosis-benchmark.sh N [FIRST_SEED]   (JOBS: cases at once, default 1;
# above 1 the cases share the cores and the time per case is no longer an idle machine's)
set -euo pipefail
n=${1:?usage: diagnosis-benchmark.sh N [FIRST_SEED]}
first=${2:-100000}
last=$((first + n - 1))
cd "$(dirname "$0")/.."
target=${CARGO_TARGET_DIR:-target}
cargo build --release --bin torsim -p torsim
cargo build --release -p benchtruth
out="$target/diagnosis-benchmark"
"$target/release/benchtruth" bench --torsim "$target/release/torsim" --seeds "$first..$last" --out "$out" --jobs "${JOBS:-1}"
