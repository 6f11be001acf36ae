# fairway report refuses unusable input with exit 2, one line naming the file,
# and writes nothing.   Usage: report_bad.sh MAKE_STUDY_DB
set -u
make_db=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
expect() { # expect PATTERN ARGS...: exit 2, one line matching, no report directory
  local pattern=$1
  shift
  out=$("$FAIRWAY" report "$@" --out "$dir/out" 2>&1)
  rc=$?
  [ "$rc" -eq 2 ] || fail "exit $rc, expected 2: $*: $out"
  [ "$(wc -l <<<"$out")" -eq 1 ] || fail "more than one line: $out"
  grep -Eq -- "$pattern" <<<"$out" || fail "output does not match /$pattern/: $out"
  [ ! -e "$dir/out" ] || fail "report directory written for $*"
  ls -a "$dir" | grep -q '\.tmp\.' && fail "temporary directory left behind for $*"
  return 0
}
"$make_db" failed "$dir/failed.db" || fail "make_study_db failed"
"$make_db" hand "$dir/hand.db" || fail "make_study_db hand"
echo "just text" > "$dir/notes.db"
expect "failed.db: no finished runs \(2 failed" "$dir/failed.db"
expect "hand.db \(domain sizes: 100, 500 m\)" "$dir/hand.db" --reference 250
expect "notes.db: not a fairway study database" "$dir/notes.db"
expect "nosuch.db: no such file" "$dir/nosuch.db"
# a directory of something else is not replaced
mkdir "$dir/keep" && echo x > "$dir/keep/data.txt"
out=$("$FAIRWAY" report "$dir/hand.db" --out "$dir/keep" --no-plots 2>&1)
[ $? -eq 2 ] && grep -q "not a fairway report directory" <<<"$out" || fail "foreign --out: $out"
[ -f "$dir/keep/data.txt" ] || fail "foreign directory touched"
echo "ok: refused, nothing written"
