/* fairway run: scenarios with SUMO traffic, full records, one table row each.
 *
 * Every scenario file is loaded and checked before anything is created, so a
 * bad file leaves no output behind.  Each run writes into a hidden temporary
 * directory next to its final place and is renamed into place at the end.
 *
 * The runs execute in a child process; this process only waits for it.  On
 * Ctrl-C or SIGTERM (which the run itself, SUMO inside, cannot stop cleanly)
 * the child is stopped, its unfinished temporary directory removed, and the
 * message says which finished runs were kept.
 */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "avoid/helm_search.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "core/files.h"
#include "core/leftover.h"
#include "core/units.h"
#include "run/run.h"
#include "scenario/scenario.h"
#include "scenario/scn_dnv.h"

static void help(void)
{
    printf("usage: fairway run SCENARIO... [--out DIR] [--sumo MODE] [--json] [--profile]\n"
           "                  [--ship SHIP]\n"
           "\n"
           "Runs each scenario file (YAML, see scenarios/README.md): SUMO moves the\n"
           "targets and background traffic (or recorded tracks and AIS reports are\n"
           "replayed), the own ship is stepped with the MMG model (own_ship.dynamics:\n"
           "nomoto: its own Nomoto model) and steered by the Nomoto avoidance policy\n"
           "every step.  Each run writes DIR/NAME/ with own.csv, targets.csv,\n"
           "encounters.csv, summary.json, run.log and sumo/ (the generated network and\n"
           "routes, run.sumocfg for sumo-gui, with outputs: fcd: true fcd.xml, which\n"
           "analysis/replay_gui.py replays).  Prints one row per scenario:\n"
           "minimum distance to any target, domain entered, collision, first action\n"
           "(time, side, helm), largest helm, path lengthening and time lost.\n"
           "\n"
           "  --out DIR     where run directories go (default: runs); an existing\n"
           "                run directory DIR/NAME is replaced, anything else there\n"
           "                refused\n"
           "  --sumo MODE   embedded (default, libsumo in-process), gui, or\n"
           "                remote:HOST:PORT (a sumo started with the command each run\n"
           "                writes, DIR/NAME/sumo/remote-command.txt: a run with no sumo\n"
           "                there fails and keeps it; a sumo on another network is refused;\n"
           "                FAIRWAY_SUMO_TIMEOUT=S: the seconds it has to connect and to\n"
           "                begin each answer, default 10 and 60)\n"
           "A SCENARIO ending in .json is a DNV maritime-schema traffic situation\n"
           "(scenarios/dnv/README.md): the targets follow their waypoints, the own ship\n"
           "is fairway's c3-mmg (or --ship) from the situation's start on its first leg.\n"
           "\n"
           "  --ship SHIP   the own ship's model for DNV situations (a name in\n"
           "                scenarios/ships or a ship file; default c3-mmg); run.log\n"
           "                says which, and what of the situation's own ship is used\n"
           "  --json        print the summaries as a JSON array instead of the table\n"
           "  --profile     where each run's CPU time went (set-up, SUMO's steps, the\n"
           "                reads, the decisions, the reactions, the own dynamics, the\n"
           "                records), a line in run.log and on stderr\n"
           "\n"
           "Watching a run in sumo-gui (--sumo gui; needs a display, e.g. xvfb-run):\n"
           "  --gui-delay MS     wall-clock ms per step at least (default 30)\n"
           "  --realtime X       instead: X simulated seconds per second (1 = real time)\n"
           "  --gui-size WxH     the window, pixels (default 1280x800)\n"
           "  --gui-view NM      width of the view about the own ship, which it follows\n"
           "                     (default 3)\n"
           "  --gui-settings FILE  sumo-gui view settings (default\n"
           "                     networks/fairway.view.xml: ships to scale, own ship orange)\n"
           "  --gui-keep         keep the window open at the end until it is closed\n"
           "  --gui-screenshot   a PNG of the view at the end: DIR/NAME/screenshot.png\n"
           "\n"
           "The same scenario and seed give byte-identical result files.\n"
           "Ctrl-C or SIGTERM stop the runs: finished runs are kept, the unfinished one\n"
           "is removed.\n"
           "Exit codes: 0 ok, 1 a run failed or was interrupted, 2 bad input (nothing is\n"
           "written).\n");
}

