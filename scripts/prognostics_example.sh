#!/usr/bin/env bash
# Reproduces the worked example of docs/PROGNOSTICS.md ("Worked example"): synthetic
# observations of the paper's case at a "true" wear coefficient, calibration of k from wear
# measurements and from vibration indicators alone, and the remaining-life predictions.
#
# Usage: scripts/prognostics_example.sh [OUT | --out OUT] [--no-prior] [--quiet]
#   OUT: default results/prognostics_example; --no-prior leaves out the prior-only prediction
#   (the costliest step); --quiet prints nothing. tests/docs_generated.rs runs it this way
#   to check the numbers of docs/PROGNOSTICS.md.
# Needs target/release/gearwear (built if missing; GEARWEAR_BIN names another binary) and
# python3 (standard library only). Every random draw has a fixed seed, so a rerun gives the
# same numbers.
set -euo pipefail
cd "$(dirname "$0")/.."
out=results/prognostics_example
prior=yes
quiet=no
while (($#)); do
    case "$1" in
        --out) out="$2"; shift ;;
        --no-prior) prior=no ;;
        --quiet) quiet=yes ;;
        *) out="$1" ;;
    esac
    shift
done
bin="${GEARWEAR_BIN:-target/release/gearwear}"
[[ -x "$bin" ]] || cargo build --release
mkdir -p "$out"

k_true=4e-16        # 1.6 x the case's k0 = 2.5e-16 m^2/N
observed_to=40000   # the gearbox has run this many pinion cycles
step=4000           # vibration readings every `step` cycles
wear_at="20000 40000"   # two profile measurements
sigma_wear_um=0.2   # given in the file (sigma_ column)
sigma_vib=0.02      # mm/s, not given: the calibration infers it
noise_seed=1        # seed of the observation noise (Python's random.Random)
limit_um=10
horizon=1e5
life_horizon=1e5    # the deterministic true run goes this far to find its life
seed=1

# (a) the truth: a dynamic wear study at k_true, to the horizon of the life
"$bin" wear -q --mode dynamic --set wear.coefficient_m2_per_n=$k_true \
    --set wear.total_cycles=$life_horizon --out "$out/truth"

# Observations: the truth at the observation cycles plus Gaussian noise. The wear is
# read exactly as the model grows it between updates (max_i (h_i + n rate_i) in the block
# holding the cycle count), the response linearly interpolated between updates.
python3 - "$out" $observed_to $step "$wear_at" $sigma_wear_um $sigma_vib $noise_seed $limit_um <<'EOF'
import csv, random, sys
out, to, step, wear_at, s_wear, s_vib, seed, limit = sys.argv[1:9]
to, step, s_wear, s_vib, seed, limit = int(to), int(step), float(s_wear), float(s_vib), int(seed), float(limit)
wear_at = [int(c) for c in wear_at.split()]
ups = list(csv.DictReader(open(f"{out}/truth/updates_dynamic.csv")))
cyc = [float(u["cycles"]) for u in ups]
prof = list(csv.DictReader(open(f"{out}/truth/wear_profiles_dynamic.csv")))

def block(c):
    """Index of the last update at or before c (the block the model is in at c)."""
    return max(j for j in range(len(cyc)) if cyc[j] <= c)

def max_wear(c):
    j = block(c)
    n = c - cyc[j]
    return max(float(p[f"wear_pinion_um_u{j}"]) + n * 1e-3 * float(p[f"rate_pinion_um_per_kcycle_u{j}"]) for p in prof)

def response(name, c):
    j = block(c)
    if j + 1 == len(cyc):
        return float(ups[j][name])
    t = (c - cyc[j]) / (cyc[j + 1] - cyc[j])
    return (1 - t) * float(ups[j][name]) + t * float(ups[j + 1][name])

def life(limit):
    """Cycles at which the maximum pinion wear first reaches `limit` (exact in the block)."""
    for j in range(len(cyc) - 1):
        if max_wear(cyc[j + 1]) >= limit:
            best = cyc[j + 1] - cyc[j]
            for p in prof:
                h = float(p[f"wear_pinion_um_u{j}"])
                r = 1e-3 * float(p[f"rate_pinion_um_per_kcycle_u{j}"])
                if r > 0:
                    best = min(best, max(0.0, (limit - h) / r))
            return cyc[j] + best
    return None

