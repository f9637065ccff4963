#!/usr/bin/env bash
# Edit-to-plot latency of the real window (issue 16): starts the release build on a
# preset under a virtual X display with TORSIM_LOG_LATENCY=1, waits WAIT s (the first
# time run finishes), then types new values into the first inertia's J field, one every
# 3 s, and prints the window's own measurement of each edit (from the edit to the end of
# the first frame that draws the edited model's Campbell diagram).
# Needs Xvfb and xdotool (Debian packages xvfb, xdotool).
# Usage: scripts/gui-latency.sh [preset] [wait_s]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-genset-20dof}"
wait_s="${2:-20}"
bin=target/release/torsim
[[ -x $bin ]] || cargo build --release --bin torsim
display=:$((80 + RANDOM % 9))
Xvfb "$display" -screen 0 1280x800x24 >/dev/null 2>&1 &
xvfb=$!
home="$(mktemp -d)"
log="$home/latency.log"
trap 'kill $app $xvfb 2>/dev/null || true; rm -rf "$home"' EXIT
sleep 1
export DISPLAY=$display
HOME=$home TORSIM_LOG_LATENCY=1 "$bin" "preset:$preset" 2>"$log" >/dev/null &
app=$!
sleep "$wait_s"
window=$(xdotool search --name torsim | head -1)
xdotool windowfocus "$window"
# The first inertia's J field at 1280 x 800 (row 1 of the Inertias table).
xdotool mousemove 160 355 click --repeat 2 1
sleep 0.5
for value in 0.2 0.15 0.1 0.25 0.12; do
    xdotool key ctrl+a
    xdotool type --delay 50 "$value"
    sleep 3
done
xdotool key Return
sleep 2
grep "torsim latency" "$log" || echo "no edit was measured" >&2
