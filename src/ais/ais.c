/* ais.c - the streaming AIS CSV reader (ais.h). */
#include "ais/ais.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/units.h"

enum { LINE_MAX_BYTES = 65536, MAX_FIELDS = 128 };

struct fw_ais_reader {
    FILE *f;
    char file[512];
    int line_no;
    int col[FW_AIS_NFIELDS]; /* field index of each, -1: absent */
    int need;                /* fields a row must have: 1 + the largest index used */
    char *buf;               /* LINE_MAX_BYTES + 2 */
    fw_ais_counts c;
};

static const char *const field_key[FW_AIS_NFIELDS] = {
    "time", "class", "mmsi", "lat", "lon", "sog", "cog", "heading", "type", "width", "length",
    "a", "b", "c", "d"};
static const char *const dma_name[FW_AIS_NFIELDS] = {
    "Timestamp", "Type of mobile", "MMSI", "Latitude", "Longitude", "SOG", "COG", "Heading",
    "Ship type", "Width", "Length", "A", "B", "C", "D"};

static const char *const kind_names[FW_AIS_NKINDS] = {
    "unknown", "cargo", "tanker", "passenger", "hsc", "fishing", "pleasure", "service"};

const char *fw_ais_kind_name(fw_ais_kind k)
{
    return k >= 0 && k < FW_AIS_NKINDS ? kind_names[k] : "unknown";
}

fw_ais_kind fw_ais_kind_of_code(int code)
{
    if (code >= 70 && code <= 79)
        return FW_AIS_CARGO;
    if (code >= 80 && code <= 89)
        return FW_AIS_TANKER;
    if (code >= 60 && code <= 69)
        return FW_AIS_PASSENGER;
    if (code >= 40 && code <= 49)
        return FW_AIS_HSC;
    if (code == 30)
        return FW_AIS_FISHING;
    if (code == 36 || code == 37)
        return FW_AIS_PLEASURE;
    if ((code >= 31 && code <= 35) || (code >= 50 && code <= 59))
        return FW_AIS_SERVICE;
    return FW_AIS_UNKNOWN;
}

/* DMA writes the ship type as words. */
static fw_ais_kind kind_of_words(const char *s)
{
    static const struct { const char *w; fw_ais_kind k; } map[] = {
        {"Cargo", FW_AIS_CARGO},         {"Tanker", FW_AIS_TANKER},
        {"Passenger", FW_AIS_PASSENGER}, {"HSC", FW_AIS_HSC},
        {"Fishing", FW_AIS_FISHING},     {"Sailing", FW_AIS_PLEASURE},
        {"Pleasure", FW_AIS_PLEASURE},   {"Tug", FW_AIS_SERVICE},
        {"Towing", FW_AIS_SERVICE},      {"Towing long/wide", FW_AIS_SERVICE},
        {"Pilot", FW_AIS_SERVICE},       {"SAR", FW_AIS_SERVICE},
        {"Dredging", FW_AIS_SERVICE},    {"Diving", FW_AIS_SERVICE},
        {"Military", FW_AIS_SERVICE},    {"Law enforcement", FW_AIS_SERVICE},
        {"Port tender", FW_AIS_SERVICE}, {"Anti-pollution", FW_AIS_SERVICE},
        {"Medical", FW_AIS_SERVICE},
    };
    for (size_t i = 0; i < sizeof map / sizeof map[0]; i++)
        if (strcmp(s, map[i].w) == 0)
            return map[i].k;
    return FW_AIS_UNKNOWN;
}

const char *fw_ais_skip_name(fw_ais_skip s)
{
    static const char *const names[FW_AIS_NSKIP] = {"not a ship", "broken line", "bad time",
                                                    "bad MMSI", "no position"};
    return s >= 0 && s < FW_AIS_NSKIP ? names[s] : "?";
}

fw_ais_columns fw_ais_dma_columns(void)
{
    fw_ais_columns c;
    for (int i = 0; i < FW_AIS_NFIELDS; i++)
        snprintf(c.name[i], sizeof c.name[i], "%s", dma_name[i]);
    return c;
}

fw_status fw_ais_columns_parse(const char *spec, const char *what, fw_ais_columns *out,
                               fw_error *err)
{
    *out = fw_ais_dma_columns();
    const char *p = spec;
    while (*p) {
        size_t len = strcspn(p, ",");
        const char *eq = memchr(p, '=', len);
        int k = -1;
        for (int i = 0; eq && i < FW_AIS_NFIELDS; i++)
            if ((size_t)(eq - p) == strlen(field_key[i]) && strncmp(p, field_key[i], eq - p) == 0)
                k = i;
        size_t vlen = eq ? len - (size_t)(eq - p) - 1 : 0;
        if (k < 0 || vlen >= sizeof out->name[0])
            return fw_fail(err, FW_EINPUT,
                           "%s: '%.*s': expected FIELD=HEADER NAME, FIELD one of time class mmsi "
                           "lat lon sog cog heading type width length a b c d",
                           what, (int)len, p);
        memcpy(out->name[k], eq + 1, vlen);
        out->name[k][vlen] = '\0';
        p += len + (p[len] == ',');
    }
    return FW_OK;
}

