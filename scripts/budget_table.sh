#!/usr/bin/env bash
# The run budget's estimate against the real peak memory (RSS) and time of every command
# at the ends of its ranges (docs/RELIABILITY.md, "Run budget"). For each run: the
# estimate, read from the refusal gearwear prints under a vanishing budget
# (--budget-scale 1e-9: "memory ~X GB ... time ~Y"), then the run itself under
# /usr/bin/time (peak RSS, wall time). Prints a Markdown table and the worst ratio of
# measured to estimated memory.
#
# Usage: scripts/budget_table.sh [OUT_DIR]   (default: a temporary folder; ~15 min on the
# shared 2-core machine). Needs /usr/bin/time (Debian: apt-get install time) and python3.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet --bin gearwear
bin="$PWD/target/release/gearwear"
work="${1:-$(mktemp -d)}"
mkdir -p "$work"
cd "$work"
rows=()

# Observations (wear and vibration) from a true run at the built-in k, for calibrate.
"$bin" wear -q --mode dynamic --set wear.total_cycles=4e4 --out truth >/dev/null 2>&1
python3 - <<'EOF'
import csv
rows = list(csv.DictReader(open("truth/updates_dynamic.csv")))
with open("obs.csv", "w") as f:
    f.write("cycles,max_wear_pinion_um,sigma_max_wear_pinion_um,velocity_y_pinion_rms_mm_per_s\n")
    for r in rows[1:]:
        f.write(f"{r['cycles']},{float(r['max_wear_pinion_um']):.4f},0.05,{float(r['velocity_y_pinion_rms_mm_per_s']):.4f}\n")
EOF

# measure NAME ARGS...: the estimate, then the run.
measure() {
    local name="$1"
    shift
    local est
    est=$("$bin" "$@" --out "est_$name" --budget-scale 1e-9 2>&1 | tr '\n' ' ' || true)
    local mem time_est
    mem=$(grep -o 'memory ~[0-9.]* GB' <<<"$est" | head -1 | grep -o '[0-9.]*' || echo "?")
    time_est=$(grep -o 'time ~[0-9.]* [a-z]*' <<<"$est" | head -1 | sed 's/time ~//' || echo "?")
    rm -rf "out_$name"
    /usr/bin/time -o "time_$name" -f "%M %e" "$bin" -q --no-budget "$@" --out "out_$name" \
        >/dev/null 2>"err_$name" || echo "$name: exit $? ($(tail -c 300 "err_$name"))" >&2
    local kb secs
    read -r kb secs < <(tail -1 "time_$name")
    local peak
    peak=$(python3 -c "print(f'{$kb * 1024 / 1e9:.3f}')")
    local ratio
    ratio=$(python3 -c "print(f'{$peak / $mem:.2f}' if '$mem' != '?' and $mem > 0 else '?')")
    rows+=("| \`$name\` | \`$*\` | $mem GB | $peak GB | $ratio | $time_est | ${secs} s |")
    echo "$name: estimate $mem GB, peak $peak GB (ratio $ratio), time estimate $time_est, took ${secs} s" >&2
}

measure stiffness_default stiffness
measure stiffness_table_1e5 stiffness --set stiffness.table_points_per_mesh_period=100000
measure dynamics_default dynamics
measure dynamics_steps_2e4 dynamics --set numerics.steps_per_mesh_period=20000
measure dynamics_periods_1000 dynamics --set numerics.evaluated_mesh_periods=1000
measure wear_default wear
measure wear_grid_1e5 wear --set wear.points_per_profile=100000
measure wear_threshold_0.02 wear --set wear.threshold_um=0.02
measure run_default run
measure run_grid_1e5 run --set wear.points_per_profile=100000
measure run_grid_1e5_threshold_0.05 run --set wear.points_per_profile=100000 --set wear.threshold_um=0.05
measure sweep_dynamics_40 sweep --vary operating.input_speed_hz=10:49:1
measure sweep_wear_8 sweep --run wear --vary operating.input_speed_hz=20:55:5
measure calibrate_k calibrate --observations obs.csv --samples 2000
measure calibrate_k_grid_1e4 calibrate --observations obs.csv --set calibration.grid_points=10000
measure calibrate_k_roughness_grid_1000 calibrate --observations obs.csv --set calibration.roughness_scale_min=0.8 --set calibration.roughness_scale_max=1.2 --set calibration.grid_points=1000 --set calibration.surrogate_nodes=3
measure calibrate_three_mcmc calibrate --observations obs.csv --set calibration.roughness_scale_min=0.8 --set calibration.roughness_scale_max=1.2 --set calibration.load_torque_min_nm=55 --set calibration.load_torque_max_nm=65 --set calibration.surrogate_nodes=2 --walkers 64 --steps 4000
measure predict_prior predict --limit-um 10 --cycles 1e5
measure predict_posterior predict --posterior out_calibrate_k/posterior_samples.csv --limit-um 10 --cycles 1e5
measure predict_samples_1e5 predict --posterior out_calibrate_k/posterior_samples.csv --limit-um 10 --cycles 1e5 --samples 100000
measure predict_grid_1e4 predict --posterior out_calibrate_k/posterior_samples.csv --limit-um 10 --cycles 1e5 --grid-points 10000
measure predict_shard predict --posterior out_calibrate_k/posterior_samples.csv --limit-um 10 --cycles 1e5 --samples 100000 --shard 1/2
measure predict_merge predict-merge out_predict_shard
measure sweep_merge sweep-merge out_sweep_dynamics_40
# A 1e6-row posterior (the file's range end), from the calibration's samples repeated.
python3 - <<'PY'
import csv
rows = list(csv.reader(open("out_calibrate_k/posterior_samples.csv")))
head, body = rows[0], rows[1:]
with open("posterior_1e6.csv", "w") as f:
    f.write(",".join(head) + "\n")
    for i in range(1_000_000):
        f.write(",".join(body[i % len(body)]) + "\n")
