#!/usr/bin/env bash
# A speed sweep on a Slurm cluster over frictrack's resumable shards (user guide: "Sweeps beyond one machine"):
# one job-array task per shard, each running every N-th speed of the range on the cores Slurm gives it, and a merge
# job that starts only when every task has succeeded (afterok). A task that dies (node failure, time limit) is
# resubmitted with `sbatch --array=K` and resumes from its journal: finished speeds are not run again.
#
#   examples/cluster/slurm-sweep.sh SCENARIO SPEEDS SHARDS OUT_DIR [--dry-run]
#   examples/cluster/slurm-sweep.sh examples/distributed-speed.toml 10:300:1 8 /scratch/sweep
#
# --dry-run prints, one per line, the folder's creation, the command each array task runs (K = 1 … N) and then the
# merge command, and
# submits nothing: run them in order on any machine for the same result (no Slurm needed). frictrack schedules
# nothing across machines itself; Slurm does. Set FRICTRACK to the binary's path if it is not on PATH, and
# SBATCH_OPTIONS for your partition, account and time limit (e.g. "--partition=short --time=02:00:00").
set -euo pipefail

if [[ $# -lt 4 ]]; then
    echo "usage: $0 SCENARIO SPEEDS SHARDS OUT_DIR [--dry-run]" >&2
    exit 2
fi
scenario=$1 speeds=$2 shards=$3 out=$4 dry_run=${5:-}
frictrack=${FRICTRACK:-frictrack}
if ! [[ $shards =~ ^[1-9][0-9]*$ ]]; then
    echo "SHARDS = $shards: must be a whole number ≥ 1" >&2
    exit 2
fi

# What task K runs: its shard of the speeds, on the task's cores, resumable from its journal.
task() {
    echo "$frictrack sweep $scenario --speeds $speeds --shard $1/$shards --out $out/shard-$1.csv --resume --jobs ${2:-0} --quiet"
}
merge() {
    local files=()
    for k in $(seq 1 "$shards"); do files+=("$out/shard-$k.csv"); done
    echo "$frictrack merge --out $out/sweep.csv ${files[*]}"
}

if [[ $dry_run == --dry-run ]]; then
    echo "mkdir -p $out"
    for k in $(seq 1 "$shards"); do task "$k"; done
    merge
    exit 0
fi

mkdir -p "$out"
# The array's tasks see SLURM_ARRAY_TASK_ID (K) and SLURM_CPUS_PER_TASK (their cores) at run time.
array=$(sbatch --parsable ${SBATCH_OPTIONS:-} --array=1-"$shards" --cpus-per-task="${CPUS_PER_TASK:-4}" \
    --job-name=frictrack-sweep --output="$out/slurm-%A_%a.out" \
    --wrap "$(task '${SLURM_ARRAY_TASK_ID}' '${SLURM_CPUS_PER_TASK}')")
merged=$(sbatch --parsable ${SBATCH_OPTIONS:-} --dependency=afterok:"$array" --job-name=frictrack-merge \
    --output="$out/slurm-merge-%j.out" --wrap "$(merge)")
echo "submitted: array job $array ($shards tasks), merge job $merged (after every task succeeds): $out/sweep.csv"
