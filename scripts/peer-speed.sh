#!/usr/bin/env bash
# torsim's time domain beside OpenTorsion's on one job, in one run (issue 15, items 2
# and 5): the linear 3-DOF driveline of benches/transient.rs, 3000 rpm, 20 s at
# 10240 Hz. Prints a Markdown table for the README:
#   - in-process: criterion's median of `simulate` against the median of
#     OpenTorsion's `dsim` (and its loop on the full state) over 5 runs in Python;
#   - CLI wall time, best of 3: `torsim simulate` (with its order analysis) against
#     `python scripts/peer_dsim.py --repeat 1` (interpreter start, import, one run).
# OpenTorsion goes into a venv of its own under target/ (PyPI), not into the system.
set -euo pipefail
cd "$(dirname "$0")/.."
venv=target/peer-venv
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet "opentorsion==0.3.2"
fi
cargo build --release --quiet --bin torsim
model=$(mktemp --suffix=.toml)
trap 'rm -f "$model"' EXIT
python3 - "$model" <<'PY'
import sys
text = open("benches/transient.rs").read()
start = text.index('r#"') + 3
open(sys.argv[1], "w").write(text[start:text.index('"#;', start)])
PY
bench_out=$(cargo bench --quiet --bench transient -- linear_3dof 2>/dev/null)
bench=$(grep -m1 "time:" <<< "$bench_out")
torsim_ms=$(echo "$bench" | sed -E 's/.*\[[^ ]+ [^ ]+ ([0-9.]+) ([mµ]s).*/\1 \2/')
peer=$("$venv/bin/python" scripts/peer_dsim.py --repeat 5)
wall() {
    local best=""
    for _ in 1 2 3; do
        local s e t
        s=$(date +%s.%N); "$@" > /dev/null; e=$(date +%s.%N)
        t=$(echo "$e - $s" | bc -l)
        if [ -z "$best" ] || [ "$(echo "$t < $best" | bc -l)" = 1 ]; then best=$t; fi
    done
    printf '%.3f' "$best"
}
torsim_wall=$(wall target/release/torsim simulate "$model" --speed-rpm 3000 --duration-s 20)
peer_wall=$(wall "$venv/bin/python" scripts/peer_dsim.py --repeat 1)
order1=$(target/release/torsim simulate "$model" --speed-rpm 3000 --duration-s 20 --json |
    python3 -c 'import json, sys; print(json.load(sys.stdin)["orders"]["engine"]["1"])')
python3 - "$torsim_ms" "$peer" "$torsim_wall" "$peer_wall" "$order1" <<'PY'
import json, sys
value, unit = sys.argv[1].split()
torsim_s = float(value) * (1e-3 if unit == "ms" else 1e-6)
peer = json.loads(sys.argv[2])
torsim_wall, peer_wall = float(sys.argv[3]), float(sys.argv[4])
dsim, full = peer["dsim"]["median_s"], peer["full_state"]["median_s"]
print("| job: linear 3-DOF, 20 s at 10240 Hz | torsim | OpenTorsion 0.3.2 | ratio |")
print("|---|---|---|---|")
print(f"| in-process, median | {torsim_s*1e3:.1f} ms ({20/torsim_s:.0f}× real time) "
      f"| `dsim` {dsim*1e3:.0f} ms; full state {full*1e3:.0f} ms | {dsim/torsim_s:.0f}×; {full/torsim_s:.0f}× |")
print(f"| CLI wall, best of 3 | {torsim_wall*1e3:.0f} ms (with the order analysis) "
      f"| {peer_wall*1e3:.0f} ms (start, import, one `dsim`) | {peer_wall/torsim_wall:.1f}× |")
print(f"| order-1 IAS of the engine | {float(sys.argv[5]):.3f} rpm | `dsim` {peer['dsim']['order1_rpm']:.3f} rpm; "
      f"full state {peer['full_state']['order1_rpm']:.3f} rpm | |")
PY
