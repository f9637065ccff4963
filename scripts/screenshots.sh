#!/usr/bin/env bash
# Retakes the README's screenshots from the release build under a virtual X display at
# 1280 x 800 (issue 16: the screenshots are of the current build). Each shot starts the
# window on a preset with a fresh HOME (no last session), drives it with xdotool at the
# positions of the 1280 x 800 layout, and writes assets/gui-*.png.
# Needs Xvfb, xdotool and ImageMagick's import (Debian: xvfb xdotool imagemagick).
# The Diagnosis shot also needs a file dialog (zenity) and is taken by hand; see README.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=target/release/torsim
[[ -x $bin ]] || cargo build --release --bin torsim
display=:$((70 + RANDOM % 9))
Xvfb "$display" -screen 0 1280x800x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
export DISPLAY=$display
sleep 1

# shot NAME PRESET SETTLE_S [xdotool steps, each "x y wait_s"]...
shot() {
    local name=$1 preset=$2 settle=$3
    shift 3
    local home
    home="$(mktemp -d)"
    HOME=$home "$bin" "preset:$preset" >/dev/null 2>&1 &
    local app=$!
    sleep "$settle"
    for step in "$@"; do
        read -r x y wait_s <<<"$step"
        xdotool mousemove "$x" "$y" click 1
        sleep "$wait_s"
    done
    xdotool mousemove 1270 795
    sleep 1
    import -window root "assets/$name.png"
    kill "$app" 2>/dev/null || true
    wait "$app" 2>/dev/null || true
    rm -rf "$home"
    echo "assets/$name.png"
}

# The Campbell tab of cng-genset with the order-3 crossing at 520 rpm selected.
shot gui-campbell cng-genset 6 "515 704 3"
# The mode-shape tab of cng-genset, mode 1.
shot gui-modes cng-genset 6 "559 177 2"
# The forced response of genset-20dof: torque in coupling_stage1 with its ratings.
shot gui-ratings genset-20dof 6 "649 261 1" "480 293 1" "497 343 2"
# The schematic of genset-20dof with its first coupling stage selected in it.
shot gui-schematic genset-20dof 6 "593 103 2"
# A 60 s run-up of test-rig-70sh: the spectrogram with order lines and order tracks.
shot gui-runup test-rig-70sh 6 "778 177 1" "514 209 25" "530 255 3"
