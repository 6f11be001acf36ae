#!/usr/bin/env bash
# Output directories (issue 28, Files): fairway deletes only what it wrote.
# `report --out DIR` with a file of the user's in DIR refuses it and leaves
# DIR as it was; `worst --out DIR` with DIR/case-1 a planted symlink writes
# nothing into, and deletes nothing from, what it points to; links planted at
# a case's tracks.csv and scenario.yaml are replaced, never written through;
# `run --out DIR` and `sweep --keep DIR` refuse a DIR/NAME that is not a run
# directory.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
tree() { (cd "$1" && find . -printf '%p %y %s\n' | sort && find . -type f -exec sha256sum {} + | sort); }

# report: an earlier report is replaced, a directory with a foreign file refused
"$FAIRWAY" sweep "$FAIRWAY_DATA/tests/data/study/small.yaml" --db "$dir/s.db" --limit 2 \
  --progress none >/dev/null 2>&1 || fail "sweep"
"$FAIRWAY" report "$dir/s.db" --out "$dir/rep" --no-plots >/dev/null 2>&1 || fail "first report"
"$FAIRWAY" report "$dir/s.db" --out "$dir/rep" --no-plots >/dev/null 2>&1 || fail "report over a report"
echo "my notes" > "$dir/rep/notes.txt"
before=$(tree "$dir/rep")
msg=$("$FAIRWAY" report "$dir/s.db" --out "$dir/rep" --no-plots 2>&1)
rc=$?
[ $rc -eq 2 ] || fail "report into a directory with notes.txt: exit $rc: $msg"
grep -qF "$dir/rep is not a fairway report directory: it holds notes.txt" <<<"$msg" || fail "message: $msg"
[ "$(tree "$dir/rep")" = "$before" ] || fail "the report directory changed"
# a planted link among a report's own names is not the report's either
rm "$dir/rep/notes.txt"
ln -s "$dir/s.db" "$dir/rep/runs.csv.lnk" && mv -f "$dir/rep/runs.csv.lnk" "$dir/rep/runs.csv"
msg=$("$FAIRWAY" report "$dir/s.db" --out "$dir/rep" --no-plots 2>&1)
[ $? -eq 2 ] && grep -qF "it holds runs.csv" <<<"$msg" || fail "linked runs.csv: $msg"
[ -L "$dir/rep/runs.csv" ] || fail "the link was removed"
ls -A "$dir" | grep -q '^\.rep\.' && fail "left: $(ls -A "$dir")"

# worst: DIR/case-1 a link to a directory of the user's
study=$FAIRWAY_DATA/tests/data/study/worst.yaml
"$FAIRWAY" sweep "$study" --db "$dir/w.db" --progress none >/dev/null 2>&1 || fail "worst sweep"
mkdir -p "$dir/victim/rerun" "$dir/victim/replay" "$dir/w"
echo keep > "$dir/victim/tracks.csv"; echo keep > "$dir/victim/rerun/run.log"
echo keep > "$dir/victim/replay/own.csv"
before=$(tree "$dir/victim")
ln -s "$dir/victim" "$dir/w/case-1"
msg=$("$FAIRWAY" worst "$dir/w.db" --out "$dir/w" --n 1 --study "$study" 2>&1)
rc=$?
[ $rc -eq 2 ] || fail "worst into a planted case-1: exit $rc: $msg"
grep -qF -- "--out $dir/w/case-1: a symlink, not a directory fairway made" <<<"$msg" || fail "message: $msg"
[ "$(tree "$dir/victim")" = "$before" ] || fail "the link's target changed: $(tree "$dir/victim")"
# links at the case's files: replaced, the victim untouched
rm "$dir/w/case-1" && mkdir "$dir/w/case-1"
echo "the victim" > "$dir/file"
want=$(sha256sum < "$dir/file")
for f in tracks.csv scenario.yaml tracks.csv.tmp scenario.yaml.tmp; do ln -s "$dir/file" "$dir/w/case-1/$f"; done
msg=$("$FAIRWAY" worst "$dir/w.db" --out "$dir/w" --n 1 --study "$study" 2>&1) || fail "worst: $msg"
[ "$(sha256sum < "$dir/file")" = "$want" ] || fail "written through a link in case-1"
[ -f "$dir/w/case-1/tracks.csv" ] && [ ! -L "$dir/w/case-1/tracks.csv" ] &&
  [ ! -L "$dir/w/case-1/scenario.yaml" ] || fail "case files not written in place"
# run: DIR/NAME of the user's (a file in a directory, a link) refused before any run
scn=$FAIRWAY_DATA/tests/data/study/base.yaml
mkdir -p "$dir/runs/study-base" && echo mine > "$dir/runs/study-base/thesis.tex"
msg=$("$FAIRWAY" run "$scn" --out "$dir/runs" 2>&1)
[ $? -eq 2 ] && grep -qF "$dir/runs/study-base is not a run directory of fairway" <<<"$msg" ||
  fail "run into a foreign DIR/NAME: $msg"
[ "$(cat "$dir/runs/study-base/thesis.tex")" = mine ] || fail "thesis.tex lost"
rm -r "$dir/runs/study-base" && ln -s "$dir/victim" "$dir/runs/study-base"
msg=$("$FAIRWAY" run "$scn" --out "$dir/runs" 2>&1)
[ $? -eq 2 ] && grep -qF "exists and is not a run directory (a symlink)" <<<"$msg" ||
  fail "run into a link: $msg"
[ "$(tree "$dir/victim")" = "$before" ] || fail "run changed the link's target"
# sweep --keep DIR: DIR/NAME of the user's (a directory with a file, a link)
# refused before the database is made (the sweep replaced them, deleting
# notes.txt); an earlier sweep's run directories are replaced
small=$FAIRWAY_DATA/tests/data/study/small.yaml
mkdir -p "$dir/keep/small-000001" && echo mine > "$dir/keep/small-000001/notes.txt"
msg=$("$FAIRWAY" sweep "$small" --db "$dir/k.db" --keep "$dir/keep" --limit 2 --progress none 2>&1)
[ $? -eq 2 ] && grep -qF -- "--keep: $dir/keep/small-000001 is not a run directory of fairway" <<<"$msg" ||
  fail "sweep --keep into a foreign DIR/NAME: $msg"
[ "$(cat "$dir/keep/small-000001/notes.txt")" = mine ] && [ ! -e "$dir/k.db" ] || fail "notes.txt lost or k.db made"
rm -r "$dir/keep/small-000001" && ln -s "$dir/victim" "$dir/keep/small-000001"
msg=$("$FAIRWAY" sweep "$small" --db "$dir/k.db" --keep "$dir/keep" --limit 2 --progress none 2>&1)
[ $? -eq 2 ] && grep -qF "small-000001 exists and is not a run directory (a symlink)" <<<"$msg" ||
  fail "sweep --keep into a link: $msg"
[ "$(tree "$dir/victim")" = "$before" ] || fail "sweep changed the link's target"
echo "ok: only fairway's own files replaced"
