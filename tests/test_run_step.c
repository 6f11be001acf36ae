/* test_run_step.c - a run stepped by hand (run.h: open, step, close).
 *
 * fw_run_scenario is open + step until done + close, so a caller that steps
 * the run itself must get the same files to the byte: checked for a paper
 * case with the kinematic source and one through SUMO.  A run closed half way
 * gives a summary that ends there, and files that are the first part of the
 * whole run's (the rows up to then are the same rows).  A run without a
 * directory writes nothing and keeps the same encounter book.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files.h"
#include "run/run.h"
#include "world/controllers.h"
#include "test.h"
#include "test_tmp.h"

static char tmp_root[256];
static fw_scenario s; /* large: a ship inside */

static const char *const files[] = {"own.csv", "targets.csv", "encounters.csv", "summary.json",
                                    "run.log"};
enum { NFILES = sizeof files / sizeof files[0] };

/* The whole of a file, malloc'd (NULL: none); its length into *n. */
static char *slurp(const char *dir, const char *name, size_t *n)
{
    char path[700];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "rb");
    *n = 0;
    if (!f)
        return NULL;
    char *b = NULL;
    size_t cap = 0;
    int c;
    while ((c = fgetc(f)) != EOF) {
        if (*n + 1 >= cap) {
            cap = cap ? 2 * cap : 4096;
            b = realloc(b, cap);
        }
        b[(*n)++] = (char)c;
    }
    fclose(f);
    return b ? b : calloc(1, 1);
}

static bool same_file(const char *d1, const char *d2, const char *name)
{
    size_t n1, n2;
    char *a = slurp(d1, name, &n1), *b = slurp(d2, name, &n2);
    bool same = a && b && n1 == n2 && memcmp(a, b, n1) == 0;
    free(a);
    free(b);
    return same;
}

/* The first `lines` lines of `name` are the same in both directories. */
static bool same_lines(const char *d1, const char *d2, const char *name, int lines)
{
    size_t n1, n2;
    char *a = slurp(d1, name, &n1), *b = slurp(d2, name, &n2);
    size_t k = 0;
    for (int l = 0; a && k < n1 && l < lines; k++)
        l += a[k] == '\n';
    bool same = a && b && k <= n2 && memcmp(a, b, k) == 0;
    free(a);
    free(b);
    return same;
}

static int count_lines(const char *dir, const char *name)
{
    size_t n;
    char *a = slurp(dir, name, &n);
    int l = 0;
    for (size_t k = 0; k < n; k++)
        l += a[k] == '\n';
    free(a);
    return l;
}

static fw_run_def def_for(const char *dir, fw_run_traffic traffic)
{
    fw_run_def d = fw_default_run_def();
    d.scenario = &s;
    d.dir = dir;
    d.traffic = traffic;
    if (dir)
        mkdir(dir, 0777);
    return d;
}

/* Opens a run and steps it `steps` times (-1: until done), then closes it. */
static fw_status step_by_hand(const fw_run_def *d, long steps, fw_run_summary *sum,
                              fw_encounter **e, int *n)
{
    fw_error err = {0};
    fw_run *r;
    fw_status st = fw_run_open(d, &r, &err);
    CHECK_MSG(st == FW_OK && r, "open: %s", err.msg);
    if (!r)
        return FW_ERUN;
    CHECK(fw_run_steps(r) == 0 && fw_run_time(r) == 0.0 && fw_run_world(r) != NULL);
    FILE *fs[4];
    int nf = fw_run_files(r, fs, 4);
    CHECK_MSG(d->dir ? nf == 2 + s.targets_csv : nf == 0, "%d open streams", nf);
    for (int i = 0; i < nf && i < 4; i++) /* the header, at least, is written */
        CHECK(fflush(fs[i]) == 0 && ftell(fs[i]) > 0);
    while (!st && !fw_run_done(r) && (steps < 0 || fw_run_steps(r) < steps))
        st = fw_run_step(r, &err);
    CHECK_MSG(st == FW_OK, "step %ld: %s", fw_run_steps(r), err.msg);
    CHECK_NEAR(fw_run_time(r), fw_run_steps(r) * s.step, 1e-9);
    if (steps < 0) { /* a run that is done is not stepped */
        long k = fw_run_steps(r);
        CHECK(fw_run_step(r, &err) == FW_EINPUT && fw_run_steps(r) == k);
        CHECK(k == lround(s.duration / s.step));
    }
    fw_status cst = fw_run_close(r, sum, e, n, &err);
    CHECK_MSG(cst == FW_OK, "close: %s", err.msg);
    return st ? st : cst;
}

