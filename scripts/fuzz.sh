#!/usr/bin/env bash
# Opt-in fuzzing of case parsing, validation and model construction (docs/RELIABILITY.md,
# "Input domain and fuzzing"). Not part of .ci/run by default: it needs cargo-fuzz and a
# nightly toolchain (or RUSTC_BOOTSTRAP=1 on stable), and its first build takes minutes.
#
# Usage: scripts/fuzz.sh [RUNS]        (default 1000000 executions of each target)
#        FUZZ_TARGET=case_values scripts/fuzz.sh   (one target; default: all in turn)
#        FUZZ_TOOLCHAIN=nightly-2026-05-15 scripts/fuzz.sh 200000
#        FUZZ_SECONDS=120 scripts/fuzz.sh (a bounded time per target too: RUNS or the time,
#        whichever comes first)
# Targets: case_input (TOML text, --set, --vary), case_values (schema keys with values
# mostly in range, so most inputs reach the model), observations and posterior (the CSV
# files of calibrate and predict), checkpoint (a wear checkpoint, checked against the
# model), dataset_design (a dataset design and its case file), dataset_sidecar (a
# record's sidecar as a resume or merge reads it, and the index built from it) and
# dataset_shard (a shard's description as dataset-merge reads it); each seeded from
# fuzz/seeds/TARGET where that exists. The corpora
# grow in fuzz/corpus/TARGET; a crash is saved in fuzz/artifacts/TARGET and makes this
# script fail.
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
limit=(-runs="$runs")
if [[ -n "${FUZZ_SECONDS:-}" ]]; then
    # Both bounds: whichever comes first.
    limit+=(-max_total_time="$FUZZ_SECONDS")
fi
for target in ${FUZZ_TARGET:-case_input case_values observations posterior checkpoint dataset_design dataset_sidecar dataset_shard}; do
    corpus="fuzz/corpus/$target"
    mkdir -p "$corpus"
    if [[ -d "fuzz/seeds/$target" ]]; then
        cp -n "fuzz/seeds/$target"/* "$corpus"/ 2>/dev/null || true
    fi
    # No sanitizer: gearwear has no unsafe code of its own; what the fuzzer looks for is a
    # panic (debug assertions are on), an abort, a hang (-timeout) or a memory blow-up
    # (-rss_limit_mb), and an uninstrumented build runs several times faster.
    # A real checkpoint is 90-120 kB (its seeds): a shorter max_len would truncate every
    # seed, and the records would never reach the model check.
    max_len=16384
    [[ "$target" == checkpoint ]] && max_len=262144
    "${cargo_cmd[@]}" fuzz run --sanitizer none "$target" "$corpus" -- \
        "${limit[@]}" -max_len="$max_len" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1
done
