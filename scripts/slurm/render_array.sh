#!/bin/sh
# One Slurm array task per image of a landsim image set (frame-major: task k renders image k
# = frame k / views, view k % views). Submit with scripts/slurm/submit.sh, which sizes the
# array from the scenario and queues the manifest check after it.
#SBATCH --job-name=landsim-image
#SBATCH --cpus-per-task=8
#SBATCH --output=landsim-%A_%a.log
set -eu
: "${LANDSIM:=build/bin/landsim}"
"$LANDSIM" render "$SCENARIO" --out "$OUT" --task-index "$SLURM_ARRAY_TASK_ID" \
  --threads "${SLURM_CPUS_PER_TASK:-0}"