static void load(const char *rel)
{
    char p[512];
    snprintf(p, sizeof p, "%s/scenarios/%s.yaml", fw_data_root(), rel);
    fw_error err = {0};
    CHECK_MSG(fw_scenario_load(p, &s, &err) == FW_OK, "%s", err.msg);
}

/* The summaries of two runs agree in every measure summary.json prints (to
 * its decimals) and in the ones it does not to the bit. */
static void same_summary(const fw_run_summary *a, const fw_run_summary *b)
{
    char *ja = NULL, *jb = NULL;
    size_t na = 0, nb = 0;
    FILE *fa = open_memstream(&ja, &na), *fb = open_memstream(&jb, &nb);
    fw_summary_json(fa, a, NULL, 0, "");
    fw_summary_json(fb, b, NULL, 0, "");
    fclose(fa);
    fclose(fb);
    CHECK(na == nb && na > 0 && memcmp(ja, jb, na) == 0);
    free(ja);
    free(jb);
    CHECK(a->status == b->status && a->n_encounters == b->n_encounters);
    CHECK(a->t_end == b->t_end && a->min_dist == b->min_dist && a->min_hull == b->min_hull);
    CHECK(a->path_length == b->path_length && a->rudder_work == b->rudder_work);
    CHECK(a->cross_track == b->cross_track && a->heading_error == b->heading_error);
    CHECK(a->helm_orders == b->helm_orders && a->kb_outside_s == b->kb_outside_s);
}

static void by_hand_against_whole(const char *rel, fw_run_traffic traffic, const char *tag)
{
    load(rel);
    char whole[400], hand[400], half[400];
    snprintf(whole, sizeof whole, "%s/%s-whole", tmp_root, tag);
    snprintf(hand, sizeof hand, "%s/%s-hand", tmp_root, tag);
    snprintf(half, sizeof half, "%s/%s-half", tmp_root, tag);
    fw_run_def dw = def_for(whole, traffic), dh = def_for(hand, traffic),
               dp = def_for(half, traffic);
    fw_run_summary sw, sh, sp;
    fw_encounter *ew = NULL, *eh = NULL, *ep = NULL;
    int nw = 0, nh = 0, np = 0;
    fw_error err = {0};
    CHECK_MSG(fw_run_scenario(&dw, &sw, &ew, &nw, &err) == FW_OK, "%s", err.msg);
    if (step_by_hand(&dh, -1, &sh, &eh, &nh))
        return;
    for (int i = 0; i < NFILES; i++)
        CHECK_MSG(same_file(whole, hand, files[i]), "%s: %s differs stepped by hand", tag,
                  files[i]);
    same_summary(&sw, &sh);
    CHECK(nw == nh && nw > 0 && memcmp(ew, eh, sizeof *ew * (size_t)nw) == 0);

    /* half way: the summary ends there, the time histories are the whole
     * run's first half (one own.csv row per record_every from t = 0) */
    long k = lround(s.duration / s.step) / 2;
    if (step_by_hand(&dp, k, &sp, &ep, &np))
        return;
    CHECK(sp.status == FW_RUN_OK);
    CHECK_NEAR(sp.t_end, k * s.step, 1e-9);
    CHECK(sp.path_length > 0.0 && sp.path_length < sw.path_length);
    CHECK(sp.along_track < sw.along_track && np <= nw && np > 0);
    int rows = 1 + (int)lround(k * s.step / s.record_every) + 1; /* header, t = 0 .. t_end */
    CHECK_MSG(count_lines(half, "own.csv") == rows, "%s: own.csv %d lines, expected %d", tag,
              count_lines(half, "own.csv"), rows);
    CHECK(same_lines(whole, half, "own.csv", rows));
    CHECK(same_lines(whole, half, "targets.csv", count_lines(half, "targets.csv")));
    size_t n;
    char *js = slurp(half, "summary.json", &n);
    char want[64];
    snprintf(want, sizeof want, "\"status\": \"ok\", \"t_end_s\": %.1f,", sp.t_end);
    CHECK_MSG(js && strstr(js, want), "%s: summary.json lacks %s", tag, want);
    free(js);
    printf("  %s: %d encounters, t_end %.0f s; half way %d encounters, t_end %.0f s, path %.0f "
           "of %.0f m\n", tag, nw, sw.t_end, np, sp.t_end, sp.path_length, sw.path_length);
    free(ew);
    free(eh);
    free(ep);
}