static void row(const fw_run_summary *s)
{
    char act[48] = "-", ret[16] = "-";
    if (s->acted)
        snprintf(act, sizeof act, "%6.0f %-4s %2.0f", s->t_act,
                 s->act_side == FW_SIDE_STARBOARD ? "stbd" : "port",
                 fw_rad_to_deg(fabs(s->act_helm)));
    if (!isnan(s->t_return))
        snprintf(ret, sizeof ret, "%.0f", s->t_return);
    printf("%-34s %8.0f %-6s %-9s %-17s %8.0f %7s %9.0f %9.0f  %s\n", s->scenario, s->min_dist,
           s->domain_entered ? "yes" : "no", s->collision ? "COLLISION" : "no", act,
           fw_rad_to_deg(s->max_helm), ret, s->path_lengthening, s->time_lost,
           s->status != FW_RUN_OK ? fw_run_status_name(s->status) : (s->colregs_ok ? "ok" : "colregs?"));
}

/* The sumo-gui options as given (checked in check_gui). */
typedef struct gui_opts {
    double delay_ms, realtime, view_nm;
    const char *size, *settings;
    bool keep, screenshot;
    bool given; /* any of them */
} gui_opts;

typedef struct run_opts {
    const char *out, *mode, *ship;
    bool json;
    gui_opts gui;
    const char **files;
    int nf;
    fw_scenario **scn;
    fw_run_def def;
} run_opts;

static fw_status add_file(void *ctx, const char *arg, fw_error *err)
{
    (void)err;
    run_opts *o = ctx;
    o->files[o->nf++] = arg;
    return FW_OK;
}

/* The gui options into the traffic mode; each refused by name when out of
 * range, and all of them without --sumo gui. */
static fw_status check_gui(const gui_opts *g, const bool *seen, fw_traffic_mode *m,
                           fw_error *err)
{
    static const char *const names[] = {"--gui-delay", "--realtime", "--gui-size", "--gui-view",
                                        "--gui-settings", "--gui-keep", "--gui-screenshot"};
    for (int k = 0; k < 7; k++)
        if (seen[k] && m->kind != FW_TRAFFIC_GUI)
            return fw_fail(err, FW_EINPUT, "%s: only with --sumo gui", names[k]);
    if (seen[0] && seen[1])
        return fw_fail(err, FW_EINPUT, "--realtime: give it or --gui-delay, not both");
    if (!(g->delay_ms >= 0.0 && g->delay_ms <= 60000.0))
        return fw_fail(err, FW_EINPUT, "--gui-delay %.15g: must be 0..60000 ms", g->delay_ms);
    if (seen[1] && !(g->realtime > 0.0 && g->realtime <= 1e6))
        return fw_fail(err, FW_EINPUT, "--realtime %.15g: must be above 0 (1 = real time)",
                       g->realtime);
    if (!(g->view_nm > 0.0 && g->view_nm <= 500.0))
        return fw_fail(err, FW_EINPUT, "--gui-view %.15g: must be in (0, 500] nm", g->view_nm);
    int w = 0, h = 0, used = 0;
    if (sscanf(g->size, "%dx%d%n", &w, &h, &used) != 2 || g->size[used] != '\0' || w < 200 ||
        h < 150 || w > 10000 || h > 10000)
        return fw_fail(err, FW_EINPUT, "--gui-size '%s': expected WxH, e.g. 1280x800", g->size);
    if (g->settings && access(g->settings, R_OK) != 0)
        return fw_fail(err, FW_EINPUT, "--gui-settings %s: cannot be read", g->settings);
    m->gui = (fw_traffic_gui){.delay_ms = g->delay_ms, .width = w, .height = h,
                              .view_m = fw_nm_to_m(g->view_nm), .keep = g->keep,
                              .settings = g->settings};
    /* no display: said at once, not after the connect timeout */
    return m->kind == FW_TRAFFIC_GUI ? fw_traffic_gui_check("--sumo", err) : FW_OK;
}

