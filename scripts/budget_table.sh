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
#        BUDGET_ROWS=issue33 scripts/budget_table.sh   (only issue 33's rows: signals records
# by length x sampling rate and by sensor count, dataset designs by records x length x
# rate x channels, predict with a future spectrum of 1-20 bins; about 10 min)
#        BUDGET_ROWS=datasets scripts/budget_table.sh   (only the dataset designs and a merge)
#        BUDGET_ROWS=predict scripts/budget_table.sh   (issue 22's predict rows: the prior,
# a posterior from calibrate, 1e5 samples, 1e4 grid points; about 10 min)
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet --bin gearwear
bin="$PWD/target/release/gearwear"
repo="$PWD"
work="${1:-$(mktemp -d)}"
mkdir -p "$work"
cd "$work"
rows=()

# measure NAME ARGS...: the estimate, then the run (into a new folder; with RESUME=1
# into the folder as it is, after the estimate made for that folder: a resume).
measure() {
    local name="$1"
    shift
    local est est_out="est_$name"
    [[ -n "${RESUME:-}" ]] && est_out="out_$name"
    est=$("$bin" "$@" --out "$est_out" --budget-scale 1e-9 2>&1 | tr '\n' ' ' || true)
    local mem time_est
    mem=$(grep -o 'memory ~[0-9.]* GB' <<<"$est" | head -1 | grep -o '[0-9.]*' || echo "?")
    time_est=$(grep -o 'time ~[0-9.]* [a-z]*' <<<"$est" | head -1 | sed 's/time ~//' || echo "?")
    [[ -z "${RESUME:-}" ]] && rm -rf "out_$name"
    /usr/bin/time -o "time_$name" -f "%M %e %U %S" "$bin" -q --no-budget "$@" --out "out_$name" \
        >/dev/null 2>"err_$name" || echo "$name: exit $? ($(tail -c 300 "err_$name"))" >&2
    local kb secs user sys
    read -r kb secs user sys < <(tail -1 "time_$name")
    local cpu
    cpu=$(python3 -c "print(f'{$user + $sys:.2f}')")
    local peak
    peak=$(python3 -c "print(f'{$kb * 1024 / 1e9:.3f}')")
    local ratio
    ratio=$(python3 -c "print(f'{$peak / $mem:.2f}' if '$mem' != '?' and $mem > 0 else '?')")
    rows+=("| \`$name\` | \`$*\` | $mem GB | $peak GB | $ratio | $time_est | ${secs} s | ${cpu} s |")
    echo "$name: estimate $mem GB, peak $peak GB (ratio $ratio), time estimate $time_est, took ${secs} s (CPU ${cpu} s)" >&2
}

# Observations (wear and vibration) from a true run at the built-in k, for calibrate.
observations() {
"$bin" wear -q --mode dynamic --set wear.total_cycles=4e4 --out truth >/dev/null 2>&1
python3 - <<'EOF'
import csv
rows = list(csv.DictReader(open("truth/updates_dynamic.csv")))
with open("obs.csv", "w") as f:
    f.write("cycles,max_wear_pinion_um,sigma_max_wear_pinion_um,velocity_y_pinion_rms_mm_per_s\n")
    for r in rows[1:]:
        f.write(f"{r['cycles']},{float(r['max_wear_pinion_um']):.4f},0.05,{float(r['velocity_y_pinion_rms_mm_per_s']):.4f}\n")
EOF
}

# predict from the prior and from calibrate's posterior (needs out_calibrate_k).
predict_rows() {
measure predict_prior predict --limit-um 10 --cycles 1e5
measure predict_posterior predict --posterior out_calibrate_k/posterior_samples.csv --limit-um 10 --cycles 1e5
measure predict_samples_1e5 predict --posterior out_calibrate_k/posterior_samples.csv --limit-um 10 --cycles 1e5 --samples 100000
measure predict_grid_1e4 predict --posterior out_calibrate_k/posterior_samples.csv --limit-um 10 --cycles 1e5 --grid-points 10000
}

# Future load spectra of N bins (torque 40-80 N m, speed 20-50 Hz, equal shares).
future_spectra() {
python3 - <<'PY'
for n in (1, 5, 20):
    with open(f"future_{n}.toml", "w") as f:
        f.write("[load_spectrum]\nbins = [\n")
        for i in range(n):
            t = 40 + 40 * i / max(n - 1, 1)
            v = 20 + 30 * ((i * 7) % n) / max(n - 1, 1)
            f.write(f"  {{ torque_nm = {t:.3f}, input_speed_hz = {v:.3f}, share = {1 / n!r} }},\n")
        f.write("]\n")
PY
}

# Predict with a future spectrum of 1, 5 and 20 bins (100 prior samples, to 2e4 cycles,
# the spectrum from 1e4 cycles on, no check runs).
future_rows() {
future_spectra
for n in 1 5 20; do
    measure "predict_future_${n}_bins" predict --limit-um 10 --cycles 2e4 --samples 100 \
        --check-runs 0 --future-spectrum "future_$n.toml" --future-from-cycles 1e4
done
}

# The rows of issue 22: every command at the ends of its ranges.
issue22_rows() {
observations

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
predict_rows
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
}

# A modal transfer path of N sensors (the generic housing's three modes, each sensor's
# gains those of `input` scaled by 1 + i/N): path_1.toml, path_20.toml, path_100.toml.
modal_paths() {
python3 - <<'PY'
for n in (1, 20, 100):
    with open(f"path_{n}.toml", "w") as f:
        f.write("sensors = [" + ", ".join(f'"s{i}"' for i in range(n)) + "]\n")
        for hz, z in ((2100.0, 0.02), (3700.0, 0.03), (6300.0, 0.04)):
            rows = ", ".join(f"[{0.0075 * (1 + i / n):.6f}, {0.025 * (1 + i / n):.6f}, 0.005, 0.02]" for i in range(n))
            f.write(f"[[mode]]\nfrequency_hz = {hz}\ndamping_ratio = {z}\ngains_per_kg = [{rows}]\n")
PY
}

