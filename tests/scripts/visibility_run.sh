# visibility_run.sh - the own ship in restricted visibility (environment:
# visibility_nm, avoid/policy.h): a ship farther off than the visibility is not
# in sight and rule 19 governs, not rules 13-17.  Imazu-like single crossings
# (scenarios/imazu), visibility 0.5 nm, perfect sensing:
#   fog-stbd   Imazu 2, a crossing ship (a 200 m one) on the starboard bow:
#              at 2 nm (its whistle heard forward of the beam) the own ship
#              reduces to 8 kn by rule 19(e), which alone keeps it out of the
#              domain; it never alters to port (19(d)(i))
#   port       the mirror, a crossing ship on the port bow: in clear weather
#              the own ship stands on (rule 17) and acts late; in fog there is
#              no stand-on ship: it reduces speed by 19(e), earlier than the
#              clear run's action, and never alters to port
#   abaft      a faster ship closing from abaft the starboard beam (being
#              overtaken): in fog the own ship does not alter towards it
#              (19(d)(ii)): to port, by rule 19; no 19(e) (not forward of the beam)
#   crossing-fog-radar  Imazu 2 in fog on radar (scenarios/sensing): as
#              fog-stbd, deciding on the radar's track
# No collision; each run's COLREGs check (summary colregs_ok) holds: out of
# sight by rule 19(d)'s sides and no standing on (run/book.c).
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
im=$FAIRWAY_DATA/scenarios/imazu
fog='s/^run:/environment: {visibility_nm: 0.5}\nrun:/'
sed "s/^name: imazu-02/name: fog-stbd/; $fog" "$im/imazu-02.yaml" > "$tmp/a.yaml"
sed 's/^name: imazu-02/name: clear-port/; s/east_m: 11112.0, north_m: 0.0, course_deg: 270.000/east_m: -11112.0, north_m: 0.0, course_deg: 90.000/' \
  "$im/imazu-02.yaml" > "$tmp/b.yaml"
sed "s/^name: clear-port/name: fog-port/; $fog" "$tmp/b.yaml" > "$tmp/c.yaml"
sed "s/^name: imazu-04/name: fog-abaft/; $fog; s/east_m: -7858.0, north_m: -7858.0, course_deg: 45.000, speed_kn: 12.001/east_m: 9623.0, north_m: -16668.0, course_deg: 330.000, speed_kn: 20.78/" \
  "$im/imazu-04.yaml" > "$tmp/d.yaml"
for x in a b c d; do "$FAIRWAY" run "$tmp/$x.yaml" --out "$tmp/o" > /dev/null; done
"$FAIRWAY" run "$FAIRWAY_DATA/scenarios/sensing/crossing-fog-radar.yaml" --out "$tmp/o" > /dev/null
"$PYTHON" - "$tmp/o" <<'PY'
import json, sys
o = sys.argv[1]
def enc(name):
    e = json.load(open("%s/%s/summary.json" % (o, name)))["encounters"][0]
    log = open("%s/%s/run.log" % (o, name)).read()
    r19e = [float(l.split()[0]) for l in log.splitlines() if "rule 19(e):" in l]
    e["t_first"] = min([e["t_act_s"] or 1e9] + r19e)
    print("%-18s %-18s acts at %6s s to %-9s least distance %4.0f m%s%s"
          % (name, e["situation"], e["t_act_s"], e["act_side"], e["min_distance_m"],
             ", by rule 19" if "rule 19, not in sight" in log else "",
             ", 19(e) speed from %.0f s" % r19e[0] if r19e else ""))
    assert not e["collision"] and e["colregs_ok"], e
    return e, "rule 19, not in sight" in log, bool(r19e)
e, r19, r19e = enc("fog-stbd")
assert e["act_side"] in ("starboard", "none") and r19e and not e["domain_entered"], e
clear, r19c, _ = enc("clear-port")
fogp, r19, r19e = enc("fog-port")
assert not r19c and r19e and fogp["act_side"] in ("starboard", "none"), fogp
assert fogp["t_first"] < clear["t_act_s"] - 30, (fogp["t_first"], clear["t_act_s"])
e, r19, r19e = enc("fog-abaft")
assert e["act_side"] == "port" and r19 and not r19e, e
# fog and radar (scenarios/sensing): the same, on the radar's track
e, r19, r19e = enc("crossing-fog-radar")
assert e["act_side"] in ("starboard", "none") and r19e, e
PY
echo "ok: rule 19 in restricted visibility"
