#!/usr/bin/env bash
# Submits a Spindulys render to Slurm: one job array with a task per chunk of whole frames and
# per tile of each frame split into tiles, and an assemble job that depends on it (afterok: it
# runs only when every task succeeded). See docs/farm.md.
#
#   farm/slurm/submit.sh [options] SCENE.dat OUTDIR [-- RENDER OPTIONS...]
#
#   --frames A-B        frames to render (a scene with animation); without it the scene's one frame
#   --chunk K           whole frames per task (default 1)
#   --tile-frames LIST  frames split into tiles instead, comma-separated ("-" without --frames:
#                       the one frame), each rendered as --tiles tasks and then assembled
#   --tiles N           tiles per split frame (default 4): bands of whole rows, see render --tile
#   --render PATH       the render command the nodes run (default: render beside this checkout)
#   --sbatch OPTION     one more sbatch option for both jobs (repeatable), e.g. --sbatch=--partition=cpu
#   RENDER OPTIONS      passed to every task, e.g. -- --spp 64 --width 1920
#
# Prints "ARRAY_JOB ASSEMBLE_JOB" (the job ids; ASSEMBLE_JOB is "-" when no frame is tiled) and
# writes the job's files into OUTDIR/.spindulys-job: settings, tasks, render-args, assemble.
# Images: OUTDIR/NAME_####.png (or OUTDIR/NAME.png for one frame), tiles in OUTDIR/tiles/.
# OUTDIR and the scene must be on storage every node sees.
set -euo pipefail
here="$(cd -P "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
render="$here/../../render"
frames="" chunk=1 tile_frames="" tiles=4
sbatch_opts=()
die() { echo "submit.sh: $*" >&2; exit 2; }
need() { [ $# -ge 2 ] || die "option $1 needs a value"; }
while [ $# -gt 0 ]; do
  case "$1" in
    --frames) need "$@"; frames=$2; shift 2 ;;
    --chunk) need "$@"; chunk=$2; shift 2 ;;
    --tile-frames) need "$@"; tile_frames=$2; shift 2 ;;
    --tiles) need "$@"; tiles=$2; shift 2 ;;
    --render) need "$@"; render=$2; shift 2 ;;
    --sbatch=*) sbatch_opts+=("${1#--sbatch=}"); shift ;;
    --) shift; break ;;
    -*) die "unknown option '$1'" ;;
    *) break ;;
  esac
done
[ $# -ge 2 ] || die "usage: submit.sh [options] SCENE.dat OUTDIR [-- RENDER OPTIONS...]"
scene=$1 outdir=$2
shift 2
if [ $# -gt 0 ] && [ "$1" = "--" ]; then shift; fi
[ -f "$scene" ] || die "scene file $scene not found"
[[ "$chunk" =~ ^[1-9][0-9]*$ ]] || die "--chunk expects a whole number from 1, found '$chunk'"
[[ "$tiles" =~ ^[1-9][0-9]*$ ]] || die "--tiles expects a whole number from 1, found '$tiles'"
render="$(cd -P "$(dirname "$render")" && pwd)/$(basename "$render")"
[ -x "$render" ] || die "the render command $render is not executable"
mkdir -p "$outdir/tiles"
outdir="$(cd -P "$outdir" && pwd)"
scene="$(cd -P "$(dirname "$scene")" && pwd)/$(basename "$scene")"
name=$(basename "$scene"); name=${name%.*}
jobdir="$outdir/.spindulys-job"
mkdir -p "$jobdir"
printf 'RENDER=%q\nSCENE=%q\nNAME=%q\nOUTDIR=%q\n' "$render" "$scene" "$name" "$outdir" > "$jobdir/settings"
if [ $# -gt 0 ]; then printf '%s\n' "$@" > "$jobdir/render-args"; else : > "$jobdir/render-args"; fi

# The task list: chunks of whole frames (skipping the tiled ones), then the tiles of each tiled frame.
: > "$jobdir/tasks"
: > "$jobdir/assemble"
declare -A tiled=()
IFS=, read -r -a tile_list <<<"$tile_frames"
for f in "${tile_list[@]}"; do
  [ -n "$f" ] || continue
  if [ -z "$frames" ]; then [ "$f" = "-" ] || die "--tile-frames without --frames takes '-' (the scene's one frame), found '$f'"
  else [[ "$f" =~ ^-?[0-9]+$ ]] || die "--tile-frames expects frame numbers, found '$f'"; fi
  tiled[$f]=1
done
if [ -z "$frames" ]; then
  [ -n "${tiled[-]:-}" ] || echo "- -" >> "$jobdir/tasks"
else
  [[ "$frames" =~ ^(-?[0-9]+)-(-?[0-9]+)$ ]] || die "--frames expects A-B, found '$frames'"
  first=${BASH_REMATCH[1]} last=${BASH_REMATCH[2]}
  [ "$first" -le "$last" ] || die "--frames $frames: the first frame is after the last"
  start=""
  for ((f = first; f <= last + 1; f++)); do
    # A chunk ends at a tiled frame, at the chunk size, and after the last frame.
    if [ "$f" -gt "$last" ] || [ -n "${tiled[$f]:-}" ] || { [ -n "$start" ] && [ $((f - start)) -ge "$chunk" ]; }; then
      if [ -n "$start" ]; then
        if [ $((f - 1)) -eq "$start" ]; then echo "$start -" >> "$jobdir/tasks"; else echo "$start-$((f - 1)) -" >> "$jobdir/tasks"; fi
        start=""
      fi
    fi
    if [ "$f" -le "$last" ] && [ -z "${tiled[$f]:-}" ] && [ -z "$start" ]; then start=$f; fi
  done
fi
for f in "${tile_list[@]}"; do
  [ -n "$f" ] || continue
  for ((i = 1; i <= tiles; i++)); do echo "$f $i/$tiles" >> "$jobdir/tasks"; done
  echo "$f $tiles" >> "$jobdir/assemble"
done
count=$(wc -l < "$jobdir/tasks")
[ "$count" -gt 0 ] || die "no task to submit"

array=$(sbatch --parsable "${sbatch_opts[@]}" --job-name="spindulys-$name" --array="0-$((count - 1))" \
  --output="$jobdir/task_%a.log" "$here/render-task.sh" "$jobdir")
array=${array%%;*}
assemble="-"
if [ -s "$jobdir/assemble" ]; then
  assemble=$(sbatch --parsable "${sbatch_opts[@]}" --job-name="spindulys-$name-assemble" --dependency="afterok:$array" \
    --output="$jobdir/assemble.log" "$here/assemble.sh" "$jobdir")
  assemble=${assemble%%;*}
fi
echo "$array $assemble"
