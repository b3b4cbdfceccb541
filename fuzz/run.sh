#!/bin/sh
# Runs a cargo-fuzz target (not part of CI). This machine has only a stable toolchain:
# RUSTC_BOOTSTRAP=1 lets stable rustc accept the -Z flags cargo-fuzz passes, and
# `--sanitizer none` avoids ASan (its runtime is not needed: the code is safe Rust; the
# targets look for panics). Usage: fuzz/run.sh [scene_text|batch_lines] [seconds] [jobs]
set -eu
cd "$(dirname "$0")/.."
target="${1:-scene_text}"
seconds="${2:-600}"
jobs="${3:-1}"
mkdir -p "fuzz/corpus/$target"
if [ "$target" = scene_text ] && [ -z "$(ls -A "fuzz/corpus/$target")" ]; then
    cp fixtures/scenes/default.toml fixtures/scenes/corridor.toml fixtures/scenes/two_bodies.toml \
        "fuzz/corpus/$target/"
fi
# With jobs > 1 libFuzzer runs child processes that log to fuzz-<n>.log in the current directory.
parallel=""
if [ "$jobs" -gt 1 ]; then parallel="-jobs=$jobs -workers=$jobs"; fi
# shellcheck disable=SC2086
RUSTC_BOOTSTRAP=1 exec cargo fuzz run --sanitizer none --fuzz-dir fuzz \
    --target-dir "${FUZZ_TARGET_DIR:-fuzz/target}" "$target" \
    "fuzz/corpus/$target" -- -max_total_time="$seconds" $parallel -max_len=8192
