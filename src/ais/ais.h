/* ais.h - AIS position reports read from CSV, one row at a time.
 *
 * The layout is the Danish Maritime Authority's (daily files
 * aisdk-YYYY-MM-DD.csv), whose header line begins with "# ":
 *
 *   # Timestamp,Type of mobile,MMSI,Latitude,Longitude,Navigational status,ROT,SOG,
 *   COG,Heading,IMO,Callsign,Name,Ship type,Cargo type,Width,Length,...,A,B,C,D
 *
 * Other CSVs are read through a column map (fw_ais_columns_parse: which
 * header names hold time, mmsi, lat, lon, sog, cog, heading, type, class,
 * length, width, a, b, c, d).  Columns are found by header name, in any order.
 *
 * The file is streamed (a daily file is 1-3 GB): fw_ais_next hands out the
 * next usable report and counts every row it passes over by reason, so a bad
 * row is never fatal.  Kept: Class A and Class B transponders (and, with no
 * class column, 9-digit MMSIs whose first digit is 2-7: ships).  Skipped: base
 * stations, aids to navigation, SAR aircraft and other non-ships; broken lines
 * (too few fields, an unterminated quote, over 64 KiB); a time, MMSI or
 * position that is missing or wrong (91/181 = not available).  Fields may be
 * quoted ("a, b" and "" inside quotes), lines may end in CRLF; a UTF-8 byte
 * order mark before the header (or after its "#") is skipped.
 *
 * Units: the report is SI (m/s, rad) with NAN for "not available" (empty,
 * `Unknown`, Heading 511, COG 360, SOG 102.3); lat/lon stay degrees (geo.h
 * projects them); courses are true.  Time: UTC seconds since 1970-01-01
 * (timestamps DD/MM/YYYY HH:MM:SS, or YYYY-MM-DD[T ]HH:MM:SS).  Length is
 * A + B and breadth C + D when given, else the Length and Width columns.
 *
 * Fatal (FW_EINPUT, "FILE:LINE: FIELD: problem"): a file that cannot be
 * opened or is a directory, no header, a required column (time, mmsi, lat, lon) absent.
 */
#ifndef FW_AIS_H
#define FW_AIS_H

#include <stdbool.h>
#include <stdio.h>

#include "core/error.h"

/* What a ship is, from the AIS ship type (codes 0-99 or DMA's words). */
typedef enum fw_ais_kind {
    FW_AIS_UNKNOWN,   /* 0, 90-99, "Undefined", "Other", ... */
    FW_AIS_CARGO,     /* 70-79 */
    FW_AIS_TANKER,    /* 80-89 */
    FW_AIS_PASSENGER, /* 60-69 */
    FW_AIS_HSC,       /* 40-49, high-speed craft */
    FW_AIS_FISHING,   /* 30 */
    FW_AIS_PLEASURE,  /* 36 sailing, 37 pleasure */
    FW_AIS_SERVICE,   /* 31-35, 50-59: tugs, pilots, SAR, dredgers, law enforcement, ... */
    FW_AIS_NKINDS
} fw_ais_kind;

/* "unknown", "cargo", "tanker", ...: the type label of a replayed ship. */
const char *fw_ais_kind_name(fw_ais_kind k);
/* The kind of an AIS type code 0-99 (other codes: unknown). */
fw_ais_kind fw_ais_kind_of_code(int code);

typedef struct fw_ais_report {
    double t;             /* s, UTC since 1970 */
    long mmsi;
    bool class_b;
    double lat, lon;      /* deg */
    double sog;           /* m/s, NAN = n/a */
    double cog, heading;  /* rad, true, NAN = n/a */
    fw_ais_kind kind;
    int type_code;        /* 0-99, 0 = not given (or given as words) */
    double length, breadth; /* m, 0 = not given */
    int line;             /* the row's line in the file */
} fw_ais_report;

/* Why a row was passed over. */
typedef enum fw_ais_skip {
    FW_AIS_SKIP_NOT_SHIP, /* base station, AtoN, SAR aircraft, other non-ship */
    FW_AIS_SKIP_BROKEN,   /* too few fields, unterminated quote, too long */
    FW_AIS_SKIP_TIME,     /* empty or unreadable timestamp */
    FW_AIS_SKIP_MMSI,     /* empty, not a number, not 1..999999999 */
    FW_AIS_SKIP_POSITION, /* empty, Unknown, 91/181 or out of range */
    FW_AIS_NSKIP
} fw_ais_skip;

const char *fw_ais_skip_name(fw_ais_skip s);

typedef struct fw_ais_counts {
    long rows;                   /* data rows (blank lines not counted) */
    long kept;                   /* handed out by fw_ais_next */
    long skipped[FW_AIS_NSKIP];
    long class_a, class_b;       /* of the kept */
    long no_sog, no_cog;         /* kept without SOG / COG */
    double t_first, t_last;      /* s UTC, the earliest and latest kept; NAN before any */
} fw_ais_counts;

/* Which header names hold which field (NULL: the DMA name; "" = no such
 * column).  Required: time, mmsi, lat, lon. */
enum { FW_AIS_F_TIME, FW_AIS_F_CLASS, FW_AIS_F_MMSI, FW_AIS_F_LAT, FW_AIS_F_LON, FW_AIS_F_SOG,
       FW_AIS_F_COG, FW_AIS_F_HEADING, FW_AIS_F_TYPE, FW_AIS_F_WIDTH, FW_AIS_F_LENGTH,
       FW_AIS_F_A, FW_AIS_F_B, FW_AIS_F_C, FW_AIS_F_D, FW_AIS_NFIELDS };
typedef struct fw_ais_columns {
    char name[FW_AIS_NFIELDS][64];
} fw_ais_columns;

/* The DMA layout's names. */
fw_ais_columns fw_ais_dma_columns(void);
/* "field=Header Name,field=..." (fields: time class mmsi lat lon sog cog
 * heading type width length a b c d) over the DMA names: those given are
 * replaced.  FW_EINPUT naming `what` (an option or FILE:LINE: FIELD). */
fw_status fw_ais_columns_parse(const char *spec, const char *what, fw_ais_columns *out,
                               fw_error *err);

typedef struct fw_ais_reader fw_ais_reader;

/* Opens path and reads its header; cols NULL = DMA. */
fw_status fw_ais_open(const char *path, const fw_ais_columns *cols, fw_ais_reader **out,
                      fw_error *err);
/* The next kept report into *r (*got true), or the end of the file (*got
 * false).  FW_ERUN only for a read error or no memory. */
fw_status fw_ais_next(fw_ais_reader *rd, fw_ais_report *r, bool *got, fw_error *err);
const fw_ais_counts *fw_ais_counts_of(const fw_ais_reader *rd);
const char *fw_ais_file(const fw_ais_reader *rd);
/* Safe on NULL. */
void fw_ais_close(fw_ais_reader *rd);

/* "YYYY-MM-DD HH:MM:SS" (or DD/MM/YYYY, or with T) as UTC seconds; false if
 * it is not one. */
bool fw_ais_parse_time(const char *s, double *t);
/* t (UTC s) as "YYYY-MM-DD HH:MM:SS" into buf (at least 20 bytes). */
void fw_ais_format_time(double t, char *buf, size_t n);

/* Prints the counts as "what: N" lines (the summary's and run.log's). */
void fw_ais_print_counts(FILE *out, const fw_ais_counts *c);

#endif
