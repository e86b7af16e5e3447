#!/usr/bin/env bash
# CI of the Python package: build the wheel in a fresh virtual environment with the
# documented command (`pip install ./python`), install the test tools, and run pytest
# against the command-line binary built from the same tree.
#
# Needs Python >= 3.9 with venv and pip, and the Rust toolchain; pip fetches maturin (the
# build backend), numpy, pytest, pandas, matplotlib and nbformat from PyPI. Run from
# anywhere: `bash python/ci.sh`. PYTHON selects the interpreter (default python3).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export PIP_DISABLE_PIP_VERSION_CHECK=1

# Debian splits venv (ensurepip) into python3-venv: fall back on PyPI's virtualenv.
if ! "${PYTHON:-python3}" -m venv "$work/venv" 2>/dev/null; then
    rm -rf "$work/venv"
    "${PYTHON:-python3}" -m pip install --quiet --user virtualenv ||
        "${PYTHON:-python3}" -m pip install --quiet --user --break-system-packages virtualenv
    "${PYTHON:-python3}" -m virtualenv --quiet "$work/venv"
fi
py="$work/venv/bin/python"
"$py" --version

start=$(date +%s)
"$py" -m pip install --quiet ./python
echo "python/ci.sh: wheel built and installed in $(($(date +%s) - start)) s"

"$py" -m pip install --quiet pytest matplotlib pandas nbformat
# The reference the summaries are compared with (a no-op after `cargo test --release`).
cargo build --release --quiet --bin gearwear
export GEARWEAR_CLI="$root/target/release/gearwear"
export MPLBACKEND=Agg

# From a folder without the package's sources, so `import gearwear` is the installed one.
cd "$work"
"$py" -m pytest -q -p no:cacheprovider "$root/python/tests"
