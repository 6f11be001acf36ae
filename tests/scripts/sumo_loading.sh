# sumo_loading.sh - which commands load SUMO (issue 15): the commands that do
# not simulate never open its modules (the dynamic loader's own record,
# LD_DEBUG=files, names every library a process maps: libsumocpp must not be
# among them), and a run that simulates maps libsumocpp exactly once.  That
# run maps the build's stand-ins for libsumocpp's GUI libraries
# (scripts/sumo_gui_stubs.py) and none of the real ones, and gives the same
# results byte for byte as a run that loads the real ones
# (FAIRWAY_SUMO_GUI_LIBS=load).
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
# how many times the process (and its children) mapped libsumocpp; the
# loader's record kept in loader.txt
loads() {
  local rc=0
  LD_DEBUG=files LD_DEBUG_OUTPUT="$tmp/ld" "$FAIRWAY" "$@" > out 2>&1 || rc=$?
  [ "$rc" -le 2 ] || { echo "fairway $* died (exit $rc):"; head -5 out; exit 1; }
  cat "$tmp"/ld.* > loader.txt 2> /dev/null || : > loader.txt
  rm -f "$tmp"/ld.*
  grep -c 'file=libsumocpp\.so .*needed by' loader.txt || true
}
while IFS= read -r cmd; do
  # shellcheck disable=SC2086 # the command's words
  n=$(loads $cmd)
  [ "$n" -eq 0 ] || { echo "fairway $cmd loaded libsumocpp $n times"; exit 1; }
done <<LIST
--help
ship c3
manoeuvre report --ship c3
helm --ship c3 --own 0,0,0,10 --target 0,1800,180,10
identify --ship c3 --speeds 10 --rudders 10
calibrate --ship c3-paper --check
report nosuch.db
run --help
LIST
echo "non-simulating commands: no libsumocpp"
# netconvert runs too (the network cache off: always), and it links GDAL: the
# checks below are of the process that loaded the libsumo module
export FAIRWAY_NETCACHE=off
n=$(loads run "$FAIRWAY_DATA/scenarios/paper/1-head-on.yaml" --out runs)
grep -q "ok$" out || { echo "the run failed:"; cat out; exit 1; }
[ "$n" -eq 1 ] || { echo "a simulating run loaded libsumocpp $n times, not once"; exit 1; }
# the lines of the process that loaded the libsumo module
own_lines() {
  local pid
  pid=$(grep 'file=[^ ]*/fairway-libsumo\.so' loader.txt | head -1 | cut -d: -f1 | tr -d ' ')
  grep "^ *$pid:" loader.txt
}
own_lines > module.txt
# the GUI libraries: the stand-ins, by SONAME, and no real one
stubs=$(dirname "$(grep -o 'file=[^ ]*/fairway-libsumo\.so' module.txt | head -1 | cut -d= -f2)")/gui-stubs
[ -s "$stubs/stubs.txt" ] || { echo "no stand-ins listed in $stubs/stubs.txt"; exit 1; }
while IFS= read -r so; do
  grep -q "file=$stubs/$so .*dynamically loaded" module.txt || { echo "stand-in $so not opened"; exit 1; }
  if grep -E "file=$so \[0\];  needed by" module.txt | grep -q .; then
    echo "the real $so was looked for: $(grep -m1 "file=$so" module.txt)"; exit 1
  fi
done < "$stubs/stubs.txt"
grep -q 'file=libgdal\.so' module.txt && { echo "GDAL mapped: $(grep -m1 'file=libgdal' module.txt)"; exit 1; }
grep -q 'needed by [^ ]*netconvert' loader.txt || { echo "netconvert did not run (cache off)"; exit 1; }
real=$(FAIRWAY_SUMO_GUI_LIBS=load loads run "$FAIRWAY_DATA/scenarios/paper/1-head-on.yaml" --out real)
own_lines > module.txt
grep -q 'file=libgdal\.so.*needed by' module.txt || { echo "FAIRWAY_SUMO_GUI_LIBS=load did not map GDAL"; exit 1; }
[ "$real" -eq 1 ] || { echo "with the real GUI libraries libsumocpp was mapped $real times"; exit 1; }
for f in own.csv encounters.csv summary.json; do
  cmp "runs/paper-1-head-on/$f" "real/paper-1-head-on/$f" || { echo "$f differs with the real GUI libraries"; exit 1; }
done
echo "GUI libraries: $(wc -l < "$stubs/stubs.txt") stand-ins, none real; the same results with the real ones"
echo "ok: SUMO loaded only to simulate, once"
