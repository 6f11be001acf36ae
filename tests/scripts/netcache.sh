# netcache.sh - the network cache (src/traffic/netcache.h): a paper case's
# network built once and reused, byte for byte what netconvert writes; a hit
# reads the entry, an entry edited or truncated since it was stored is
# rebuilt (its sums), a changed input misses, an entry missing its file is
# rebuilt, parallel runs leave one whole entry and no temporary directories.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export XDG_CACHE_HOME=$tmp/cache
net=$XDG_CACHE_HOME/fairway/net
p=$FAIRWAY_DATA/scenarios/paper
files="own.csv targets.csv encounters.csv summary.json sumo/run.net.xml sumo/netconvert.log"
run() { # OUT SCENARIO...
  local out=$1; shift
  "$FAIRWAY" run "$@" --out "$tmp/$out" > "$tmp/$out.table" 2>&1 ||
    { echo "run $out failed:"; cat "$tmp/$out.table"; exit 1; }
}
same() { # A B SCENARIO_NAME
  for f in $files; do
    cmp -s "$tmp/$1/$3/$f" "$tmp/$2/$3/$f" || { echo "$1 and $2: $3/$f differ"; exit 1; }
  done
}
entries() { find "$net" -mindepth 1 -maxdepth 1 -type d -name '[0-9a-f]*' | wc -l; }

FAIRWAY_NETCACHE=off run ref "$p/1-head-on.yaml"
[ ! -e "$XDG_CACHE_HOME" ] || { echo "FAIRWAY_NETCACHE=off wrote a cache"; exit 1; }
# what a SIGKILLed build and store left, marked by a process that has ended,
# is removed by the next (core/leftover.h); an unmarked directory is kept
sh -c 'exit 0' & dead=$!
wait $dead
mkdir -p "$net/.tmp.K1lled" "$net/.tmp.m1ne00"
echo "$dead 1" > "$net/.tmp.K1lled/.fairway-owner"
run first "$p/1-head-on.yaml"
[ ! -e "$net/.tmp.K1lled" ] &&
  grep -q "removed $net/.tmp.K1lled, left by an interrupted network cache store" "$tmp/first.table" ||
  { echo "the leftover: not removed, or not said"; cat "$tmp/first.table"; exit 1; }
[ -d "$net/.tmp.m1ne00" ] || { echo "an unmarked directory removed"; exit 1; }
rmdir "$net/.tmp.m1ne00"
[ ! -e "$(find "$net" -name .fairway-owner)" ] || { echo "a cache entry holds the owner mark"; exit 1; }
[ "$(entries)" -eq 1 ] || { echo "after one run: $(entries) entries, not 1"; exit 1; }
run second "$p/1-head-on.yaml"
same ref first paper-1-head-on
same ref second paper-1-head-on
echo "cached network: the same files as netconvert's"

# a hit reads the entry (its directory stays the same one); an entry whose
# file is not as stored (size and digest, sums) is removed and built again
e=$(find "$net" -mindepth 1 -maxdepth 1 -type d -name '[0-9a-f]*')
cp "$e/net.xml" "$tmp/saved.xml"
ino=$(stat -c %i "$e")
run hit "$p/1-head-on.yaml"
[ "$(stat -c %i "$e")" = "$ino" ] || { echo "the second run did not take its network from the cache"; exit 1; }
echo "<!-- marked by netcache.sh -->" >> "$e/net.xml"
run marked "$p/1-head-on.yaml"
! grep -q "marked by netcache.sh" "$tmp/marked/paper-1-head-on/sumo/run.net.xml" ||
  { echo "an edited entry was handed out"; exit 1; }
cmp -s "$e/net.xml" "$tmp/saved.xml" || { echo "the edited entry was not built again"; exit 1; }
same ref marked paper-1-head-on
head -c 1000 "$tmp/saved.xml" > "$e/net.xml"   # truncated: same name, part of the bytes
run truncated "$p/1-head-on.yaml"
same ref truncated paper-1-head-on
cmp -s "$e/net.xml" "$tmp/saved.xml" || { echo "the truncated entry was not built again"; exit 1; }
echo "edited and truncated entries rebuilt"

# other targets, other tracks: a miss and an entry of their own
run other "$p/2-overtaking.yaml"
[ "$(entries)" -eq 2 ] || { echo "another scenario: $(entries) entries, not 2"; exit 1; }

# an entry missing its network is rebuilt, the run unharmed
rm "$e/net.xml"
run damaged "$p/1-head-on.yaml"
same ref damaged paper-1-head-on
run repaired "$p/1-head-on.yaml"
[ -f "$e/net.xml" ] && cmp -s "$e/net.xml" "$tmp/saved.xml" ||
  { echo "the damaged entry was not stored again"; exit 1; }
echo "miss on other inputs, damaged entry rebuilt"

# four runs at once on an empty cache: one entry, nothing half-written
rm -rf "$XDG_CACHE_HOME"
FAIRWAY_NETCACHE=off run ref3 "$p/3-crossing.yaml"
for k in 1 2 3 4; do run "par$k" "$p/3-crossing.yaml" & done
wait
for k in 1 2 3 4; do same ref3 "par$k" paper-3-crossing; done
[ "$(entries)" -eq 1 ] || { echo "parallel runs: $(entries) entries, not 1"; exit 1; }
left=$(find "$net" -name '.tmp*' | wc -l)
[ "$left" -eq 0 ] || { echo "parallel runs left $left temporary files"; exit 1; }
# at most FAIRWAY_NETCACHE_MAX entries, the least recently used going first
rm -rf "$XDG_CACHE_HOME"
run lru1 "$p/1-head-on.yaml"
sleep 0.05
run lru2 "$p/2-overtaking.yaml"
sleep 0.05
run lru3 "$p/1-head-on.yaml"       # a hit: 1-head-on is now the most recently used
sleep 0.05
FAIRWAY_NETCACHE_MAX=2 run lru4 "$p/3-crossing.yaml"
[ "$(entries)" -eq 2 ] || { echo "FAIRWAY_NETCACHE_MAX=2: $(entries) entries, not 2"; exit 1; }
run lru5 "$p/1-head-on.yaml"       # kept: a hit adds nothing
[ "$(entries)" -eq 2 ] || { echo "1-head-on was pruned: $(entries) entries after it"; exit 1; }
run lru6 "$p/2-overtaking.yaml"    # the least recently used, pruned: a miss stores it again
[ "$(entries)" -eq 3 ] || { echo "2-overtaking was kept: $(entries) entries after it"; exit 1; }
same lru2 lru6 paper-2-overtaking
echo "ok: networks reused byte for byte"
