#!/usr/bin/env bash
# The Slurm recipe of docs/SCALING.md run for real: a one-node Slurm cluster (Debian's
# slurm-wlm and munge) is started on this machine, a sharded speed sweep is submitted as a
# job array with the recipe's script, merged by a dependent job, and the merged table is
# compared byte for byte with the same sweep run unsharded.
#
# Usage: scripts/slurm_test.sh [path/to/gearwear]   (default: target/release/gearwear)
# Needs root (it installs packages and starts daemons) and a Debian-like system.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=$(realpath "${1:-target/release/gearwear}")
[ -x "$BIN" ] || { echo "no gearwear binary at $BIN (cargo build --release first)"; exit 1; }
started=$(date +%s)

if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurm-wlm munge >/dev/null
fi

WORK=$(mktemp -d /tmp/gearwear-slurm.XXXXXX)
HOST=$(hostname -s)
CPUS=$(nproc)
cleanup() {
    [ -f "$WORK/slurmd.pid" ] && kill "$(cat "$WORK/slurmd.pid")" 2>/dev/null || true
    [ -f "$WORK/slurmctld.pid" ] && kill "$(cat "$WORK/slurmctld.pid")" 2>/dev/null || true
    [ -f "$WORK/munged.pid" ] && kill "$(cat "$WORK/munged.pid")" 2>/dev/null || true
    sleep 1
}
trap cleanup EXIT

# munge: a fresh key and a private socket.
mkdir -p "$WORK/munge" && chmod 700 "$WORK/munge"
dd if=/dev/urandom of="$WORK/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$WORK/munge/munge.key"
munged --force --key-file="$WORK/munge/munge.key" --socket="$WORK/munge/munge.socket" \
    --pid-file="$WORK/munged.pid" --log-file="$WORK/munge/munged.log" \
    --seed-file="$WORK/munge/munged.seed"

# One node, no cgroups, everything under $WORK.
mkdir -p "$WORK/state" "$WORK/spool" "$WORK/logs"
cat > "$WORK/slurm.conf" <<CONF
ClusterName=gearwear-test
SlurmctldHost=$HOST
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$WORK/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool
SlurmctldPidFile=$WORK/slurmctld.pid
SlurmdPidFile=$WORK/slurmd.pid
SlurmctldLogFile=$WORK/logs/slurmctld.log
SlurmdLogFile=$WORK/logs/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=$HOST CPUs=$CPUS State=UNKNOWN
PartitionName=test Nodes=$HOST Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$WORK/slurm.conf"
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for _ in $(seq 1 30); do
    sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)' && break
    sleep 1
done
sinfo -h -o '%P %t %c' || { echo "slurm did not come up"; cat "$WORK"/logs/*.log; exit 1; }

# The recipe of docs/SCALING.md (paths and sizes adapted): N shards into one directory.
N=4
VARY="operating.input_speed_hz=20:50:2.5"
cat > "$WORK/sweep.sbatch" <<SCRIPT
#!/bin/bash
#SBATCH --job-name=gearwear-sweep
#SBATCH --cpus-per-task=1
#SBATCH --time=00:10:00
#SBATCH --output=$WORK/logs/sweep_%A_%a.log
set -euo pipefail
N=$N
export RAYON_NUM_THREADS=\${SLURM_CPUS_PER_TASK}
"$BIN" sweep --vary $VARY --run dynamics \\
    --shard "\${SLURM_ARRAY_TASK_ID}/\${N}" --out "$WORK/sweep1"
SCRIPT
jid=$(sbatch --parsable --array=1-$N "$WORK/sweep.sbatch")
mid=$(sbatch --parsable --dependency=afterany:"$jid" --output="$WORK/logs/merge.log" \
    --wrap "\"$BIN\" sweep-merge \"$WORK/sweep1\" --out \"$WORK/sweep1/merged\"")
for _ in $(seq 1 300); do
    [ -z "$(squeue -h -j "$jid,$mid" 2>/dev/null)" ] && break
    sleep 1
done
sacct_state=$(scontrol show job "$mid" 2>/dev/null | grep -o 'JobState=[A-Z]*' || true)
echo "merge job: ${sacct_state:-gone from the queue}"

# The same sweep unsharded, outside Slurm.
"$BIN" --quiet sweep --vary "$VARY" --run dynamics --out "$WORK/unsharded" 2>/dev/null
if cmp "$WORK/sweep1/merged/sweep.csv" "$WORK/unsharded/sweep.csv"; then
    rows=$(($(wc -l < "$WORK/unsharded/sweep.csv") - 1))
    echo "PASS: the merge of $N Slurm array shards equals the unsharded sweep byte for byte ($rows rows, $(( $(date +%s) - started )) s)"
else
    echo "FAIL: merged and unsharded tables differ"
    cat "$WORK"/logs/*.log
    exit 1
fi

# The dataset recipe of docs/SCALING.md: a small design as an array of N shards into one
# directory, merged in place by a dependent job, against the same dataset unsharded.
cat > "$WORK/design.toml" <<DESIGN
seed = 5
set = ["signals.snr_db=30", "signals.record_length=0.1", "numerics.steps_per_mesh_period=60",
       "stiffness.table_points_per_mesh_period=60"]
[run_to_failure]
cycles = [0, 1e4]
max_cycles = 1e4
[operating]
input_speed_hz = [25, 30]
[records]
noise_realisations = 2
DESIGN
cat > "$WORK/dataset.sbatch" <<SCRIPT
#!/bin/bash
#SBATCH --job-name=gearwear-dataset
#SBATCH --cpus-per-task=1
#SBATCH --time=00:10:00
#SBATCH --output=$WORK/logs/dataset_%A_%a.log
set -euo pipefail
N=$N
export RAYON_NUM_THREADS=\${SLURM_CPUS_PER_TASK}
"$BIN" dataset --design "$WORK/design.toml" \\
    --shard "\${SLURM_ARRAY_TASK_ID}/\${N}" --out "$WORK/dataset1"
SCRIPT
jid=$(sbatch --parsable --array=1-$N "$WORK/dataset.sbatch")
mid=$(sbatch --parsable --dependency=afterany:"$jid" --output="$WORK/logs/dataset_merge.log" \
    --wrap "\"$BIN\" dataset-merge \"$WORK/dataset1\" --out \"$WORK/dataset1\"")
for _ in $(seq 1 300); do
    [ -z "$(squeue -h -j "$jid,$mid" 2>/dev/null)" ] && break
    sleep 1
done
"$BIN" --quiet dataset --design "$WORK/design.toml" --out "$WORK/dataset_unsharded" 2>/dev/null
same=1
for f in index.parquet index.csv metadata.json; do
    cmp -s "$WORK/dataset1/$f" "$WORK/dataset_unsharded/$f" || same=0
done
diff -rq "$WORK/dataset1/signals" "$WORK/dataset_unsharded/signals" >/dev/null || same=0
if [ "$same" = 1 ]; then
    echo "PASS: the merge of $N Slurm array shards of a dataset equals the unsharded dataset byte for byte ($(ls "$WORK/dataset1/signals" | wc -l) records)"
else
    echo "FAIL: merged and unsharded datasets differ"
    cat "$WORK"/logs/*.log
    exit 1
fi