rng = random.Random(seed)
vib = ["velocity_y_pinion_rms_mm_per_s", "mesh_harmonic1_mm_per_s"]
with open(f"{out}/obs_vibration.csv", "w") as f:
    f.write("cycles," + ",".join(vib) + "\n")
    for c in range(step, to + 1, step):
        f.write(f"{c}," + ",".join(f"{response(q, c) + rng.gauss(0, s_vib):.4f}" for q in vib) + "\n")
with open(f"{out}/obs_wear.csv", "w") as f:
    f.write("cycles,max_wear_pinion_um,sigma_max_wear_pinion_um\n")
    for c in wear_at:
        f.write(f"{c},{max_wear(c) + rng.gauss(0, s_wear):.4f},{s_wear}\n")
with open(f"{out}/truth.txt", "w") as f:
    print(f"true max pinion wear at {to} cycles: {max_wear(to):.4f} um", file=f)
    for q in vib:
        print(f"true {q}: {response(q, 0):.4f} at 0, {response(q, to):.4f} at {to}", file=f)
    print(f"true cycles to {limit} um: {life(limit):.0f}", file=f)
# The same numbers in full precision, for tests/docs_generated.rs.
with open(f"{out}/truth.json", "w") as f:
    import json
    json.dump({"observed_to_cycles": to, "max_wear_pinion_um_at_observed_to": max_wear(to),
               "response_at_0": {q: response(q, 0) for q in vib},
               "response_at_observed_to": {q: response(q, to) for q in vib},
               "cycles_to_limit": life(limit)}, f, indent=1)
EOF

# (b) calibrations, (c) predictions
for ev in wear vibration; do
    "$bin" calibrate -q --observations "$out/obs_$ev.csv" --seed $seed --out "$out/cal_$ev"
    "$bin" predict -q --posterior "$out/cal_$ev/posterior_samples.csv" --limit-um $limit_um \
        --cycles $horizon --seed $seed --out "$out/pred_$ev"
done
if [[ $prior == yes ]]; then
    "$bin" predict -q --limit-um $limit_um --cycles 1e6 --seed $seed --out "$out/pred_prior"
fi
[[ $quiet == no ]] || exit 0

# (d) the numbers the docs quote
python3 - "$out" <<'EOF'
import csv, json, sys
out = sys.argv[1]
print(open(f"{out}/truth.txt").read(), end="")
def fmt(x):
    return "> horizon" if x is None else f"{x:.4g}"
import os
for ev in ["wear", "vibration", "prior"]:
    if not os.path.isdir(f"{out}/pred_{ev}"):
        continue
    print(f"--- evidence: {ev}")
    if ev != "prior":
        cal = json.load(open(f"{out}/cal_{ev}/summary.json"))
        k = cal["parameters"][0]
        print(f"k median {k['median']:.4g}, 90 % interval {k['ci90'][0]:.4g} - {k['ci90'][1]:.4g} m^2/N")
        for o in cal["observations"]:
            print(f"  {o['quantity']}: noise {o['noise']}, scale at the median {o['noise_scale_at_posterior_median']:.3g}")
        print(f"  surrogate check (error / predictive sd): {cal['surrogate_check_max_error_over_predictive_sd']:.2g}")
    pred = json.load(open(f"{out}/pred_{ev}/summary.json"))
    life = pred["remaining_life_cycles"]
    print(f"cycles to the limit: median {fmt(life['median'])}, 5 % {fmt(life['p05'])}, 95 % {fmt(life['p95'])};"
          f" P(> {pred['horizon_cycles']:.0e}) = {life['prob_beyond_horizon']:.4g};"
          f" failed samples {pred['failed_samples']['count']}")
    print(f"  surrogate check (life error / spread): max {max(c['life_error_over_spread'] for c in pred['surrogate_check']):.2g}")
    if ev == "vibration":
        rows = list(csv.DictReader(open(f"{out}/pred_{ev}/fan_vibration.csv")))
        for q in ["velocity_y_pinion_rms_mm_per_s", "mesh_harmonic1_mm_per_s", "mesh_harmonic2_mm_per_s",
                  "dte_peak_to_peak_um", "dte_harmonic1_um"]:
            med = [(float(r[q + "_p50"]), float(r["cycles"])) for r in rows]
            lo = min(med)
            print(f"  fan median of {q}: {med[0][0]:.3g} at 0, minimum {lo[0]:.3g} at {lo[1]:.3g} cycles,"
                  f" {med[-1][0]:.3g} at {med[-1][1]:.3g}")
EOF
