#!/usr/bin/env bash
# The diagnosis' speed on the issue's reference campaign: `torsim synth` makes ten
# recordings of the diagnosis bench (its default plan: eight regimes of 4 s, a 30 s long
# run and a 60 s run-up at 2048 Hz, two stations) with one effect and ±5 % plain errors
# (none for `none`),
# then `torsim diagnose` is timed on them. Usage: scripts/diagnosis-speed.sh [EFFECT]
# (default gear_backlash) [TORSIM_BINARY].
set -euo pipefail
cd "$(dirname "$0")/.."
effect="${1:-gear_backlash}"
bin="${2:-target/release/torsim}"
[ -x "$bin" ] || cargo build --release --quiet
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# `none` means no plain errors either.
pct=5
[ "$effect" = none ] && pct=0
"$bin" synth tests/data/diagnosis/none/model.toml --effect "$effect" \
  --param-error-pct "$pct" --seed 7 --out "$dir" > /dev/null
start=$(date +%s.%N)
"$bin" diagnose "$dir/model.toml" "$dir"/*.csv --json > "$dir/report.json"
end=$(date +%s.%N)
python3 - "$dir/report.json" "$effect" "$start" "$end" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
v = r["verdict"]
print(f"truth {sys.argv[2]}: verdict {v['effect']} {v['parameters']}, held-out χ²/N "
      f"{r['fit']['before']:.2f} → {r['fit']['after']:.2f}, "
      f"{float(sys.argv[4]) - float(sys.argv[3]):.1f} s")
PY
