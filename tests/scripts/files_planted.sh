#!/usr/bin/env bash
# Outputs are never written through a symlink fairway did not make (issue 28,
# Files): a symlink planted at the temporary name fairway used to write
# through (OUT.tmp) or at the output itself leaves the file it points to
# byte for byte as it was, and the output is written in its own place
# (manoeuvre --csv, ais tracks and demand --out, traffic --routes and the
# SUMO log it names); "-",
# /dev/stdout and a link to this process's standard output are written as a
# stream and printed, never replaced by a regular file (manoeuvre, ais
# tracks, identify).
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
ais=$FAIRWAY_DATA/scenarios/ais/aisdk-2026-03-01.csv
printf 'the victim: not an output of fairway\n' > "$dir/victim"
want=$(sha256sum < "$dir/victim")
victim_intact() { [ "$(sha256sum < "$dir/victim")" = "$want" ] || fail "$1: the victim was written"; }

# writer NAME OUT HEADER: runs the writer NAME into OUT; HEADER is its file's first line
writer() {
  case $1 in
    manoeuvre) "$FAIRWAY" manoeuvre turning --ship c3 --speed 20 --rudder 35 --csv "$2" ;;
    tracks) "$FAIRWAY" ais tracks "$ais" --origin 56.5,11.5 --out "$2" 2>/dev/null ;;
    demand) "$FAIRWAY" ais demand "$ais" --network channel --origin 56.5,11.5 --out "$2" ;;
    identify) "$FAIRWAY" identify --ship c3 --speeds 10,12,14 --rudders 10,20,30 --out "$2" ;;
  esac
}
declare -A head=([manoeuvre]="t_s,east_m,north_m,heading_deg" [tracks]="t_s,id,east_m,north_m"
                 [demand]="# Demand of network channel from AIS" [identify]="name: c3")
for w in manoeuvre tracks demand; do
  out=$dir/$w.out
  # at the old predictable temporary name
  ln -s "$dir/victim" "$out.tmp"
  msg=$(writer $w "$out" 2>&1) || fail "$w with $out.tmp planted: exit $?: $msg"
  victim_intact "$w, link at $out.tmp"
  [ -f "$out" ] && [ ! -L "$out" ] && head -1 "$out" | grep -q "^${head[$w]}" ||
    fail "$w: $out not written: $(head -c 200 "$out" 2>&1)"
  rm -f "$out" "$out.tmp"
  # at the output itself: the link is replaced, not written through
  ln -s "$dir/victim" "$out"
  msg=$(writer $w "$out" 2>&1) || fail "$w with $out planted: exit $?: $msg"
  victim_intact "$w, link at $out"
  [ -f "$out" ] && [ ! -L "$out" ] || fail "$w: $out still a link"
  left=$(ls -A "$dir" | grep -F "$w.out." || true)
  [ -z "$left" ] || fail "$w left $left"
done

# fairway traffic's route file (it runs in $dir: its log and run.sumocfg go there)
ln -s "$dir/victim" "$dir/r.rou.xml" && ln -s "$dir/victim" "$dir/r.rou.xml.tmp"
# and SUMO's log (default fairway-traffic.log), which SUMO itself opens: SUMO
# wrote its messages into the victim
ln -s "$dir/victim" "$dir/fairway-traffic.log"
msg=$(cd "$dir" && "$FAIRWAY" traffic --network channel --ships 5 --duration 60 --every 60 \
        --routes "$dir/r.rou.xml" 2>&1) || fail "traffic: exit $?: $msg"
victim_intact "traffic --routes, links at r.rou.xml, r.rou.xml.tmp and fairway-traffic.log"
[ -f "$dir/fairway-traffic.log" ] && [ ! -L "$dir/fairway-traffic.log" ] &&
  grep -q "Simulation ended" "$dir/fairway-traffic.log" || fail "traffic: SUMO's log not in its place"
[ -f "$dir/r.rou.xml" ] && [ ! -L "$dir/r.rou.xml" ] && grep -q "<routes>" "$dir/r.rou.xml" ||
  fail "traffic: no route file"
rm -f "$dir"/r.rou.xml* "$dir/run.sumocfg" "$dir/fairway-traffic.log"

# streams: "-", a link of ours to the standard output, then /dev/stdout itself
# (last: as root a regression would replace /dev/stdout, the first two catch it)
ln -s /proc/self/fd/1 "$dir/to-stdout"
for out in - "$dir/to-stdout" /dev/stdout; do
  for w in manoeuvre tracks identify; do
    got=$(writer $w "$out" 2>&1) || fail "$w --out $out: exit $?: $got"
    grep -q "^${head[$w]}" <<<"$got" || fail "$w --out $out printed no file: $(head -c 300 <<<"$got")"
  done
  lines=$(writer tracks "$out" | wc -l)
  [ "$lines" -eq 1199 ] || fail "tracks --out $out: $lines lines, expected 1199"
done
[ -L "$dir/to-stdout" ] || fail "the link to the standard output was replaced"
[ -L /dev/stdout ] || [ ! -f /dev/stdout ] || fail "/dev/stdout replaced by a regular file"
[ -z "$(ls -A "$dir" | grep -v '^\(victim\|to-stdout\|[a-z]*\.out\|[a-z]*\.out\.tmp\)$')" ] ||
  fail "left: $(ls -A "$dir")"
echo "ok: nothing written through a planted link, streams printed"
