#!/usr/bin/env python3
"""generate.py - writes aisdk-2026-03-01.csv, a small synthetic AIS file in the
Danish Maritime Authority's layout, for the AIS workflow of scenarios/ais/.

Deterministic (no randomness): running it again gives the same bytes.

The place: origin 56.5 N, 11.5 E (open water of the Kattegat), the plane of
the scenarios here; the ships sail the `channel` network's fairway placed
there (networks/channel: a straight two-way fairway 20 km east along the
x axis from the origin, eastbound ships south of the centre line, westbound
north of it).  Positions are the plane's east/north turned into latitude
and longitude on the WGS84 ellipsoid with the meridional and prime-vertical
inverse transverse Mercator (the plane fairway projects onto, geom/geo.h);
reported SOG is the speed rounded to 0.1 kn as AIS sends it, COG the true
course (the grid course plus the meridian convergence) to 0.1 deg.  The
positions carry no GPS noise.

Time: 01/03/2026 10:00:00 to 10:45:00 UTC (45 minutes).  Class A ships report
every 10 s, Class B every 30 s, the base station every 10 minutes and the
aid to navigation every 3 minutes.

Ships (MMSI, class, type, track):
  219000101  A  Cargo      eastbound y = -300 m, 12 kn, from x = 2000 m
  219000102  A  Tanker     westbound y = +300 m, 10 kn, from x = 13600 m
                           (crosses the own ship of ais-crossing.yaml from starboard)
  219000103  A  Passenger  eastbound y = -500 m, 18 kn, from x = 0 at 10:20
  219000104  B  Pleasure   westbound y = +200 m, 6 kn, from x = 15000 m
                           (Class B: no A/B/C/D, Length and Width only; COG empty)
  219000105  A  Cargo      westbound y = +400 m, 14 kn, from x = 20000 m at 10:15,
                           silent from 10:25 to 10:31 (a gap of 6 minutes)
  219000106  A  Fishing    northbound at x = 8000 m, 4 kn, from y = -3000 m
                           (crosses the fairway: matches no route)
  2190001    Base Station, 992191001 AtoN (ignored by the reader)
Through traffic on the channel: 2 eastbound and 3 westbound passes in 45 min,
2.67 and 4.00 an hour (what `fairway ais demand` must find).

Bad rows, each once (the reader skips or repairs them, and counts them):
  - fields empty or `Unknown` (ROT, IMO, Callsign, Draught, ETA, Heading 511)
  - the tanker's SOG `Unknown` in one row (kept; SOG taken from the motion)
  - a broken line (the cargo ship's row cut in the middle, at 10:05:00)
  - a row with position 91/181 (not available) for the passenger ship
  - out-of-order rows (the tanker's rows of 10:02:00 and 10:02:10 swapped)
  - a duplicate row (the cargo ship's row of 10:10:00 twice)
  - CRLF line ends on the base station's rows, quoted names with commas

Usage: python3 scenarios/ais/generate.py [OUT]  (default: beside this file)
"""
import math
import os
import sys

LAT0, LON0 = 56.5, 11.5
T0 = 10 * 3600  # 10:00:00 of the day, s
SPAN = 45 * 60
KN = 1852.0 / 3600.0
A_WGS, F_WGS = 6378137.0, 1 / 298.257223563
E2 = F_WGS * (2 - F_WGS)

HEADER = ("# Timestamp,Type of mobile,MMSI,Latitude,Longitude,Navigational status,ROT,SOG,COG,"
          "Heading,IMO,Callsign,Name,Ship type,Cargo type,Width,Length,Type of position fixing "
          "device,Draught,Destination,ETA,Data source type,A,B,C,D")


def latlon(east, north):
    """Plane metres -> degrees: the inverse transverse Mercator about the origin
    (k0 = 1, WGS84; Snyder, Map Projections, USGS 1987, eqs. 3-21, 7-19, 8-18
    to 8-25: within millimetres of PROJ's tmerc over tens of kilometres)."""
    e2 = E2
    ep2 = e2 / (1 - e2)
    m = meridian_arc(math.radians(LAT0)) + north
    mu = m / (A_WGS * (1 - e2 / 4 - 3 * e2 ** 2 / 64 - 5 * e2 ** 3 / 256))
    e1 = (1 - math.sqrt(1 - e2)) / (1 + math.sqrt(1 - e2))
    phi1 = (mu + (3 * e1 / 2 - 27 * e1 ** 3 / 32) * math.sin(2 * mu)
            + (21 * e1 ** 2 / 16 - 55 * e1 ** 4 / 32) * math.sin(4 * mu)
            + (151 * e1 ** 3 / 96) * math.sin(6 * mu) + (1097 * e1 ** 4 / 512) * math.sin(8 * mu))
    c1 = ep2 * math.cos(phi1) ** 2
    t1 = math.tan(phi1) ** 2
    n1 = A_WGS / math.sqrt(1 - e2 * math.sin(phi1) ** 2)
    r1 = A_WGS * (1 - e2) / (1 - e2 * math.sin(phi1) ** 2) ** 1.5
    d = east / n1
    lat = phi1 - (n1 * math.tan(phi1) / r1) * (
        d ** 2 / 2 - (5 + 3 * t1 + 10 * c1 - 4 * c1 ** 2 - 9 * ep2) * d ** 4 / 24
        + (61 + 90 * t1 + 298 * c1 + 45 * t1 ** 2 - 252 * ep2 - 3 * c1 ** 2) * d ** 6 / 720)
    lon = (d - (1 + 2 * t1 + c1) * d ** 3 / 6
           + (5 - 2 * c1 + 28 * t1 - 3 * c1 ** 2 + 8 * ep2 + 24 * t1 ** 2) * d ** 5 / 120) / math.cos(phi1)
    return math.degrees(lat), LON0 + math.degrees(lon)


