#!/usr/bin/env bash
# A file that is not the kind an option expects (a ship named /etc/shadow) is
# refused with FILE:LINE and exit 2, and no line of it is printed (issue 28).
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
f=$dir/shadow
printf 'root:$6$s3cretHASH:19000:0:99999:7:::\ndaemon:*:19000:0:99999:7:::\n' > "$f"
cp "$f" "$dir/shadow.json" # read as a DNV situation: Jansson's message quoted 'root'
for args in "ship $f" "manoeuvre turning --ship $f --speed 10 --rudder 35" \
            "calibrate --ship c3 --trial $f" "run $f" "sweep $f --db $dir/x.db" \
            "traffic --demand $f" "run $dir/shadow.json" "situation $f --out $dir/s"; do
  out=$(cd "$dir" && "$FAIRWAY" $args 2>&1)
  rc=$?
  [ $rc -eq 2 ] || fail "$args: exit $rc: $out"
  grep -qE "$dir/shadow(\.json)?:1:" <<<"$out" || fail "$args: no FILE:LINE: $out"
  grep -q 'root\|s3cret\|99999' <<<"$out" && fail "$args printed the file: $out"
done
echo "ok: no line of a foreign file printed"
