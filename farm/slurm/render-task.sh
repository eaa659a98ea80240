#!/usr/bin/env bash
# One task of a Spindulys render on Slurm: line SLURM_ARRAY_TASK_ID (from 0) of the job's task
# list, "FRAMES TILE", rendered with the job's render options. Submitted by submit.sh as
#   sbatch --array=0-(tasks-1) render-task.sh JOBDIR
# JOBDIR holds what submit.sh wrote: "settings" (RENDER, SCENE, NAME, OUTDIR as shell
# assignments), "tasks" (one line per task) and "render-args" (one render option a line).
#   FRAMES  "-" for a scene without animation, else one frame N or a chunk A-B of whole frames
#   TILE    "-" for whole frames, else I/N: band I of N (from 1) of the frame, into a tile
# Exits with render's status, so a task that fails is reported failed by Slurm (and the
# dependent assemble job never starts).
set -euo pipefail
jobdir=${1:?usage: render-task.sh JOBDIR}
# shellcheck source=/dev/null
source "$jobdir/settings"
task=${SLURM_ARRAY_TASK_ID:?not run as a task of a Slurm job array}
line=$(sed -n "$((task + 1))p" "$jobdir/tasks")
[ -n "$line" ] || { echo "render-task.sh: task $task has no line in $jobdir/tasks" >&2; exit 2; }
read -r frames tile <<<"$line"
mapfile -t extra < "$jobdir/render-args"

args=("$SCENE")
if [ "$frames" = "-" ]; then
  stem="$NAME"
else
  # render replaces #### by the padded frame number (anim: --frame / --frames).
  stem="${NAME}_####"
  case "$frames" in
    *-*) args+=(--frames "$frames" --skip-existing) ;;
    *) args+=(--frame "$frames") ;;
  esac
fi
if [ "$tile" = "-" ]; then
  args+=(-o "$OUTDIR/$stem.png")
else
  args+=(--tile "$tile" -o "$OUTDIR/tiles/$stem.tile_${tile%/*}_of_${tile#*/}.png")
fi
echo "task $task on $(hostname): render ${args[*]} ${extra[*]}"
exec "$RENDER" "${args[@]}" "${extra[@]}" --progress plain
