# gui_screenshot.sh - a paper case in sumo-gui under Xvfb, and its screenshot checked.
#
# Without an X server the test is skipped (exit 77, ctest's SKIP_RETURN_CODE), but
# only when Xvfb really cannot run here; with FAIRWAY_REQUIRE_XVFB=1 (.ci/run) that
# is a failure instead.  The screenshot (fairway run --gui-screenshot, taken by
# sumo-gui through TraCI at the end) must show the own ship in its signal orange
# (255,80,0): centred, since the view follows it, and to scale, its outline
# as long as the hull at the --gui-view zoom (1 nm over the view's height).
set -uo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
keep=${GUI_SHOT_KEEP:-}  # a directory to keep the screenshot in, for a look
skip() {
  if [ "${FAIRWAY_REQUIRE_XVFB:-0}" = 1 ]; then echo "FAIL (FAIRWAY_REQUIRE_XVFB=1): $*"; exit 1; fi
  echo "SKIP: $*"; exit 77
}
command -v xvfb-run > /dev/null || skip "no xvfb-run (Debian package xvfb)"
xvfb=(xvfb-run -a -s "-screen 0 1600x1000x24")
"${xvfb[@]}" true > "$tmp/xvfb.log" 2>&1 || skip "Xvfb cannot start: $(head -1 "$tmp/xvfb.log")"
"$PYTHON" -c "import PIL" 2> /dev/null || { echo "FAIL: $PYTHON has no PIL (Debian python3-pil)"; exit 1; }

scn=$FAIRWAY_DATA/scenarios/paper/1-head-on.yaml
# 5 ms a step: with none, sumo-gui's painting (which moves the tracked view) falls
# behind the steps under Xvfb's software rendering and the view lags the ship
"${xvfb[@]}" "$FAIRWAY" run "$scn" --sumo gui --gui-delay 5 --gui-view 1 --gui-size 1280x800 \
  --gui-screenshot --out "$tmp/runs" > "$tmp/out" 2>&1
rc=$?
run=$tmp/runs/paper-1-head-on
[ $rc -eq 0 ] || { echo "gui run failed ($rc):"; cat "$tmp/out"; cat "$run/sumo/"*.gui 2>/dev/null; exit 1; }
grep -q "Retrying" "$tmp/out" && { echo "libtraci's retry noise on the terminal"; exit 1; }
# the same results as the embedded run: watching changes nothing
"$FAIRWAY" run "$scn" --out "$tmp/ref" > /dev/null 2>&1 || { echo "embedded run failed"; exit 1; }
cmp -s "$run/own.csv" "$tmp/ref/paper-1-head-on/own.csv" || { echo "gui run's own.csv differs"; exit 1; }
"$PYTHON" - "$run/screenshot.png" "$run/summary.json" <<'EOF'
import json, math, sys
from PIL import Image
png, summary = sys.argv[1:]
im = Image.open(png).convert("RGB")
w, h = im.size
# the view: the 1280x800 window less sumo-gui's menu, tool and message bars
if not (900 <= w <= 1280 and 300 <= h <= 800):
    sys.exit(f"screenshot is {w}x{h}: not the view of a 1280x800 window")
# the own ship's colour, within a little of it (edges are blended)
own = [(x, y) for y in range(h) for x in range(w)
       if (lambda p: abs(p[0] - 255) <= 12 and abs(p[1] - 80) <= 24 and p[2] <= 24)(im.getpixel((x, y)))]
if len(own) < 20:
    sys.exit(f"only {len(own)} pixels of the own ship's orange")
xs, ys = [p[0] for p in own], [p[1] for p in own]
cx, cy = sum(xs) / len(xs), sum(ys) / len(ys)
if abs(cx - w / 2) > 0.1 * w or abs(cy - h / 2) > 0.1 * h:
    sys.exit(f"own ship at ({cx:.0f}, {cy:.0f}) px, not near the centre: the view does not follow it")
s = json.load(open(summary))
length = s["own_length_m"]
m_per_px = 1852.0 / min(w, h)  # --gui-view 1 nm fitted to the view's height
drawn = math.hypot(max(xs) - min(xs), max(ys) - min(ys)) * m_per_px
if not 0.75 * length <= drawn <= 1.25 * length:
    sys.exit(f"own ship drawn {drawn:.0f} m long, its hull is {length:.0f} m: not to scale")
print(f"own ship: {len(own)} px at ({cx:.0f}, {cy:.0f}), drawn {drawn:.0f} m for a {length:.0f} m hull")
EOF
rc=$?
[ -z "$keep" ] || cp "$run/screenshot.png" "$keep/"
[ $rc -eq 0 ] || exit 1
echo "ok: the own ship in the sumo-gui screenshot"
