#!/usr/bin/env bash
# Remakes the concealed diagnosis cases in tests/data/diagnosis/ (one per effect of
# spec/diagnosis.md, plus the `none` and `parameter_error` controls) with `torsim synth`.
# Run from the repository root:
#   scripts/make-diagnosis-cases.sh                    # all cases, with target/debug/torsim
#   TORSIM=target/release/torsim scripts/make-diagnosis-cases.sh gear_backlash
# Each case's truth.toml records the exact command that made it; tests/synth_cases.rs checks
# that the shipped files are what these commands make.
set -euo pipefail

torsim=${TORSIM:-target/debug/torsim}
data=tests/data/diagnosis
bench=preset:diagnosis-bench
# The bench every case shares: two stations (crank encoder, coupling zebra tape), 0.3 rpm
# of white noise, 20 ns of pulse jitter, a 0.2 % speed wobble, samples to 0.1 rpm, the
# campaign of plan.toml.
common=(--plan "$data/plan.toml" --rate-hz 2000 --station engine:encoder:360
    --station coupling_es:zebra:78 --noise-rpm 0.3 --jitter-ns 20 --wobble-pct 0.2
    --resolution-rpm 0.1)

make_case() {
    local name=$1
    shift
    if [[ -n ${only:-} && $only != "$name" ]]; then
        return
    fi
    echo "== $name"
    "$torsim" synth "$@" "${common[@]}" --out "$data/$name"
}

only=${1:-}
make_case none $bench --effect none --seed 101
make_case parameter_error $bench --effect parameter_error --param target=coupling \
    --param factor=0.9 --seed 102
make_case coupling_amplitude_nonlinearity $bench --effect coupling_amplitude_nonlinearity \
    --param-error-pct 10 --seed 103
make_case coupling_frequency_dependence $bench --effect coupling_frequency_dependence \
    --param scale=0.3 --param-error-pct 10 --seed 104
make_case coupling_thermal_drift $bench --effect coupling_thermal_drift --param capacity_j_per_k=120 \
    --param-error-pct 10 --seed 105
make_case hysteretic_damping "$data/model-viscous.toml" --effect hysteretic_damping \
    --param reference_hz=140 --param-error-pct 5 --seed 106
make_case unmodelled_mode $bench --effect unmodelled_mode --param inertia_kg_m2=0.1 \
    --param-error-pct 5 --seed 107
make_case crank_variable_inertia "$data/model-norecip.toml" --effect crank_variable_inertia \
    --param mass_kg=0.6 --param drop_harmonics=2 --param-error-pct 5 --seed 108
make_case gear_backlash $bench --effect gear_backlash --param backlash_deg=0.1 \
    --param-error-pct 5 --seed 109
make_case cylinder_imbalance $bench --effect cylinder_imbalance --param cylinder=3 \
    --param pressure_scale=0.95 --param-error-pct 5 --seed 110
make_case sensor_artifact $bench --effect sensor_artifact --param station=coupling_es \
    --param joint_fraction=0.03 --param-error-pct 5 --seed 111