def meridian_arc(phi):
    e2 = E2
    return A_WGS * ((1 - e2 / 4 - 3 * e2 ** 2 / 64 - 5 * e2 ** 3 / 256) * phi
                    - (3 * e2 / 8 + 3 * e2 ** 2 / 32 + 45 * e2 ** 3 / 1024) * math.sin(2 * phi)
                    + (15 * e2 ** 2 / 256 + 45 * e2 ** 3 / 1024) * math.sin(4 * phi)
                    - (35 * e2 ** 3 / 3072) * math.sin(6 * phi))


def true_course(grid_deg, lat, lon):
    """A grid course as the true course AIS reports: plus the meridian
    convergence there (dlon sin(lat), to 1e-3 deg over this area)."""
    gamma = (lon - LON0) * math.sin(math.radians(lat))
    return (grid_deg + gamma) % 360.0


def stamp(t):
    h, r = divmod(int(t), 3600)
    m, s = divmod(r, 60)
    return f"01/03/2026 {h:02d}:{m:02d}:{s:02d}"


# mmsi, class, type, name, (x0, y0), course (deg, grid: straight in the
# plane), kn, start s after 10:00,
# period, (A, B, C, D) or None, (width, length)
SHIPS = [
    (219000101, "Class A", "Cargo", '"NORDIC, TRADER"', (2000, -300), 90, 12, 0, 10, (100, 20, 10, 10), (20, 120)),
    (219000102, "Class A", "Tanker", "KATTEGAT SPIRIT", (13600, 300), 270, 10, 0, 10, (150, 30, 16, 16), (32, 180)),
    (219000103, "Class A", "Passenger", '"FERRY ""SKAW"""', (0, -500), 90, 18, 1200, 10, (160, 25, 14, 14), (28, 185)),
    (219000104, "Class B", "Pleasure", "SPRAY", (15000, 200), 270, 6, 0, 30, None, (4, 12)),
    (219000105, "Class A", "Cargo", "BALTIC BULK", (20000, 400), 270, 14, 900, 10, (160, 30, 15, 15), (30, 190)),
    (219000106, "Class A", "Fishing", "HAVFRUEN", (8000, -3000), 0, 4, 0, 10, (18, 6, 4, 4), (8, 24)),
]


def ship_rows(ship):
    mmsi, cls, typ, name, (x0, y0), course, kn, start, period, abcd, (wid, length) = ship
    v = kn * KN
    rows = []
    t = start
    while t <= SPAN:
        if mmsi == 219000105 and 25 * 60 <= t < 31 * 60:
            t += period  # the gap: silent 10:25 to 10:31
            continue
        d = v * (t - start)
        x = x0 + d * math.sin(math.radians(course))
        y = y0 + d * math.cos(math.radians(course))
        lat, lon = latlon(x, y)
        sog = f"{kn:.1f}"
        cog = f"{true_course(course, lat, lon):.1f}" if cls == "Class A" else ""
        hdg = f"{course:d}" if cls == "Class A" else "511"
        if mmsi == 219000102 and t == 300:
            sog = "Unknown"
        if mmsi == 219000103 and t == 1500:
            lat, lon = 91.0, 181.0
        a, b, c, dd = abcd if abcd else ("", "", "", "")
        status = "Under way using engine" if typ != "Fishing" else "Engaged in fishing"
        dest = '"AARHUS, DK"' if typ == "Cargo" else "Unknown"
        rows.append((T0 + t, f"{stamp(T0 + t)},{cls},{mmsi},{lat:.6f},{lon:.6f},{status},"
                     f"{'0.0' if cls == 'Class A' else ''},{sog},{cog},{hdg},Unknown,Unknown,"
                     f"{name},{typ},,{wid},{length},GPS,Unknown,{dest},Unknown,AIS,"
                     f"{a},{b},{c},{dd}"))
        t += period
    return rows


def fixed_rows():
    rows = []
    for t in range(0, SPAN + 1, 600):
        rows.append((T0 + t, f"{stamp(T0 + t)},Base Station,2190001,56.450000,11.400000,"
                     "Unknown value,,,,,Unknown,Unknown,,Undefined,,,,Surveyed,,Unknown,,AIS,,,,\r"))
    for t in range(0, SPAN + 1, 180):
        rows.append((T0 + t, f"{stamp(T0 + t)},AtoN,992191001,56.495000,11.600000,Unknown value,"
                     ",,,,Unknown,Unknown,FAIRWAY BUOY 3,Undefined,,2,2,GPS,,Unknown,,AIS,1,1,1,1"))
    return rows


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__) or ".",
                                                             "aisdk-2026-03-01.csv")
    rows = fixed_rows()
    for s in SHIPS:
        rows += ship_rows(s)
    rows.sort(key=lambda r: (r[0], r[1].split(",")[2]))  # by time, then MMSI: as DMA files come
    lines = [r[1] for r in rows]
    # the bad rows
    cut = next(i for i, l in enumerate(lines) if l.startswith(stamp(T0 + 300) + ",Class A,219000101"))
    lines[cut] = lines[cut][:60]
    i = next(i for i, l in enumerate(lines) if l.startswith(stamp(T0 + 120) + ",Class A,219000102"))
    j = next(i for i, l in enumerate(lines) if l.startswith(stamp(T0 + 130) + ",Class A,219000102"))
    lines[i], lines[j] = lines[j], lines[i]
    k = next(i for i, l in enumerate(lines) if l.startswith(stamp(T0 + 600) + ",Class A,219000101"))
    lines.insert(k + 1, lines[k])
    with open(out, "w", newline="") as f:
        f.write(HEADER + "\n")
        for l in lines:
            f.write(l + "\n")


if __name__ == "__main__":
    main()
