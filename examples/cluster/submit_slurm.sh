#!/usr/bin/env bash
# Runs a rollbench study on a Slurm cluster: an array job of N shards, then a merge job
# that starts only when every shard succeeded (afterok). See docs/studies.md.
#
#   examples/cluster/submit_slurm.sh decks/studies/trb_32007_clearance_tolerance.study.toml 4 results/
#
# The study file, its deck and the rollbench binary must be on a file system every node
# sees (ROLLBENCH: the binary, default `rollbench` on PATH).
set -euo pipefail
study=${1:?usage: submit_slurm.sh STUDY.toml SHARDS OUTDIR}
shards=${2:?usage: submit_slurm.sh STUDY.toml SHARDS OUTDIR}
out=${3:?usage: submit_slurm.sh STUDY.toml SHARDS OUTDIR}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
array=$(sbatch --parsable --array=0-$((shards - 1)) --output="$out/shard-%a.log" \
    "$here/study_shard.sbatch" "$study" "$out")
merge=$(sbatch --parsable --dependency=afterok:"$array" --output="$out/merge.log" \
    "$here/study_merge.sbatch" "$out")
echo "array job $array ($shards shards), merge job $merge: results in $out/result.csv"
