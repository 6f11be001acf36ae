#!/usr/bin/env python3
"""One `fairway run` directory as GeoJSON for QGIS and other GIS tools.

A run whose scenario has an origin (origin: {lat_deg, lon_deg}) writes lat_deg
and lon_deg in own.csv and targets.csv (src/geom/geo.h: WGS84, hull centres).
This writes them as a FeatureCollection (RFC 7946: WGS84, longitude first):

  - one LineString per ship: the own ship (role "own") and every target
    (role "target"), properties id, role, t_start_s, t_end_s, points;
  - one Point per ship at its closest approach to the own ship
    (role "cpa", properties id, t_s, range_m), from targets.csv.

    python3 analysis/export_geojson.py runs/geo-twin [--out FILE]

The file goes next to the CSVs (tracks.geojson) unless --out says otherwise;
it is written whole or not at all.  A run without lat/lon columns is refused
(exit 2): give its scenario an origin.
"""
import argparse
import csv
import json
import os
import sys
import tempfile


def fail(msg):
    print(f"export_geojson: {msg}", file=sys.stderr)
    sys.exit(2)


def read_rows(path, need):
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail(f"{path}: {e.strerror}")
    if not rows:
        fail(f"{path}: no rows")
    missing = [c for c in need if c not in rows[0]]
    if missing:
        extra = " (the scenario needs an origin: {lat_deg, lon_deg})" if "lat_deg" in missing else ""
        fail(f"{path}: missing columns {', '.join(missing)}{extra}")
    return rows


def number(row, key, path, line):
    try:
        return float(row[key])
    except (TypeError, ValueError):
        fail(f"{path}:{line}: {key}: '{row[key]}' is not a number")


def line_feature(ident, role, pts):
    return {"type": "Feature",
            "geometry": {"type": "LineString", "coordinates": [[lon, lat] for _, lat, lon in pts]},
            "properties": {"id": ident, "role": role, "t_start_s": pts[0][0],
                           "t_end_s": pts[-1][0], "points": len(pts)}}


def collect(rows, path, key):
    """Points (t, lat, lon) by ship id, and each ship's closest approach."""
    tracks, cpa = {}, {}
    for i, r in enumerate(rows, start=2):
        if r["lat_deg"] == "":
            continue  # a position the projection could not convert
        ident = r[key] if key else "own"
        t = number(r, "t_s", path, i)
        lat, lon = number(r, "lat_deg", path, i), number(r, "lon_deg", path, i)
        tracks.setdefault(ident, []).append((t, lat, lon))
        if "range_m" in r:
            d = number(r, "range_m", path, i)
            if ident not in cpa or d < cpa[ident][0]:
                cpa[ident] = (d, t, lat, lon)
    return tracks, cpa


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run", help="a fairway run directory (own.csv, targets.csv)")
    ap.add_argument("--out", help="the GeoJSON file (default RUN/tracks.geojson)")
    a = ap.parse_args()
    own_path = os.path.join(a.run, "own.csv")
    own, _ = collect(read_rows(own_path, ["t_s", "lat_deg", "lon_deg"]), own_path, None)
    features = [line_feature("own", "own", pts) for pts in own.values() if len(pts) > 1]
    tgt_path = os.path.join(a.run, "targets.csv")
    if os.path.exists(tgt_path):
        rows = read_rows(tgt_path, ["t_s", "id", "lat_deg", "lon_deg", "range_m"])
        tracks, cpa = collect(rows, tgt_path, "id")
        for ident in sorted(tracks):
            if len(tracks[ident]) > 1:
                features.append(line_feature(ident, "target", tracks[ident]))
            d, t, lat, lon = cpa[ident]
            features.append({"type": "Feature",
                             "geometry": {"type": "Point", "coordinates": [lon, lat]},
                             "properties": {"id": ident, "role": "cpa", "t_s": t,
                                            "range_m": d}})
    out = a.out or os.path.join(a.run, "tracks.geojson")
    doc = {"type": "FeatureCollection", "features": features}
    # whole or not at all: a temporary file beside the target, then renamed
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(out)), suffix=".tmp")
    try:
        with os.fdopen(fd, "w") as f:
            json.dump(doc, f)
        os.replace(tmp, out)
    except OSError as e:
        os.unlink(tmp)
        fail(f"{out}: {e.strerror}")
    print(f"wrote {out}: {len(features)} features")


if __name__ == "__main__":
    main()
