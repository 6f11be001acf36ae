#!/usr/bin/env bash
# sweep_mpi_split.sh - a study's splitting estimates over MPI (sweep_mpi.c): mpirun -np 3
# (rank 0 commits, ranks 1 and 2 each make one (cell, batch) in a forked worker) gives the
# estimates of --jobs 1 to the bit, and a resumed MPI sweep makes only the missing one.
set -euo pipefail
study=$FAIRWAY_DATA/tests/data/study/split-watch.yaml
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
q="select cell, batch, status, rounds, runs, sim_s, p_collision, p_near_miss, best_closeness,
   best_path from splits order by cell, batch"
"$FAIRWAY" sweep "$study" --db "$dir/j1.db" --jobs 1 --progress none
timeout 300 mpirun --oversubscribe -np 3 "$FAIRWAY" sweep "$study" --db "$dir/mpi.db" \
  --progress lines > "$dir/out" 2>&1 || { cat "$dir/out"; exit 1; }
[ "$(sqlite3 "$dir/j1.db" "$q")" = "$(sqlite3 "$dir/mpi.db" "$q")" ] ||
  { echo "differ:"; sqlite3 "$dir/j1.db" "$q"; sqlite3 "$dir/mpi.db" "$q"; exit 1; }
[ "$(grep -c '^splitting: cell 0 .* batch [01]: ' "$dir/out")" -eq 2 ] || { cat "$dir/out"; exit 1; }
# resumed: batch 1 forgotten, made again alone, the same
sqlite3 "$dir/mpi.db" "delete from splits where batch = 1"
timeout 300 mpirun --oversubscribe -np 3 "$FAIRWAY" sweep "$study" --db "$dir/mpi.db" \
  --progress lines > "$dir/out2" 2>&1 || { cat "$dir/out2"; exit 1; }
grep -q '^splitting: cell 0 .* batch 1: ' "$dir/out2" && ! grep -q 'batch 0' "$dir/out2" ||
  { echo "resumed:"; cat "$dir/out2"; exit 1; }
[ "$(sqlite3 "$dir/j1.db" "$q")" = "$(sqlite3 "$dir/mpi.db" "$q")" ] ||
  { echo "differ after resuming"; exit 1; }
echo "ok: splitting over MPI as with --jobs 1, resumed"
