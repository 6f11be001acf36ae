# network_user.sh - a network of the user's own (traffic/netbuild.h
# fw_network_build), as a user adds one: networks/bend copied to a new name
# under a FAIRWAY_DATA of their own, with no rebuild of fairway.  The first
# run builds its net.xml into the network cache, SUMO reads that file, a
# second run reuses it; an edited shape point is built again and the next run
# sails the new network; a scenario may name the directory by its path;
# parallel runs on a new version leave one whole entry and nothing half
# written; a network without nodes or with edges netconvert refuses is
# FILE:LINE: FIELD, exit 2, nothing run.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export XDG_CACHE_HOME=$tmp/cache TMPDIR=$tmp/t
mkdir -p "$tmp/data/networks" "$tmp/data/scenarios" "$TMPDIR" "$tmp/elsewhere"
cp -r "$FAIRWAY_DATA/scenarios/ships" "$tmp/data/scenarios/"
cp "$FAIRWAY_DATA/networks/ships.add.xml" "$tmp/data/networks/"
mine=$tmp/data/networks/mine
mkdir "$mine"
cp "$FAIRWAY_DATA/networks/bend/demand.yaml" "$mine/"
for x in nod edg typ; do cp "$FAIRWAY_DATA/networks/bend/bend.$x.xml" "$mine/mine.$x.xml"; done
scen() { # NETWORK: a short scenario on it
  sed -e "s|network: bend|network: $1|" -e 's/duration_s: 3600/duration_s: 60/' \
      -e 's/fill: 20/fill: 6/' -e 's/^name: bend-watch/name: mine/' \
      "$FAIRWAY_DATA/tests/data/bend_traffic.yaml"
}
scen mine > "$tmp/data/scenarios/mine.yaml"
scen ../data/networks/mine > "$tmp/elsewhere/by-path.yaml"
export FAIRWAY_DATA=$tmp/data
run() { # OUT SCENARIO
  "$FAIRWAY" run "$2" --out "$tmp/$1" > "$tmp/$1.table" 2>&1 ||
    { echo "run $1 failed:"; cat "$tmp/$1.table"; exit 1; }
}
net_of() { sed -n 's/.*<net-file value="\([^"]*\)".*/\1/p' "$tmp/$1/mine/sumo/run.sumocfg"; }
entries() { find "$XDG_CACHE_HOME/fairway/net" -mindepth 1 -maxdepth 1 -type d -name '[0-9a-f]*' | wc -l; }

