#!/usr/bin/env bash
# Opt-in fuzzing of case parsing, validation and model construction (docs/RELIABILITY.md,
# "Input domain and fuzzing"). Not part of .ci/run by default: it needs cargo-fuzz and a
# nightly toolchain (or RUSTC_BOOTSTRAP=1 on stable), and its first build takes minutes.
#
# Usage: scripts/fuzz.sh [RUNS]        (default 1000000 executions)
#        FUZZ_TOOLCHAIN=nightly-2026-05-15 scripts/fuzz.sh 200000
#        FUZZ_SECONDS=120 scripts/fuzz.sh (a bounded time instead of a number of runs)
# The corpus grows in fuzz/corpus/case_input (seeded from fuzz/seeds); a crash is saved in
# fuzz/artifacts/case_input and makes this script fail.
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-1000000}"
toolchain="${FUZZ_TOOLCHAIN:-nightly}"
if ! command -v cargo-fuzz >/dev/null; then
    echo "cargo-fuzz is missing: cargo install cargo-fuzz" >&2
    exit 2
fi
if rustup toolchain list 2>/dev/null | grep -q "^${toolchain}"; then
    cargo_cmd=(cargo "+${toolchain}")
else
    echo "no ${toolchain} toolchain: trying the default one with RUSTC_BOOTSTRAP=1" >&2
    export RUSTC_BOOTSTRAP=1
    cargo_cmd=(cargo)
fi
corpus=fuzz/corpus/case_input
mkdir -p "$corpus"
cp -n fuzz/seeds/* "$corpus"/ 2>/dev/null || true
limit=(-runs="$runs")
if [[ -n "${FUZZ_SECONDS:-}" ]]; then
    limit=(-max_total_time="$FUZZ_SECONDS")
fi
# No sanitizer: gearwear has no unsafe code of its own; what the fuzzer looks for is a
# panic (debug assertions are on), an abort, a hang (-timeout) or a memory blow-up
# (-rss_limit_mb), and an uninstrumented build runs several times faster.
"${cargo_cmd[@]}" fuzz run --sanitizer none case_input "$corpus" -- \
    "${limit[@]}" -max_len=16384 -timeout=20 -rss_limit_mb=2048 -print_final_stats=1
