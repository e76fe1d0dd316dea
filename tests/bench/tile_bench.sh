#!/usr/bin/env bash
# tile_bench.sh: the tiled terrain benchmark (docs/terrain.md, "Tiles").
#
#   tile_bench.sh --meshstep PATH --make-grid PATH --tile-check PATH [--work DIR]
#                 [--columns 10000] [--rows 10000] [--tile 1000] [--max-error 0.1%]
#                 [--algorithm lepp-surface] [--keep]
#
# 1. make_grid writes a synthetic COLUMNS x ROWS .asc grid into DIR (kept there and reused:
#    1e8 samples are 756 MB; put DIR in /tmp, never in the repository);
# 2. meshstep terrain GRID --tile N --max-error E -o DIR/tiles/t.ply, timed by /usr/bin/time -v
#    (wall time and peak resident memory);
# 3. meshstep terrain-join of every tile: one boundary loop, no crack, the rectangle covered;
# 4. tile_check: every sample covered and within the bound, measured apart from meshstep;
# 5. one middle tile again alone (--tile-index), which must be byte for byte the same file,
#    with its own peak memory.
# Prints the figures and the memory bound; exits 1 if any check fails. CTest runs it on a
# small grid (bench.tile_bench_smoke); the 1e8 run is by hand.
set -euo pipefail

columns=10000 rows=10000 tile=1000 max_error=0.1% algorithm=lepp-surface keep=0
meshstep= make_grid= tile_check= work=/tmp/meshstep_tile_bench
while [[ $# -gt 0 ]]; do
  case "$1" in
    --columns) columns=$2; shift 2 ;;
    --rows) rows=$2; shift 2 ;;
    --tile) tile=$2; shift 2 ;;
    --max-error) max_error=$2; shift 2 ;;
    --algorithm) algorithm=$2; shift 2 ;;
    --meshstep) meshstep=$2; shift 2 ;;
    --make-grid) make_grid=$2; shift 2 ;;
    --tile-check) tile_check=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --keep) keep=1; shift ;;
    *) echo "tile_bench.sh: error: unknown argument $1" >&2; exit 2 ;;
  esac
done
for program in "$meshstep" "$make_grid" "$tile_check"; do
  if [[ ! -x "$program" ]]; then
    echo "tile_bench.sh: error: give --meshstep, --make-grid and --tile-check (programs)" >&2
    exit 2
  fi
done

mkdir -p "$work"
grid="$work/grid_${columns}x${rows}.asc"
tiles="$work/tiles"
rm -rf "$tiles"
mkdir -p "$tiles"

# /usr/bin/time -v where there is one (peak memory); else the wall clock alone.
timed() {
  local report=$1
  shift
  if [[ -x /usr/bin/time ]]; then
    /usr/bin/time -v -o "$report" "$@"
  else
    local start=$SECONDS
    "$@"
    echo "Elapsed (wall clock) time (h:mm:ss or m:ss): $((SECONDS - start)) s" > "$report"
  fi
}
wall() { sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$1"; }
peak_mib() {
  local kib
  kib=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$1")
  if [[ -n "$kib" ]]; then awk -v k="$kib" 'BEGIN { printf "%.1f", k / 1024 }'; else echo "?"; fi
}
json_field() { sed -n "s/.*\"$2\":\([^,}]*\).*/\1/p" "$1" | tail -1; }

if [[ ! -s "$grid" ]]; then
  echo "making $grid"
  timed "$work/make_grid.time" "$make_grid" "$columns" "$rows" "$grid"
fi
echo "grid: $grid ($(du -h "$grid" | cut -f1), $columns x $rows samples)"

timed "$work/terrain.time" "$meshstep" terrain "$grid" --tile "$tile" --max-error "$max_error" -a "$algorithm" \
  -o "$tiles/t.ply" --stats json > "$work/terrain.out"
stats="$work/terrain.out"
bound=$(json_field "$stats" bound)
tile_rows=$(json_field "$stats" tile_rows)
tile_columns=$(json_field "$stats" tile_columns)
echo "terrain: $(json_field "$stats" tiles) tiles ($tile_rows x $tile_columns), $(json_field "$stats" triangles) triangles," \
  "$(json_field "$stats" vertices) vertices, largest error $(json_field "$stats" max_error) (bound $bound)"
echo "  wall $(wall "$work/terrain.time"), peak RSS $(peak_mib "$work/terrain.time") MiB" \
  "(the band of rows: $(json_field "$stats" band_mib) MiB)"

status=0
timed "$work/join.time" "$meshstep" terrain-join "$tiles"/t.r*-c*.ply --stats json > "$work/join.out" || status=1
echo "join: $(head -1 "$work/join.out")"
echo "  wall $(wall "$work/join.time"), peak RSS $(peak_mib "$work/join.time") MiB"

timed "$work/check.time" "$tile_check" "$grid" "$tiles"/t.r*-c*.ply --bound "$bound" > "$work/check.out" || status=1
echo "tile_check: $(cat "$work/check.out")"

# A middle tile alone: the same file, byte for byte.
r=$((tile_rows / 2)) c=$((tile_columns / 2))
mkdir -p "$work/alone"
timed "$work/alone.time" "$meshstep" terrain "$grid" --tile "$tile" --tile-index "$r,$c" --max-error "$max_error" \
  -a "$algorithm" -o "$work/alone/t.ply" -q
if cmp -s "$work/alone/t.r$r-c$c.ply" "$tiles/t.r$r-c$c.ply"; then same="the same bytes"; else same="DIFFERENT"; status=1; fi
echo "tile $r,$c alone: $same as in the whole run; wall $(wall "$work/alone.time")," \
  "peak RSS $(peak_mib "$work/alone.time") MiB"

if [[ $keep -eq 0 ]]; then rm -rf "$tiles" "$work/alone"; fi
if [[ $status -ne 0 ]]; then echo "tile_bench.sh: a check failed" >&2; fi
exit $status