/* Returns -1 to go on, else the exit code. */
static int parse_options(int argc, char **argv, run_opts *o, fw_error *err)
{
    gui_opts *g = &o->gui;
    bool seen[7] = {0};
    const fw_opt opts[] = {
        FW_OPT("--out", FW_OPT_TEXT, &o->out), FW_OPT("--sumo", FW_OPT_TEXT, &o->mode),
        FW_OPT("--json", FW_OPT_FLAG, &o->json), FW_OPT("--ship", FW_OPT_TEXT, &o->ship), FW_OPT("--profile", FW_OPT_FLAG, &o->def.profile),
        FW_OPT_SEEN("--gui-delay", FW_OPT_DOUBLE, &g->delay_ms, &seen[0]),
        FW_OPT_SEEN("--realtime", FW_OPT_DOUBLE, &g->realtime, &seen[1]),
        FW_OPT_SEEN("--gui-size", FW_OPT_TEXT, &g->size, &seen[2]),
        FW_OPT_SEEN("--gui-view", FW_OPT_DOUBLE, &g->view_nm, &seen[3]),
        FW_OPT_SEEN("--gui-settings", FW_OPT_TEXT, &g->settings, &seen[4]),
        FW_OPT_SEEN("--gui-keep", FW_OPT_FLAG, &g->keep, &seen[5]),
        FW_OPT_SEEN("--gui-screenshot", FW_OPT_FLAG, &g->screenshot, &seen[6]), FW_OPT_END,
    };
    int rc = fw_args_parse(argc, argv, "run", opts, help, add_file, o, err);
    if (rc >= 0)
        return rc;
    if (o->nf == 0)
        fw_fail(err, FW_EINPUT, "no scenario given (see fairway run --help)");
    else if (!fw_traffic_mode_parse(o->mode, &o->def.mode, err) &&
             !fw_check_sumo_mode("--sumo", &o->def.mode, err))
        check_gui(g, seen, &o->def.mode, err);
    return err->status ? fw_report(err) : -1;
}

/* Every scenario loaded and checked, and --out made, before any run. */
/* DIR/NAME is replaced whole by the run (core/files.h fw_check_run_dir). */
static fw_status check_run_dir(const char *out, const char *name, fw_error *err)
{
    char dst[1024];
    if (fw_path(dst, sizeof dst, err, "%s/%s", out, name))
        return err->status;
    return fw_check_run_dir("--out", dst, err);
}

static int load_all(run_opts *o, fw_error *err)
{
    if (!(o->scn = calloc((size_t)o->nf, sizeof *o->scn)))
        return fw_report((fw_fail(err, FW_ERUN, "out of memory"), err));
    for (int i = 0; i < o->nf; i++) {
        o->scn[i] = malloc(sizeof **o->scn);
        if (!o->scn[i])
            return fw_report((fw_fail(err, FW_ERUN, "out of memory"), err));
        fw_status st = fw_scn_is_dnv(o->files[i])
                           ? fw_scn_dnv_load(o->files[i], o->ship, o->scn[i], err)
                           : fw_scenario_load(o->files[i], o->scn[i], err);
        if (st)
            return fw_report(err);
        for (int j = 0; j < i; j++)
            if (strcmp(o->scn[i]->name, o->scn[j]->name) == 0)
                return fw_report((fw_fail(err, FW_EINPUT,
                                          "%s and %s have the same name '%s' (one output directory)",
                                          o->files[j], o->files[i], o->scn[i]->name),
                                  err));
    }
    if (strlen(o->out) > 700)
        return fw_report((fw_fail(err, FW_EINPUT, "--out: path too long"), err));
    if (fw_mkdirs(o->out, "--out", err))
        return fw_report(err);
    for (int i = 0; i < o->nf; i++)
        if (check_run_dir(o->out, o->scn[i]->name, err))
            return fw_report(err);
    for (int i = 0; i < o->nf; i++)
        fw_warn_nomoto_speed(&o->scn[i]->ship, fw_ms_to_kn(o->scn[i]->speed), o->files[i],
                             "own_ship.speed_kn");
    return -1;
}

