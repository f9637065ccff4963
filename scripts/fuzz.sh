#!/usr/bin/env bash
# Fuzzes torsim's readers (issue 13, deliverable 5) on stable Rust, every target in turn:
#   scripts/fuzz.sh            # 10 minutes per target
#   scripts/fuzz.sh 3600       # an hour per target
#   scripts/fuzz.sh 60 model   # one target (model, recording or sidecar)
#
# The targets (fuzz/fuzz_targets/, bodies in fuzz/src/lib.rs) are built by cargo-fuzz with
# `--sanitizer none`, which works on stable (the sanitizers need nightly). cargo-fuzz is
# installed into ~/.cargo/bin when missing (`cargo install cargo-fuzz --locked`, ~3 min).
#
# New interesting inputs go to fuzz/new-corpus/<target>/ (not committed); the saved corpus
# fuzz/corpus/<target>/ is only read. To keep a few of them, minimise and copy the small
# ones (`cargo fuzz cmin -s none <target> fuzz/new-corpus/<target>`, then copy files of a
# few KB into fuzz/corpus/<target>/); keep the corpus under ~2 MB.
#
# When a target crashes, libFuzzer writes the input to fuzz/artifacts/<target>/crash-<hash>
# and prints it. To add it:
#   1. reproduce: `cd fuzz && cargo fuzz run -s none <target> artifacts/<target>/crash-<hash>`
#   2. copy it, named for what it is, to fuzz/regressions/<target>/ (replayed by the
#      ignored test `regressions_read_without_panic` in tests/fuzz_corpus.rs) and fix the
#      reader;
#   3. once fixed, move it into fuzz/corpus/<target>/, where the stable
#      `cargo test --test fuzz_corpus` replays it on every CI run (libFuzzer also replays
#      the corpus first, so an input that still crashes must not be there).
set -euo pipefail

seconds=${1:-600}
targets=("${@:2}")
if ((${#targets[@]} == 0)); then
    targets=(model recording sidecar)
fi

cd "$(dirname "$0")/../fuzz"
if ! cargo fuzz --version >/dev/null 2>&1; then
    echo "fuzz.sh: installing cargo-fuzz" >&2
    cargo install cargo-fuzz --locked
fi
# Its own target dir: the fuzz build uses other flags than the main build.
unset CARGO_TARGET_DIR
for t in "${targets[@]}"; do
    mkdir -p "new-corpus/$t"
    echo "fuzz.sh: $t for $seconds s" >&2
    # -max_len: 64 KiB holds the largest seeds (a preset, a few hundred CSV rows);
    # -timeout: an input that takes over 10 s is a hang (issue 13: every input ends
    # within 10 s).
    cargo fuzz run -s none "$t" "new-corpus/$t" "corpus/$t" -- \
        -max_total_time="$seconds" -max_len=65536 -timeout=10 -print_final_stats=1
done