/* Splits a CSV line in place: fields may be quoted ("" is a quote inside
 * one).  The count, or -1 for an unterminated quote. */
static int split(char *s, char **f, int max)
{
    int n = 0;
    char *r = s, *w = s;
    for (;;) {
        if (n == max)
            return n;
        f[n++] = w;
        if (*r == '"') {
            r++;
            for (;;) {
                if (*r == '\0')
                    return -1;
                if (*r == '"' && r[1] == '"') {
                    *w++ = '"';
                    r += 2;
                } else if (*r == '"') {
                    r++;
                    break;
                } else {
                    *w++ = *r++;
                }
            }
        }
        while (*r && *r != ',')
            *w++ = *r++;
        if (*r == '\0') {
            *w = '\0';
            return n;
        }
        *w++ = '\0';
        r++;
    }
}

/* Reads one line into rd->buf (its end cut): 1 a line, 0 end of file, -1
 * a line longer than LINE_MAX_BYTES (the rest of it read and dropped). */
static int read_line(fw_ais_reader *rd)
{
    if (!fgets(rd->buf, LINE_MAX_BYTES + 2, rd->f))
        return 0;
    rd->line_no++;
    size_t n = strlen(rd->buf);
    if (n > 0 && rd->buf[n - 1] == '\n') {
        rd->buf[--n] = '\0';
        if (n > 0 && rd->buf[n - 1] == '\r')
            rd->buf[--n] = '\0';
        return 1;
    }
    if (n <= LINE_MAX_BYTES)
        return 1; /* the last line, without a line end */
    int ch;
    while ((ch = fgetc(rd->f)) != EOF && ch != '\n')
        ;
    return -1;
}

static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t')
        s++;
    size_t n = strlen(s);
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r'))
        s[--n] = '\0';
    return s;
}

static fw_status header(fw_ais_reader *rd, const fw_ais_columns *cols, fw_error *err)
{
    int got = read_line(rd);
    if (got == 0)
        return fw_fail(err, FW_EINPUT, "%s: empty: no header line", rd->file);
    char *h = rd->buf, *f[MAX_FIELDS];
    if (got < 0)
        return fw_fail_at(err, rd->file, 1, "header", "longer than %d bytes", LINE_MAX_BYTES);
    /* a UTF-8 byte order mark, before the '#' (as editors write it) or after */
    if (strncmp(h, "\xEF\xBB\xBF", 3) == 0)
        h += 3;
    if (h[0] == '#')
        h += 1 + (h[1] == ' ');
    if (strncmp(h, "\xEF\xBB\xBF", 3) == 0)
        h += 3;
    int n = split(h, f, MAX_FIELDS);
    if (n < 0)
        return fw_fail_at(err, rd->file, 1, "header", "unterminated quote");
    rd->need = 0;
    for (int k = 0; k < FW_AIS_NFIELDS; k++) {
        rd->col[k] = -1;
        for (int i = 0; cols->name[k][0] && i < n && rd->col[k] < 0; i++)
            if (strcmp(trim(f[i]), cols->name[k]) == 0)
                rd->col[k] = i;
        bool required = k == FW_AIS_F_TIME || k == FW_AIS_F_MMSI || k == FW_AIS_F_LAT ||
                        k == FW_AIS_F_LON;
        if (required && rd->col[k] < 0)
            return fw_fail_at(err, rd->file, 1, "header", "no column '%s' (the %s)",
                              cols->name[k], field_key[k]);
        if (rd->col[k] + 1 > rd->need)
            rd->need = rd->col[k] + 1;
    }
    return FW_OK;
}

