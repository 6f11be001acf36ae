#!/usr/bin/env bash
# A full disk (issue 28 item 7): a sweep whose work directory fills stops with
# a message that says so (instead of marking every remaining run failed), no
# run recorded as failed, and the same command resumes once there is room; a
# database that cannot be created on a full disk says the disk is full
# (was "not a usable SQLite database: database or disk is full", exit 2) and
# leaves nothing.  Needs a small tmpfs: mounted as root, else skipped.
set -u
dir=$(mktemp -d)
full=$dir/full
mkdir "$full"
if ! mount -t tmpfs -o size=512k tmpfs "$full" 2>/dev/null; then
  rm -rf "$dir"; echo "skipped: cannot mount a tmpfs (not root)"; exit 0
fi
trap 'umount "$full"; rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
study=$FAIRWAY_DATA/tests/data/study/small.yaml
fill() { # fill KB: leave about KB free
  rm -f "$full/filler"
  local free=$(df -k --output=avail "$full" | tail -1)
  dd if=/dev/zero of="$full/filler" bs=1k count=$((free - $1)) status=none 2>/dev/null
}
fill 24
out=$(TMPDIR=$full "$FAIRWAY" sweep "$study" --db "$dir/s.db" --jobs 2 --progress none 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "sweep on a full disk: exit $rc: $out"
grep -qE "^fairway: the disk of the sweep's work directory in $full is full: run small-0000(00|01) failed \(small-0000(00|01)/.*No space left on device\); the sweep stopped there, that run and 9 more are not recorded" <<<"$out" ||
  fail "message: $out"
[ "$(sqlite3 "$dir/s.db" "SELECT COUNT(*) FROM runs")" = 0 ] || fail "runs recorded: $(sqlite3 "$dir/s.db" "SELECT run_id, status, reason FROM runs")"
[ -z "$(ls "$full" | grep -v '^filler$')" ] || fail "left in the work directory's place: $(ls "$full")"
rm "$full/filler"
TMPDIR=$full "$FAIRWAY" sweep "$study" --db "$dir/s.db" --limit 2 --progress none >/dev/null 2>&1 ||
  fail "resume after freeing space"
[ "$(sqlite3 "$dir/s.db" "SELECT group_concat(status) FROM runs")" = "ok,ok" ] || fail "resumed runs"
# the database itself on the full disk
fill 4
out=$("$FAIRWAY" sweep "$study" --db "$full/x.db" --progress none 2>&1)
rc=$?
[ $rc -eq 1 ] && grep -q "^fairway: $full/x.db: .*(the disk holding the database is full: free space, then run the same command again to resume)" <<<"$out" ||
  fail "database on a full disk: exit $rc: $out"
[ "$(ls "$full")" = filler ] || fail "left: $(ls "$full")"
echo "ok: a full disk stops the sweep and says so"