PY
measure predict_posterior_1e6_rows predict --posterior posterior_1e6.csv --limit-um 10 --cycles 1e5
# The issue's run: the finest profile grid with a fine wear threshold (1.98 GB estimated,
# 7.9 GB measured before the estimate was corrected).
measure run_grid_1e5_threshold_0.015 run --set wear.points_per_profile=100000 --set wear.threshold_um=0.015
# Tooth-resolved (every tooth drawn for ISO 1328-1 class 5: 589 mesh periods of excitation).
measure dynamics_teeth_grade5 dynamics --set teeth.accuracy_grade=5
measure wear_teeth_grade5_4e4 wear --set teeth.accuracy_grade=5 --set wear.total_cycles=4e4
# Signals: the default record, a long fast one, a run-up (transient) and a torque fluctuation.
measure signals_default signals
measure signals_100khz_20s signals --set signals.sampling_rate_hz=100000 --set signals.record_length=20
measure signals_runup_10s signals --set operating.input_speed_hz=5 --set signals.ramp_end_speed_hz=60 --set signals.record_length=10
measure signals_torque_fluctuation_2s signals --set signals.torque_fluctuation_rms_nm=5 --set signals.record_length=2
# A dataset (3 states x 2 speeds x 3 noise realisations, CSV records too) and its merge.
cat > design.toml <<'TOML'
seed = 7
[run_to_failure]
states = 3
max_cycles = 2e4
wear_limit_um = 10
[operating]
input_speed_hz = [20, 30]
[records]
noise_realisations = 3
csv = true
TOML
measure dataset_12_records dataset --design design.toml
measure dataset_merge dataset-merge out_dataset_12_records
# Duty cycles: a measured history of 1e7 rows (the file's range end) counted into 100 x 100 classes, and a run
# under a three-bin spectrum.
python3 - <<'PY'
import math
with open("history_1e7.csv", "w") as f:
    f.write("time_s,torque_nm,input_speed_hz\n")
    for i in range(10_000_000):
        t = i * 1e-3
        f.write(f"{t:.3f},{60 + 30 * math.sin(0.7 * t):.4f},{30 + 10 * math.sin(0.13 * t):.4f}\n")
PY
measure load_spectrum_1e7_rows load-spectrum --history history_1e7.csv --torque-classes 100 --speed-classes 100
cat > three_bins.toml <<'TOML'
[load_spectrum]
bins = [
  { torque_nm = 40.0, input_speed_hz = 30.0, share = 0.5 },
  { torque_nm = 60.0, input_speed_hz = 40.0, share = 0.3 },
  { torque_nm = 80.0, input_speed_hz = 50.0, share = 0.2 },
]
TOML
measure run_spectrum_3_bins run --config three_bins.toml

echo
echo "| run | command | estimated memory | measured peak (RSS) | peak / estimate | estimated time | measured time |"
echo "|---|---|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"
python3 - "${rows[@]}" <<'EOF'
import sys
r = [float(x.split("|")[5]) for x in sys.argv[1:] if x.split("|")[5].strip() not in ("?", "")]
print(f"\nworst peak / estimate: {max(r):.2f}" if r else "")
EOF
