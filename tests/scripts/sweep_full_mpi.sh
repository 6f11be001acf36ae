#!/usr/bin/env bash
# A full disk under mpirun (issue 28 item 7), as sweep_full.sh for --jobs:
# the sweep's work directory filling up stops the sweep with the message
# that says so (rank 0, for a run of another rank), no run recorded failed,
# nothing recorded after the stop (the count of runs not recorded holds),
# and the same command resumes; a disk already full, where the work
# directories or Open MPI's session files go, stops every rank before
# MPI_Init with the reason (there MPI_Init failed and mpirun waited for
# ever).  Needs a small tmpfs: mounted as root, else skipped.
set -u
dir=$(mktemp -d)
full=$dir/full
mkdir "$full" "$dir/sess"
if ! mount -t tmpfs -o size=512k tmpfs "$full" 2>/dev/null; then
  rm -rf "$dir"; echo "skipped: cannot mount a tmpfs (not root)"; exit 0
fi
trap 'umount "$full"; rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
study=$FAIRWAY_DATA/tests/data/study/small.yaml
fill() { # fill KB: leave about KB free
  rm -f "$full/filler"
  local free=$(df -k --output=avail "$full" | tail -1)
  dd if=/dev/zero of="$full/filler" bs=1k count=$((free - $1)) status=none 2>/dev/null
}
mpi() { # DB, then sweep options; Open MPI's session files in $dir/sess
  local db=$1; shift
  OMPI_MCA_orte_tmpdir_base=$dir/sess TMPDIR=$full timeout -s KILL 120 \
    mpirun --oversubscribe -np 3 "$FAIRWAY" sweep "$study" --db "$db" --progress none "$@" 2>&1
}
# the disk fills once the sweep is under way (its database made)
mpi "$dir/s.db" > "$dir/out" &
pid=$!
while kill -0 $pid 2>/dev/null && [ ! -e "$dir/s.db" ]; do sleep 0.02; done
fill 24
wait $pid
rc=$?
out=$(cat "$dir/out")
[ $rc -ne 137 ] || fail "mpirun hung: $out"
re="^fairway: the disk of the sweep's work directory in $full is full: run small-0000([0-9]{2}) failed \((.*[ (])?small-0000[0-9]{2}/.*No space left on device.*\); the sweep stopped there, that run and ([0-9]+) more are not recorded"
[ $rc -eq 1 ] && [[ $out =~ $re ]] ||
  fail "message (exit $rc): $out; $(ls -A "$full"); $(sqlite3 "$dir/s.db" "SELECT run_id, status, reason FROM runs" 2>&1)"
more=${BASH_REMATCH[3]} # groups: the run, what precedes its directory, the count
n=$(sqlite3 "$dir/s.db" "SELECT COUNT(*) FROM runs")
[ "$(sqlite3 "$dir/s.db" "SELECT COUNT(*) FROM runs WHERE status <> 'ok'")" = 0 ] ||
  fail "runs recorded failed: $(sqlite3 "$dir/s.db" "SELECT run_id, reason FROM runs WHERE status <> 'ok'")"
[ $((n + more + 1)) -eq 10 ] || fail "$n runs recorded, and that run and $more more not: not the 10"
[ -z "$(ls "$full" | grep -v '^filler$')" ] || fail "left in the work directory's place: $(ls "$full")"
echo "stopped: $n recorded, 1 + $more not: $out"
rm "$full/filler"
mpi "$dir/s.db" --limit 2 > /dev/null || fail "resume after freeing space"
[ "$(sqlite3 "$dir/s.db" "SELECT COUNT(*) FROM runs WHERE status = 'ok'")" = $((n + 2)) ] || fail "resumed runs"
# already full where the work directories go: every rank stops before MPI_Init
fill 24
out=$(mpi "$dir/t.db")
rc=$?
[ $rc -eq 1 ] && grep -qE "^fairway: (rank [0-9]+: )?the disk of the sweep's work directory in $full is full \(less than 64 kB left\); nothing was run" <<<"$out" ||
  fail "work disk full before the start: exit $rc: $out"
[ ! -e "$dir/t.db" ] || fail "a database made"
# Open MPI's session files on the small disk (TMPDIR): the ranks stop before
# MPI_Init saying so (mpirun passes them its session directory), and mpirun
# ends; or mpirun, short of room itself, fails before it starts them (either
# way within the timeout: before the check MPI_Init failed and mpirun waited
# for ever)
rm "$full/filler"
out=$(TMPDIR=$full timeout -s KILL 120 mpirun --oversubscribe -np 3 "$FAIRWAY" sweep "$study" \
      --db "$dir/t.db" --progress none 2>&1)
rc=$?
[ $rc -ne 0 ] && [ $rc -ne 137 ] && [ ! -e "$dir/t.db" ] || fail "session disk small: exit $rc: $out"
if grep -qE "^fairway: (rank [0-9]+: )?the disk of $full has too little room \([0-9]+ kB left\): Open MPI keeps its session files there" <<<"$out"; then
  echo "session disk small: said"
else
  grep -q "fairway" <<<"$out" && fail "session disk small: $out"
  echo "session disk small: mpirun failed by itself (exit $rc)"
fi
echo "ok: a full disk stops an MPI sweep and says so"