run first "$tmp/data/scenarios/mine.yaml"
n1=$(net_of first)
case "$n1" in "$XDG_CACHE_HOME"/fairway/net/*/net.xml) ;; *) echo "SUMO read $n1, not the cache's"; exit 1;; esac
grep -q '<junction id="B" type="unregulated" x="10000.00" y="0.00"' "$n1" ||
  { echo "the built network is not mine.nod.xml's"; exit 1; }
grep -q '<output-file value="mine.net.xml"/>' "$n1" || { echo "the header names a build path"; exit 1; }
run second "$tmp/data/scenarios/mine.yaml"
[ "$(net_of second)" = "$n1" ] && [ "$(entries)" -eq 1 ] || { echo "not reused: $(entries) entries"; exit 1; }
cmp -s "$tmp/first/mine/own.csv" "$tmp/second/mine/own.csv" || { echo "the same network gave another run"; exit 1; }
# a damaged cache file (truncated) is found by its size and digest and built again
cp "$n1" "$tmp/n1.xml"
head -c 500 "$tmp/n1.xml" > "$n1"
run repaired "$tmp/data/scenarios/mine.yaml"
[ "$(net_of repaired)" = "$n1" ] && cmp -s "$n1" "$tmp/n1.xml" || { echo "the damaged net.xml was used"; exit 1; }
cmp -s "$tmp/first/mine/own.csv" "$tmp/repaired/mine/own.csv" || { echo "the rebuilt network gave another run"; exit 1; }
echo "built on first use, reused after, rebuilt when damaged"

# a shape point moved: built again, the next run on the new network
sed -i 's/<node id="B" x="10000" y="0"/<node id="B" x="10000" y="800"/' "$mine/mine.nod.xml"
run edited "$tmp/data/scenarios/mine.yaml"
n2=$(net_of edited)
[ "$n2" != "$n1" ] && [ "$(entries)" -eq 2 ] || { echo "the edit was not built: $n2"; exit 1; }
grep -q '<junction id="B" type="unregulated" x="10000.00" y="800.00"' "$n2" ||
  { echo "the run's network is not the edited one"; exit 1; }
cmp -s "$tmp/first/mine/traffic_encounters.csv" "$tmp/edited/mine/traffic_encounters.csv" &&
  { echo "the edited network changed nothing in the run"; exit 1; }
# the same sources named by their directory's path, from another directory
(cd "$tmp/elsewhere" && "$FAIRWAY" run by-path.yaml --out "$tmp/bypath" > /dev/null 2>&1) ||
  { echo "a network named by its path failed"; exit 1; }
[ "$(net_of bypath)" = "$n2" ] || { echo "by path: $(net_of bypath), not $n2"; exit 1; }
echo "an edit is built again and sailed"

# three runs at once on a new version: one whole entry, nothing left over
sed -i 's/y="800"/y="600"/' "$mine/mine.nod.xml"
for k in 1 2 3; do run "par$k" "$tmp/data/scenarios/mine.yaml" & done
wait
[ "$(entries)" -eq 3 ] || { echo "parallel runs: $(entries) entries, not 3"; exit 1; }
for k in 2 3; do
  [ "$(net_of par$k)" = "$(net_of par1)" ] || { echo "parallel runs read different files"; exit 1; }
  cmp -s "$tmp/par1/mine/own.csv" "$tmp/par$k/mine/own.csv" || { echo "parallel runs differ"; exit 1; }
done
left=$( (find "$XDG_CACHE_HOME" -name '.tmp*'; find "$TMPDIR" -mindepth 1) | wc -l)
[ "$left" -eq 0 ] || { echo "parallel builds left $left temporary files"; exit 1; }
# no cache: the network is still built, in a directory of the user's under TMPDIR
FAIRWAY_NETCACHE=off run nocache "$tmp/data/scenarios/mine.yaml"
case "$(net_of nocache)" in "$TMPDIR/fairway-$(id -u)/net/"*) ;; *) echo "no cache: $(net_of nocache)"; exit 1;; esac
cmp -s "$tmp/par1/mine/own.csv" "$tmp/nocache/mine/own.csv" || { echo "without the cache another run"; exit 1; }
echo "parallel builds whole, no cache handled"

# bad networks: FILE:LINE: FIELD, exit 2, nothing run
bad() { # PATTERN: the run refused with it
  local rc=0
  "$FAIRWAY" run "$tmp/data/scenarios/mine.yaml" --out "$tmp/bad" > "$tmp/bad.txt" 2>&1 || rc=$?
  [ "$rc" -eq 2 ] && grep -q -- "$1" "$tmp/bad.txt" && [ ! -e "$tmp/bad" ] ||
    { echo "rc $rc, wanted 2 and '$1':"; cat "$tmp/bad.txt"; exit 1; }
}
line="mine.yaml:14: traffic.network: "
mv "$mine/mine.nod.xml" "$tmp/nod.xml"
bad "${line}network 'mine': $mine/mine.nod.xml does not exist (its nodes"
cp "$tmp/nod.xml" "$mine/mine.nod.xml"
: > "$mine/mine.edg.xml"
bad "${line}network 'mine': $mine/mine.edg.xml is empty (its edges"
printf '<edges>\n  <edge id="WB" from="Q" to="B" type="fairway"/>\n</edges>\n' > "$mine/mine.edg.xml"
bad "${line}network 'mine' ($mine): netconvert cannot build it: \"Edge's 'WB' from-node 'Q' is not known.\""
printf '<edges>\n  <edge id="WB" from="W"\n' > "$mine/mine.edg.xml"
bad "${line}$mine/mine.edg.xml:4: network: netconvert: unexpected end of input"
echo "ok: a network of the user's own built on first use"
