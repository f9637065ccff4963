#!/usr/bin/env bash
# The diagnosis' accuracy on the shipped concealed cases (README table): runs
# `torsim diagnose --json` on each case's model and ten recordings, and prints one
# Markdown row per case: the truth (from truth.toml, which only this script and the
# tests read), the verdict, its fitted parameters, held-out χ²/N before → after, and the
# wall time. Usage: scripts/diagnosis-accuracy.sh [TORSIM_BINARY]
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:-target/release/torsim}"
[ -x "$bin" ] || cargo build --release --quiet
report=$(mktemp)
trap 'rm -f "$report"' EXIT
echo "| case | truth | verdict | fitted | held-out χ²/N before → after | time |"
echo "|---|---|---|---|---|---|"
for dir in tests/data/diagnosis/*/; do
  case=$(basename "$dir")
  [ -f "$dir/truth.toml" ] || continue
  truth=$(python3 -c "import tomllib,sys; print(tomllib.load(open(sys.argv[1],'rb'))['effect']['name'])" "$dir/truth.toml")
  start=$(date +%s.%N)
  # The report (with its overlays) is too long for an environment variable: a file.
  "$bin" diagnose "$dir/model.toml" "$dir"/*.csv --json > "$report"
  end=$(date +%s.%N)
  python3 - "$case" "$truth" "$start" "$end" "$report" <<'PY'
import json, sys
case, truth, t0, t1 = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
r = json.load(open(sys.argv[5]))
v = r["verdict"]
params = ", ".join(f"{k} = {x:.4g}" if isinstance(x, (int, float)) else f"{k} = {x}"
                   for k, x in v["parameters"].items())
mark = "" if v["effect"] == truth else " (wrong)"
print(f"| `{case}` | {truth} | {v['effect']}{mark} | {params} | "
      f"{r['fit']['before']:.2f} → {r['fit']['after']:.2f} | {t1 - t0:.0f} s |")
PY
done
