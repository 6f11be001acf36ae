#!/usr/bin/env bash
# mpirun -np 3 (rank 0 writes, ranks 1 and 2 run) gives the results of --jobs 1.
set -eu
study=$FAIRWAY_DATA/tests/data/study/small.yaml
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# root in CI containers; 3 ranks on 2 cores; no ssh: every rank is local
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
"$FAIRWAY" sweep "$study" --db "$dir/j1.db" --jobs 1 --progress none
timeout 300 mpirun --oversubscribe -np 3 "$FAIRWAY" sweep "$study" --db "$dir/mpi.db" --progress lines
"$PYTHON" "$FAIRWAY_DATA/tests/scripts/study_db_compare.py" "$dir/j1.db" "$dir/mpi.db"