/* --out is at most 700 characters (load_all) and a name 63: the run's paths
 * fit in 1024 bytes, never cut. */
static void tmp_name(const run_opts *o, int i, long pid, char *out, size_t n)
{
    snprintf(out, n, "%s/.%s.tmp.%ld", o->out, o->scn[i]->name, pid);
}

/* One scenario into DIR/NAME; *fatal when the remaining runs must not go on. */
static int run_one(run_opts *o, int i, bool first, bool *fatal, fw_error *err)
{
    char tmp[1024], dst[1024];
    tmp_name(o, i, (long)getpid(), tmp, sizeof tmp);
    snprintf(dst, sizeof dst, "%s/%s", o->out, o->scn[i]->name);
    *fatal = true;
    fw_remove_tree(tmp);
    if (mkdir(tmp, 0777) != 0)
        return fw_report((fw_fail(err, FW_ERUN, "cannot create %s", tmp), err));
    if (fw_leftover_mark(tmp, err)) /* a SIGKILL leaves it: the next run removes it */
        return fw_report(err);
    o->def.scenario = o->scn[i];
    o->def.dir = tmp;
    char shot[1100];
    if (o->gui.screenshot) {
        snprintf(shot, sizeof shot, "%s/screenshot.png", tmp);
        o->def.mode.gui.screenshot = shot;
    }
    if (o->gui.realtime > 0.0) /* SUMO's delay is per step */
        o->def.mode.gui.delay_ms = 1000.0 * o->scn[i]->step / o->gui.realtime;
    fw_run_summary sum;
    fw_encounter *enc = NULL;
    int ne = 0;
    fw_status st = fw_run_scenario(&o->def, &sum, &enc, &ne, err);
    if (st == FW_EINPUT) {
        fw_remove_tree(tmp);
        free(enc);
        return fw_report(err);
    }
    /* a failed run keeps its directory: the log says what happened */
    fw_remove_tree(dst);
    if (rename(tmp, dst) != 0) {
        fw_remove_tree(tmp);
        free(enc);
        return fw_report((fw_fail(err, FW_ERUN, "cannot rename %s to %s", tmp, dst), err));
    }
    *fatal = false;
    if (st)
        fprintf(stderr, "fairway run: %s: %s\n", o->scn[i]->name, err->msg);
    if (o->json) {
        printf("%s\n", first ? "" : ",");
        fw_summary_json(stdout, &sum, enc, ne, "  ");
    } else {
        row(&sum);
    }
    fflush(stdout);
    free(enc);
    return st ? 1 : 0;
}

/* The child's part: every run, each reported on fd (its index) once it is
 * in place. */
static int run_all(run_opts *o, int fd, fw_error *err)
{
    if (!o->json)
        printf("%-34s %8s %-6s %-9s %-17s %8s %7s %9s %9s  %s\n", "scenario", "min_d_m", "domain",
               "collision", "action_s side deg", "max_helm", "return", "path_+m", "lost_s",
               "status");
    else
        printf("[");
    int rc = 0, done = 0;
    for (int i = 0; i < o->nf; i++) {
        bool fatal;
        int r = run_one(o, i, done == 0, &fatal, err);
        if (fatal) {
            rc = r;
            break;
        }
        done++;
        rc = r ? r : rc;
        unsigned char idx[4] = {(unsigned char)(i >> 24), (unsigned char)(i >> 16),
                                (unsigned char)(i >> 8), (unsigned char)i};
        if (write(fd, idx, sizeof idx) != (ssize_t)sizeof idx)
            break; /* the parent is gone */
    }
    if (o->json)
        printf("%s]\n", done ? "\n" : "");
    fflush(stdout);
    return rc;
}