static void test_kinematic(void)
{
    by_hand_against_whole("paper/5-crossing-complex", FW_RUN_TRAFFIC_KINEMATIC, "kin");
}

static void test_sumo(void) { by_hand_against_whole("paper/3-crossing", FW_RUN_TRAFFIC_SUMO, "sumo"); }

/* No directory: no files, the same encounter book and summary; SUMO needs a
 * directory (a clear error, the run closed as failed). */
static void test_no_dir(void)
{
    load("paper/5-crossing-complex");
    char whole[400];
    snprintf(whole, sizeof whole, "%s/nodir-whole", tmp_root);
    fw_run_def dw = def_for(whole, FW_RUN_TRAFFIC_KINEMATIC);
    fw_run_def dn = def_for(NULL, FW_RUN_TRAFFIC_KINEMATIC);
    fw_run_summary sw, sn;
    fw_encounter *ew = NULL, *en = NULL;
    int nw = 0, nn = 0;
    fw_error err = {0};
    CHECK_MSG(fw_run_scenario(&dw, &sw, &ew, &nw, &err) == FW_OK, "%s", err.msg);
    if (step_by_hand(&dn, -1, &sn, &en, &nn))
        return;
    same_summary(&sw, &sn);
    CHECK(nw == nn && nw > 0 && memcmp(ew, en, sizeof *ew * (size_t)nw) == 0);
    free(ew);
    free(en);

    fw_run_def ds = def_for(NULL, FW_RUN_TRAFFIC_SUMO);
    fw_run *r;
    fw_status st = fw_run_open(&ds, &r, &err);
    CHECK_MSG(st == FW_EINPUT && strstr(err.msg, "needs a run directory"), "%d %s", st, err.msg);
    CHECK(r && fw_run_done(r) && fw_run_world(r) == NULL);
    CHECK(fw_run_step(r, &err) == FW_EINPUT);
    CHECK(fw_run_close(r, &sn, &en, &nn, &err) == FW_EINPUT);
    CHECK(sn.status == FW_RUN_FAILED && nn == 0 && en == NULL);
    CHECK(strcmp(sn.scenario, s.name) == 0);

    /* a controller of the caller's is the run's also when the set-up fails
     * (LeakSanitizer would see it otherwise) */
    fw_manoeuvre_def md = {.t_act = 0.0, .helm = 0.1, .course = s.course, .alteration = 0.5};
    CHECK(fw_manoeuvre_controller_create(&md, &ds.controller, &err) == FW_OK);
    CHECK(fw_run_open(&ds, &r, &err) == FW_EINPUT && r && fw_run_done(r));
    CHECK(fw_run_close(r, &sn, &en, &nn, &err) == FW_EINPUT && sn.status == FW_RUN_FAILED);
}

int main(void)
{
    if (test_tmpdir("run_step", tmp_root, sizeof tmp_root))
        return 1;
    TEST_RUN(test_kinematic);
    TEST_RUN(test_sumo);
    TEST_RUN(test_no_dir);
    return TEST_EXIT();
}
