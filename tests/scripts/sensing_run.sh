# sensing_run.sh - the own ship deciding on AIS reports (sense/sensing.h):
# Imazu case 1 (head-on) with AIS sensing (10% of reports lost, 1 s late):
# the own ship still acts and passes clear; the records keep the truth (its
# least distance is the true one, from targets.csv's true positions); the
# same seed gives the same run to the byte, another seed another; the summary
# counts the reports.
# Then on its radar's tracks (mode radar, sense/arpa.h): the target is tracked
# (one track, shown a minute after its first plot), the own ship acts to
# starboard on the track and passes clear, the records keep the truth; the
# summary gives the scans, plots and the rms error of the track against the
# truth; the same seed gives the same run.  With ais+radar (AIS first,
# MSC.192(79) 5.29) the run also counts AIS reports.  Every run keeps what the
# own ship knew beside the truth (sensed.csv, its error within 30% of the
# summary's rms for the radar runs).
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
src=$FAIRWAY_DATA/scenarios/imazu/imazu-01.yaml
sed 's/^name: imazu-01/name: ais/; s/^run:/sensing: {mode: ais, dropout: 0.1, latency_s: 1}\nrun:/' "$src" > "$tmp/a.yaml"
sed 's/^  seed: 1/  seed: 2/' "$tmp/a.yaml" > "$tmp/b.yaml"
sed -i 's/^name: ais/name: ais2/' "$tmp/b.yaml"
"$FAIRWAY" run "$tmp/a.yaml" --out "$tmp/o1" > /dev/null
"$FAIRWAY" run "$tmp/a.yaml" --out "$tmp/o2" > /dev/null
"$FAIRWAY" run "$tmp/b.yaml" --out "$tmp/o3" > /dev/null
cmp "$tmp/o1/ais/own.csv" "$tmp/o2/ais/own.csv" || { echo "the same seed gave another run"; exit 1; }
if cmp -s "$tmp/o1/ais/own.csv" "$tmp/o3/ais2/own.csv"; then echo "another seed gave the same run"; exit 1; fi
sed 's/^name: imazu-01/name: radar/; s/^run:/sensing: {mode: radar}\nrun:/' "$src" > "$tmp/r.yaml"
sed 's/^name: imazu-01/name: fused/; s/^run:/sensing: {mode: ais+radar}\nrun:/' "$src" > "$tmp/f.yaml"
"$FAIRWAY" run "$tmp/r.yaml" --out "$tmp/o1" > /dev/null
"$FAIRWAY" run "$tmp/r.yaml" --out "$tmp/o2" > /dev/null
"$FAIRWAY" run "$tmp/f.yaml" --out "$tmp/o1" > /dev/null
cmp "$tmp/o1/radar/own.csv" "$tmp/o2/radar/own.csv" || { echo "the same seed gave another radar run"; exit 1; }
"$PYTHON" - "$tmp/o1/ais" "$tmp/o1/radar" "$tmp/o1/fused" <<'PY'
import csv, json, math, sys
for d in sys.argv[1:]:
    s = json.load(open(d + "/summary.json"))
    sen = s["sensing"]
    own = {r["t_s"]: r for r in csv.DictReader(open(d + "/own.csv"))}
    least = min(math.hypot(float(r["east_m"]) - float(own[r["t_s"]]["east_m"]),
                           float(r["north_m"]) - float(own[r["t_s"]]["north_m"]))
                for r in csv.DictReader(open(d + "/targets.csv")) if r["t_s"] in own)
    enc = s["encounters"][0]
    assert enc["act_side"] == "starboard" and not enc["collision"], enc
    # both kept: sensed.csv has what the own ship knew, its error against the truth
    err = [float(r["error_m"]) for r in csv.DictReader(open(d + "/sensed.csv"))]
    rms = math.sqrt(sum(e * e for e in err) / len(err))
    assert len(err) > 100 and 0.0 < rms < 100.0, (len(err), rms)
    if "position_error_rms_m" in sen:
        assert abs(rms / sen["position_error_rms_m"] - 1.0) < 0.3, (rms, sen)
    # the truth (5 s rows)
    assert abs(enc["min_distance_m"] - least) < 30.0, (enc["min_distance_m"], least)
    if sen["mode"] == "ais":
        assert sen["reports_sent"] > 100, sen
        assert 0.05 < sen["lost"] / sen["reports_sent"] < 0.15, sen
        what = "%d reports, %d lost" % (sen["reports_sent"], sen["lost"])
    else:
        assert sen["tracks"] == 1 and sen["tracks_lost"] == 0, sen
        assert sen["plotted"] > 0.9 * sen["scanned"] > 500, sen
        if sen["mode"] == "radar":
            assert "reports_sent" not in sen and 2.0 < sen["position_error_rms_m"] < 60.0, sen
        else:
            assert sen["mode"] == "ais+radar" and sen["reports_sent"] > 100, sen
        what = "%d plots of %d scans, rms error %.1f m" % (sen["plotted"], sen["scanned"],
                                                         sen["position_error_rms_m"])
    print("%s: %s; acted, least distance %.0f m (true positions %.0f m)"
          % (sen["mode"], what, enc["min_distance_m"], least))
PY
echo "ok: the own ship decides on AIS reports and on radar tracks"