static volatile sig_atomic_t g_child = 0, g_signal = 0;

static void forward(int sig)
{
    g_signal = sig;
    if (g_child > 0)
        kill((pid_t)g_child, sig);
}

/* After the child died of a signal: remove its unfinished directory, say
 * what was kept. */
static int interrupted(run_opts *o, pid_t pid, int sig, int fd)
{
    bool *kept = calloc((size_t)o->nf, sizeof *kept);
    unsigned char idx[4];
    while (kept && read(fd, idx, sizeof idx) == (ssize_t)sizeof idx) {
        int i = idx[0] << 24 | idx[1] << 16 | idx[2] << 8 | idx[3];
        if (i >= 0 && i < o->nf)
            kept[i] = true;
    }
    int n = 0;
    for (int i = 0; i < o->nf; i++) {
        char tmp[1024];
        tmp_name(o, i, (long)pid, tmp, sizeof tmp);
        fw_remove_tree(tmp);
        n += kept && kept[i];
    }
    fflush(stdout);
    fprintf(stderr, "\nfairway run: %s; kept %d finished run%s in %s%s", strsignal(sig), n,
            n == 1 ? "" : "s", o->out, n ? ":" : "");
    for (int i = 0; i < o->nf; i++)
        if (kept && kept[i])
            fprintf(stderr, " %s", o->scn[i]->name);
    fprintf(stderr, "; the unfinished run was removed\n");
    free(kept);
    return 1;
}

/* Runs run_all in a child and waits, forwarding SIGINT and SIGTERM. */
static int supervise(run_opts *o, fw_error *err)
{
    int fds[2];
    if (pipe(fds) != 0)
        return fw_report((fw_fail(err, FW_ERUN, "pipe: %s", strerror(errno)), err));
    /* what a SIGKILLed run before left in the output */
    fw_leftover_clean(o->out, ".", "an interrupted fairway run");
    fflush(NULL);
    pid_t parent = getpid();
    pid_t pid = fork();
    if (pid < 0)
        return fw_report((fw_fail(err, FW_ERUN, "fork: %s", strerror(errno)), err));
    if (pid == 0) {
        /* a background job starts with SIGINT ignored: the child must die of it */
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        /* and of this process's death (a SIGKILL it cannot forward): an
         * orphan would finish its run and write it into the output later */
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent)
            _exit(1);
        close(fds[0]);
        exit(run_all(o, fds[1], err));
    }
    close(fds[1]);
    g_child = pid;
    struct sigaction sa = {0}, old_int, old_term;
    sa.sa_handler = forward;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    g_child = 0;
    int rc = WIFEXITED(status) ? WEXITSTATUS(status)
                               : interrupted(o, pid, WIFSIGNALED(status) ? WTERMSIG(status) : 0,
                                             fds[0]);
    close(fds[0]);
    return rc;
}

int fw_cmd_run(int argc, char **argv)
{
    fw_error err = {0};
    run_opts o = {.out = "runs", .mode = "embedded", .def = fw_default_run_def(),
                  .gui = {.delay_ms = 30.0, .view_nm = 3.0, .size = "1280x800"}};
    if (!(o.files = calloc((size_t)argc + 1, sizeof *o.files)))
        return 1;
    int rc = parse_options(argc, argv, &o, &err);
    if (rc < 0)
        rc = load_all(&o, &err);
    if (rc < 0)
        rc = supervise(&o, &err);
    for (int i = 0; o.scn && i < o.nf; i++)
        free(o.scn[i]);
    free(o.scn);
    free(o.files);
    return rc;
}
