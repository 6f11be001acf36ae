# install_layout.sh CMAKE BUILD_DIR - `cmake --install` into a temporary prefix, then
# the installed fairway run from an unrelated directory with FAIRWAY_DATA unset.
#
# The source tree cannot be taken away inside ctest, so the test proves the
# installed binary does without it instead: the prefix is moved after the
# install (nothing can point at where it was installed), a paper case and a
# network scenario run from the moved prefix and give the build tree's
# results byte for byte, and once the prefix's share/fairway is taken away the
# same run fails naming the prefix's data directory, although the source tree
# is still there to fall back on; without the prefix's lib/fairway (the SUMO
# modules) a run fails naming the module, and a command that does not
# simulate still works.
set -euo pipefail
cmake_cmd=$1 build=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$cmake_cmd" --install "$build" --prefix "$tmp/first" > "$tmp/install.log"
mv "$tmp/first" "$tmp/p"
p=$tmp/p
for f in bin/fairway lib/fairway/fairway-libsumo.so lib/fairway/fairway-libtraci.so lib/fairway/gui-stubs/stubs.txt \
         share/fairway/scenarios/ships/c3.yaml share/fairway/scenarios/paper/1-head-on.yaml \
         share/fairway/networks/ships.add.xml share/fairway/networks/dover/dover.nod.xml \
         share/fairway/networks/dover/demand.yaml share/fairway/analysis/plot_study.py \
         share/man/man1/fairway.1; do
  [ -e "$p/$f" ] || { echo "not installed: $f"; exit 1; }
done
# a manual page per command the main help lists, made from that command's help
cmds=$("$p/bin/fairway" --help | sed -n '/^commands:/,/^$/p' | awk 'NF > 1 {print $1}')
[ -n "$cmds" ] || { echo "fairway --help lists no commands"; exit 1; }
for c in $cmds; do
  page=$p/share/man/man1/fairway-$c.1
  [ -f "$page" ] || { echo "no manual page for $c"; exit 1; }
  grep -q "^\.TH FAIRWAY-${c^^} 1" "$page" || { echo "$page: no .TH line"; exit 1; }
  usage=$("$p/bin/fairway" "$c" --help | head -1 | sed 's/^usage: //; s/\\/\\e/g')
  grep -qF -- "$usage" "$page" || { echo "$page: lacks the usage line '$usage'"; exit 1; }
done
echo "layout ok: $(echo $cmds | wc -w) command pages"

mkdir "$tmp/elsewhere" "$tmp/ref"
scenarios="$p/share/fairway/scenarios/paper/1-head-on.yaml $p/share/fairway/scenarios/traffic/dover-crossing.yaml"
# the build tree's fairway on the source tree: the reference
"$FAIRWAY" run $scenarios --out "$tmp/ref/runs" > "$tmp/ref/table"
cd "$tmp/elsewhere"
env -u FAIRWAY_DATA -u FAIRWAY_PYTHON PATH=/usr/bin:/bin "$p/bin/fairway" run $scenarios --out runs > table
grep -q "^paper-1-head-on .* ok$" table || { echo "installed run failed:"; cat table; exit 1; }
grep -q "^dover-crossing .* ok$" table || { echo "installed network run failed:"; cat table; exit 1; }
for r in paper-1-head-on dover-crossing; do
  for f in own.csv encounters.csv summary.json; do
    cmp -s "runs/$r/$f" "$tmp/ref/runs/$r/$f" || { echo "$r/$f differs from the build tree's"; exit 1; }
  done
done
echo "installed runs ok: the build tree's results"

# take the SUMO modules away: what does not simulate still works, a run
# says which module it misses (exit 1: the input was fine)
mv "$p/lib/fairway" "$p/lib/gone"
"$p/bin/fairway" ship c3 > out 2>&1 || { echo "ship c3 needs the SUMO modules:"; cat out; exit 1; }
rc=0
env -u FAIRWAY_DATA "$p/bin/fairway" run "$p/share/fairway/scenarios/traffic/dover-crossing.yaml" \
  --out runs3 > out 2>&1 || rc=$?
if [ "$rc" -ne 1 ] || ! grep -qF "cannot load the SUMO back end $p/lib/fairway/fairway-libsumo.so" out; then
  echo "without its SUMO modules the installed fairway gave exit $rc:"; cat out; exit 1
fi
echo "without lib/fairway: $(grep -F 'cannot load' out | head -1)"
mv "$p/lib/gone" "$p/lib/fairway"

# take the prefix's data away: no fallback to the source tree may hide it
mv "$p/share/fairway" "$p/share/gone"
cp "$p/share/gone/scenarios/paper/1-head-on.yaml" .
rc=0
env -u FAIRWAY_DATA "$p/bin/fairway" run 1-head-on.yaml --out runs2 > out 2>&1 || rc=$?
if [ "$rc" -ne 2 ] || ! grep -qF "$p/share/fairway/scenarios/ships/" out; then
  echo "without its data the installed fairway gave exit $rc:"; cat out; exit 1
fi
echo "without share/fairway: $(head -1 out)"
echo "ok: installed fairway uses its prefix"
