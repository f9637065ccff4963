#!/usr/bin/env bash
# Idle CPU of the real window (issue 16): starts the release build on a preset under a
# virtual X display, leaves it alone for WARMUP s, then reads the process' CPU time from
# /proc over SECONDS_IDLE s and prints it as a percentage of one core.
# Needs Xvfb (Debian package xvfb). Usage: scripts/gui-idle-cpu.sh [preset] [seconds]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-cng-genset}"
seconds_idle="${2:-20}"
warmup=8
bin=target/release/torsim
[[ -x $bin ]] || cargo build --release --bin torsim
display=:$((90 + RANDOM % 9))
Xvfb "$display" -screen 0 1280x800x24 >/dev/null 2>&1 &
xvfb=$!
home="$(mktemp -d)"
app=
# The window goes first and is waited for, then the display: killed the other way round,
# the window lost its display mid-frame and printed a segfault.
cleanup() {
    if [[ -n $app ]]; then
        kill "$app" 2>/dev/null || true
        wait "$app" 2>/dev/null || true
    fi
    kill "$xvfb" 2>/dev/null || true
    rm -rf "$home"
}
trap cleanup EXIT
sleep 1
DISPLAY=$display HOME=$home "$bin" "preset:$preset" >/dev/null 2>&1 &
app=$!
sleep "$warmup"
ticks() { awk '{print $14 + $15}' "/proc/$app/stat"; }
t0=$(ticks)
sleep "$seconds_idle"
t1=$(ticks)
hz=$(getconf CLK_TCK)
awk -v a="$t0" -v b="$t1" -v s="$seconds_idle" -v hz="$hz" -v p="$preset" \
    'BEGIN { printf "%s: idle window %.2f %% of one core over %d s\n", p, 100 * (b - a) / hz / s, s }'