# Datasets: records x length x rate x channels; realisations sharing a state; a merge.
dataset_rows() {
dataset_design() { # NAME STATES SPEEDS REALISATIONS LENGTH_S RATE_HZ [PATH]
    {
        echo "seed = 3"
        echo "set = [\"signals.record_length=$5\", \"signals.sampling_rate_hz=$6\"]"
        [[ -n "${7:-}" ]] && echo "transfer_path = \"$7\""
        echo "[run_to_failure]"
        echo "states = $2"
        echo "max_cycles = 2e4"
        echo "wear_limit_um = 10"
        echo "[operating]"
        echo "input_speed_hz = $3"
        echo "[records]"
        echo "noise_realisations = $4"
    } >"$1.toml"
}
dataset_design ds_8x0.25s 2 "[20, 30]" 2 0.25 25600
measure dataset_8_records_0.25s_25.6khz dataset --design ds_8x0.25s.toml
dataset_design ds_4x2s 2 "[30]" 2 2 25600
measure dataset_4_records_2s_25.6khz dataset --design ds_4x2s.toml
dataset_design ds_4x0.5s_100k 2 "[30]" 2 0.5 100000
measure dataset_4_records_0.5s_100khz dataset --design ds_4x0.5s_100k.toml
dataset_design ds_24x0.1s 3 "[20, 30]" 4 0.1 25600
measure dataset_24_records_0.1s_25.6khz dataset --design ds_24x0.1s.toml
dataset_design ds_4x0.5s_20ch 2 "[30]" 2 0.5 25600 path_20.toml
measure dataset_4_records_0.5s_20_sensors dataset --design ds_4x0.5s_20ch.toml
dataset_design ds_40x1s 40 "[30]" 1 1 25600
measure dataset_40_records_1s_1_realisation dataset --design ds_40x1s.toml
RESUME=1 measure dataset_40_records_1s_1_realisation dataset --design ds_40x1s.toml
dataset_design ds_4x4s_20ch 4 "[30]" 1 4 25600 path_20.toml
measure dataset_4_records_4s_20_sensors dataset --design ds_4x4s_20ch.toml
dataset_design ds_400x1s 40 "[30]" 10 1 25600
measure dataset_400_records_1s_10_realisations dataset --design ds_400x1s.toml
for i in 1 2; do
    "$bin" dataset -q --no-budget --design ds_400x1s.toml --shard "$i/2" --out "shard_$i" >/dev/null
done
measure dataset_merge_400_records dataset-merge shard_1 shard_2
}

# Issue 33: the estimate across record length x sampling rate, sensor count, dataset
# designs (records x length x rate x channels) and a future spectrum's bins.
issue33_rows() {
modal_paths
# Stiffness: a pair, a pair with a cracked tooth, the two-stage example, and that train
# with a crack on stage 1's pinion (milliseconds: the figures and the process dominate).
cp "$repo/examples/two_stage_reducer.toml" train.toml
{ cat train.toml; printf '\n[[fault]]\nkind = "crack"\nstage = 1\ngear = "pinion"\ntooth = 0\ncrack_depth_mm = 1.0\n'; } >train_fault.toml
measure stiffness_pair stiffness
measure stiffness_cracked_pair stiffness --set fault.kind=crack --set fault.gear=pinion --set fault.tooth=0 --set fault.crack_depth_mm=1
measure stiffness_train stiffness --config train.toml
measure stiffness_cracked_train stiffness --config train_fault.toml
# Signals: record length x sampling rate (steady records, the generic housing's 2 sensors).
measure signals_10s_25.6khz signals --set signals.record_length=10
measure signals_1s_200khz signals --set signals.sampling_rate_hz=200000
measure signals_5s_200khz signals --set signals.sampling_rate_hz=200000 --set signals.record_length=5
measure signals_0.5s_1mhz signals --set signals.sampling_rate_hz=1000000 --set signals.record_length=0.5
# Signals: the sensor count (a modal path of 1, 20, 100 sensors; 1 s at 25.6 kHz).
measure signals_1_sensor signals --transfer-path path_1.toml
measure signals_20_sensors signals --transfer-path path_20.toml
measure signals_100_sensors signals --transfer-path path_100.toml
# Figures at a requested size (the pixel buffers, counted with the budget).
measure stiffness_figures_2048x1024 stiffness --figure-size 2048x1024
measure stiffness_figures_8192x4096 stiffness --figure-size 8192x4096
dataset_rows
future_rows
}

case "${BUDGET_ROWS:-all}" in
    issue33) issue33_rows ;;
    datasets) modal_paths; dataset_rows ;;
    predict)
        observations
        measure calibrate_k calibrate --observations obs.csv --samples 2000
        predict_rows
        ;;
    *) issue22_rows; issue33_rows ;;
esac

echo
echo "| run | command | estimated memory | measured peak (RSS) | peak / estimate | estimated time | measured wall time | measured CPU time |"
echo "|---|---|---|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"
python3 - "${rows[@]}" <<'EOF'
import sys
r = [float(x.split("|")[5]) for x in sys.argv[1:] if x.split("|")[5].strip() not in ("?", "")]
print(f"\nworst peak / estimate: {max(r):.2f}" if r else "")
EOF