fw_status fw_ais_open(const char *path, const fw_ais_columns *cols, fw_ais_reader **out,
                      fw_error *err)
{
    *out = NULL;
    fw_ais_columns dma = fw_ais_dma_columns();
    fw_ais_reader *rd = calloc(1, sizeof *rd);
    if (!rd || !(rd->buf = malloc(LINE_MAX_BYTES + 2))) {
        free(rd);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    snprintf(rd->file, sizeof rd->file, "%s", path);
    rd->c.t_first = rd->c.t_last = NAN;
    struct stat sb = {0};
    if (!(rd->f = fopen(path, "rb")) || fstat(fileno(rd->f), &sb) != 0 || S_ISDIR(sb.st_mode)) {
        /* fopen opens a directory; its first read fails (EISDIR), which
         * looked like an empty file */
        fw_status st = rd->f && S_ISDIR(sb.st_mode)
                           ? fw_fail(err, FW_EINPUT, "%s: is a directory", path)
                           : fw_fail(err, FW_EINPUT, "%s: cannot open: %s", path, strerror(errno));
        fw_ais_close(rd);
        return st;
    }
    fw_status st = header(rd, cols ? cols : &dma, err);
    if (st) {
        fw_ais_close(rd);
        return st;
    }
    *out = rd;
    return FW_OK;
}

void fw_ais_close(fw_ais_reader *rd)
{
    if (!rd)
        return;
    if (rd->f)
        fclose(rd->f);
    free(rd->buf);
    free(rd);
}

const fw_ais_counts *fw_ais_counts_of(const fw_ais_reader *rd) { return &rd->c; }
const char *fw_ais_file(const fw_ais_reader *rd) { return rd->file; }

/* Days from 1970-01-01 to y-m-d (proleptic Gregorian; H. Hinnant's algorithm). */
static long days_from_civil(long y, long m, long d)
{
    y -= m <= 2;
    long era = (y >= 0 ? y : y - 399) / 400;
    long yoe = y - era * 400;
    long doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

bool fw_ais_parse_time(const char *s, double *t)
{
    int a, b, c, hh, mm, n = 0;
    double ss;
    char sep1, sep2, mid;
    if (sscanf(s, "%d%c%d%c%d%c%d:%d:%lf%n", &a, &sep1, &b, &sep2, &c, &mid, &hh, &mm, &ss, &n) !=
            9 ||
        s[n + strspn(s + n, " Z")] != '\0' || sep1 != sep2 || (mid != ' ' && mid != 'T'))
        return false;
    int y, mo, d;
    if (sep1 == '/')
        y = c, mo = b, d = a; /* DD/MM/YYYY */
    else if (sep1 == '-')
        y = a, mo = b, d = c;
    else
        return false;
    static const int mdays[12] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    if (y < 1970 || y > 9999 || mo < 1 || mo > 12 || d < 1 ||
        d > mdays[mo - 1] - (mo == 2 && !leap) || hh < 0 || hh > 23 || mm < 0 || mm > 59 ||
        !(ss >= 0.0 && ss < 61.0))
        return false;
    *t = (double)days_from_civil(y, mo, d) * 86400.0 + hh * 3600.0 + mm * 60.0 + ss;
    return true;
}

void fw_ais_format_time(double t, char *buf, size_t n)
{
    long s = (long)floor(t), days = s / 86400, sec = s % 86400;
    /* civil_from_days (the inverse of the above) */
    long z = days + 719468, era = z / 146097, doe = z - era * 146097;
    long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    long doy = doe - (365 * yoe + yoe / 4 - yoe / 100), mp = (5 * doy + 2) / 153;
    long d = doy - (153 * mp + 2) / 5 + 1, m = mp + (mp < 10 ? 3 : -9);
    long y = yoe + era * 400 + (m <= 2);
    snprintf(buf, n, "%04ld-%02ld-%02ld %02ld:%02ld:%02ld", y, m, d, sec / 3600, sec / 60 % 60,
             sec % 60);
}

/* A number field: NAN when empty, "Unknown" or not a number. */
static double num(char **f, int col)
{
    if (col < 0)
        return NAN;
    char *s = trim(f[col]), *end;
    if (!*s)
        return NAN;
    double v = strtod(s, &end);
    return end != s && *trim(end) == '\0' && isfinite(v) ? v : NAN;
}

static double size_of(double a, double b, double whole)
{
    if (a >= 0 && b >= 0 && a + b > 0 && a + b < 1000)
        return a + b;
    return whole > 0 && whole < 1000 ? whole : 0.0;
}

/* Fills r from a row's fields; the reason when it is skipped, else -1. */
static int parse_row(const fw_ais_reader *rd, char **f, fw_ais_report *r)
{
    const int *col = rd->col;
    memset(r, 0, sizeof *r);
    if (col[FW_AIS_F_CLASS] >= 0) {
        const char *cls = trim(f[col[FW_AIS_F_CLASS]]);
        if (strcmp(cls, "Class A") != 0 && strcmp(cls, "Class B") != 0)
            return FW_AIS_SKIP_NOT_SHIP;
        r->class_b = cls[6] == 'B';
    }
    if (!fw_ais_parse_time(trim(f[col[FW_AIS_F_TIME]]), &r->t))
        return FW_AIS_SKIP_TIME;
    double mmsi = num(f, col[FW_AIS_F_MMSI]);
    if (!(mmsi >= 1 && mmsi <= 999999999 && mmsi == floor(mmsi)))
        return FW_AIS_SKIP_MMSI;
    r->mmsi = (long)mmsi;
    /* without a class column, the MMSI says: ships have 9 digits, the first 2-7 */
    if (col[FW_AIS_F_CLASS] < 0 && (r->mmsi < 200000000 || r->mmsi > 799999999))
        return FW_AIS_SKIP_NOT_SHIP;
    r->lat = num(f, col[FW_AIS_F_LAT]);
    r->lon = num(f, col[FW_AIS_F_LON]);
    if (!(fabs(r->lat) <= 90.0 && fabs(r->lon) <= 180.0)) /* 91/181: not available */
        return FW_AIS_SKIP_POSITION;
    double sog = num(f, col[FW_AIS_F_SOG]), cog = num(f, col[FW_AIS_F_COG]);
    double hdg = num(f, col[FW_AIS_F_HEADING]);
    r->sog = sog >= 0.0 && sog < 102.2 ? fw_kn_to_ms(sog) : NAN;
    r->cog = cog >= 0.0 && cog < 360.0 ? fw_deg_to_rad(cog) : NAN;
    r->heading = hdg >= 0.0 && hdg < 360.0 ? fw_deg_to_rad(hdg) : NAN;
    if (col[FW_AIS_F_TYPE] >= 0) {
        const char *ty = trim(f[col[FW_AIS_F_TYPE]]);
        double code = num(f, col[FW_AIS_F_TYPE]);
        if (code >= 0 && code <= 99 && code == floor(code)) {
            r->type_code = (int)code;
            r->kind = fw_ais_kind_of_code(r->type_code);
        } else {
            r->kind = kind_of_words(ty);
        }
    }
    r->length = size_of(num(f, col[FW_AIS_F_A]), num(f, col[FW_AIS_F_B]),
                        num(f, col[FW_AIS_F_LENGTH]));
    r->breadth = size_of(num(f, col[FW_AIS_F_C]), num(f, col[FW_AIS_F_D]),
                         num(f, col[FW_AIS_F_WIDTH]));
    return -1;
}

static void keep(fw_ais_counts *c, const fw_ais_report *r)
{
    c->kept++;
    c->class_a += !r->class_b;
    c->class_b += r->class_b;
    c->no_sog += isnan(r->sog);
    c->no_cog += isnan(r->cog);
    if (isnan(c->t_first) || r->t < c->t_first)
        c->t_first = r->t;
    if (isnan(c->t_last) || r->t > c->t_last)
        c->t_last = r->t;
}

fw_status fw_ais_next(fw_ais_reader *rd, fw_ais_report *r, bool *got, fw_error *err)
{
    *got = false;
    char *f[MAX_FIELDS];
    for (;;) {
        int l = read_line(rd);
        if (l == 0)
            break;
        if (l > 0 && rd->buf[strspn(rd->buf, " \t")] == '\0')
            continue; /* blank */
        rd->c.rows++;
        int n = l > 0 ? split(rd->buf, f, MAX_FIELDS) : -1;
        int why = n < rd->need ? FW_AIS_SKIP_BROKEN : parse_row(rd, f, r);
        if (why >= 0) {
            rd->c.skipped[why]++;
            continue;
        }
        r->line = rd->line_no;
        keep(&rd->c, r);
        *got = true;
        return FW_OK;
    }
    if (ferror(rd->f))
        return fw_fail(err, FW_ERUN, "%s:%d: read error", rd->file, rd->line_no);
    return FW_OK;
}

void fw_ais_print_counts(FILE *out, const fw_ais_counts *c)
{
    fprintf(out, "rows: %ld\nkept: %ld (Class A %ld, Class B %ld; without SOG %ld, without COG "
                 "%ld)\n",
            c->rows, c->kept, c->class_a, c->class_b, c->no_sog, c->no_cog);
    for (int k = 0; k < FW_AIS_NSKIP; k++)
        fprintf(out, "skipped, %s: %ld\n", fw_ais_skip_name((fw_ais_skip)k), c->skipped[k]);
    if (c->kept > 0) {
        char a[32], b[32];
        fw_ais_format_time(c->t_first, a, sizeof a);
        fw_ais_format_time(c->t_last, b, sizeof b);
        fprintf(out, "time: %s to %s UTC (%.0f s)\n", a, b, c->t_last - c->t_first);
    }
}
