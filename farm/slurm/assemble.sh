#!/usr/bin/env bash
# The assemble step of a Spindulys render on Slurm, run by submit.sh's dependent job once every
# render task has succeeded: each tiled frame listed in JOBDIR/assemble ("FRAME N" a line, FRAME
# "-" for a scene without animation) is put together from its N tiles into OUTDIR.
set -euo pipefail
jobdir=${1:?usage: assemble.sh JOBDIR}
# shellcheck source=/dev/null
source "$jobdir/settings"
while read -r frame count; do
  if [ "$frame" = "-" ]; then stem="$NAME"; else stem=$(printf '%s_%04d' "$NAME" "$frame"); fi
  tiles=()
  for ((i = 1; i <= count; i++)); do tiles+=("$OUTDIR/tiles/$stem.tile_${i}_of_${count}.png"); done
  "$RENDER" assemble "${tiles[@]}" -o "$OUTDIR/$stem.png"
done < "$jobdir/assemble"
