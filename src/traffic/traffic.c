/* traffic.c - the C side of the SUMO coupling: starting SUMO (embedded, a
 * sumo-gui, a remote sumo), the one frame conversion, and the step-loop calls
 * dispatched to the libsumo or libtraci table of traffic_sumo.cpp.  The
 * queries are in traffic_query.c, SUMO's command line in sumoargs.c. */
#include "core/files.h"
#include "traffic/traffic.h"

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/clock.h"
#include "core/idmap.h"
#include "core/mem.h"
#include "core/spawn.h"
#include "core/units.h"
#include "traffic/backend.h"
#include "traffic/fcd.h"
#include "traffic/traci_guard.h"
#include "traffic/traffic_internal.h"


static bool embedded_open = false; /* libsumo: one simulation per process */

fw_traffic_def fw_default_traffic_def(void)
{
    fw_traffic_def d;
    memset(&d, 0, sizeof d);
    d.mode.kind = FW_TRAFFIC_EMBEDDED;
    d.step = 1.0;
    d.seed = 1;
    d.sumo_gui = "sumo-gui";
    d.connect_timeout = 10.0;
    d.reply_timeout = 60.0;
    d.own_id = "own";
    d.own_length = 100.0;
    d.own_width = 16.0;
    d.radius = fw_nm_to_m(6.0);
    d.lane_change_s = 900.0;
    return d;
}

void fw_traffic_to_sumo(double x, double y, double heading, double length, double *fx,
                        double *fy, double *angle_deg)
{
    *fx = x + 0.5 * length * sin(heading);
    *fy = y + 0.5 * length * cos(heading);
    *angle_deg = fw_rad_to_deg(fw_wrap_2pi(heading));
}

void fw_traffic_from_sumo(double fx, double fy, double angle_deg, double length, double *x,
                          double *y, double *heading)
{
    double h = fw_deg_to_rad(angle_deg);
    fw_traffic_from_sumo_sc(fx, fy, angle_deg, sin(h), cos(h), length, x, y, heading);
}

void fw_traffic_from_sumo_sc(double fx, double fy, double angle_deg, double sh, double ch,
                             double length, double *x, double *y, double *heading)
{
    *x = fx - 0.5 * length * sh;
    *y = fy - 0.5 * length * ch;
    *heading = fw_wrap_2pi(fw_deg_to_rad(angle_deg));
}

static fw_status check_def(const fw_traffic_def *d, fw_error *err)
{
    if (!(d->step > 0.0 && d->step <= 60.0))
        return fw_fail(err, FW_EINPUT, "traffic step %g s: must be in (0, 60]", d->step);
    if (!(d->radius > 0.0 && isfinite(d->radius)))
        return fw_fail(err, FW_EINPUT, "traffic radius %g m: must be positive", d->radius);
    if (!(d->area_radius >= 0.0 && isfinite(d->area_radius)))
        return fw_fail(err, FW_EINPUT, "traffic area radius %g m: must be 0 (none) or positive",
                       d->area_radius);
    if (!(d->near_radius >= 0.0 && isfinite(d->near_radius)))
        return fw_fail(err, FW_EINPUT, "traffic near radius %g m: must be 0 (none) or positive",
                       d->near_radius);
    if (!(d->own_length > 0.0 && d->own_width > 0.0))
        return fw_fail(err, FW_EINPUT, "own ship %g x %g m: length and width must be positive",
                       d->own_length, d->own_width);
    if (!d->own_id || !d->own_id[0] || strlen(d->own_id) >= 64)
        return fw_fail(err, FW_EINPUT, "own ship id must have 1..63 characters");
    if (d->mode.kind != FW_TRAFFIC_REMOTE) {
        const char *files[3] = {d->net_file, d->route_file, d->add_file};
        const char *what[3] = {"network", "route", "additional"};
        if (!d->net_file)
            return fw_fail(err, FW_EINPUT, "no network file given");
        for (int i = 0; i < 3; i++) {
            /* SUMO takes comma-separated lists: each file checked */
            for (const char *p = files[i]; p && *p;) {
                size_t n = strcspn(p, ",");
                char one[1200];
                if (n >= sizeof one)
                    return fw_fail(err, FW_EINPUT, "%s file name too long: %.60s...", what[i], p);
                memcpy(one, p, n);
                one[n] = '\0';
                if (access(one, R_OK) != 0)
                    return fw_fail(err, FW_EINPUT, "%s file '%s' cannot be read", what[i], one);
                p += n + (p[n] == ',');
            }
        }
    }
    return FW_OK;
}

static void own_sigpipe(void)
{
    /* A sumo that dies leaves a closed socket: writing to it must give an error
     * from libtraci, not kill fairway with SIGPIPE. */
    struct sigaction sa;
    if (sigaction(SIGPIPE, NULL, &sa) == 0 && sa.sa_handler == SIG_DFL) {
        sa.sa_handler = SIG_IGN;
        sigaction(SIGPIPE, &sa, NULL);
    }
}

/* Puts context in front of the back end's message. */
static fw_status prefix(fw_error *err, const char *fmt, const char *a, int b)
{
    if (!err)
        return FW_ERUN;
    char head[400], msg[sizeof err->msg];
    snprintf(head, sizeof head, fmt, a, b);
    snprintf(msg, sizeof msg, "%s", err->msg);
    return fw_fail(err, FW_ERUN, "%s: %s", head, msg);
}

/* libtraci's own retries print "Retrying in 1 second" on stdout, into the
 * run's table: fairway retries itself, quietly, every 0.1 s until the
 * connect timeout, and gives up at once when the sumo-gui started here has
 * exited (a bad settings file, no display). */
static fw_status connect_quietly(fw_traffic *t, const char *host, int port, bool *broken,
                                 fw_error *err)
{
    *broken = false;
    const fw_traffic_mode *m = &t->def.mode;
    double deadline = fw_clock_s() + (m->timeout > 0.0 ? m->timeout : t->def.connect_timeout);
    for (;;) {
        /* libtraci talks to the peer through the checking relay only
         * (traci_guard.h): no byte from the wire can crash or hang fairway */
        fw_traci_guard_def gd = {.host = host, .port = port,
                                 .connect_timeout = fmax(0.1, deadline - fw_clock_s()),
                                 .reply_timeout = m->kind == FW_TRAFFIC_GUI ? 0.0
                                                  : m->timeout > 0.0     ? m->timeout
                                                                         : t->def.reply_timeout};
        int local;
        fw_status st = fw_traci_guard_start(&gd, &t->guard, &local, err);
        if (!st) {
            st = t->be->connect("127.0.0.1", local, 0, err);
            if (!st)
                return FW_OK;
            *broken = fw_traci_guard_reason(t->guard)[0] != '\0';
            if (*broken) /* a peer that answered wrongly: no retry mends it */
                st = fw_fail(err, FW_ERUN, "%s", fw_traci_guard_reason(t->guard));
            t->be->close();
            fw_traci_guard_stop(t->guard);
            t->guard = NULL;
            if (*broken || fw_clock_s() >= deadline)
                return st;
        }
        int status;
        if (t->child > 0 && waitpid(t->child, &status, WNOHANG) == t->child) {
            t->child = 0;
            return fw_fail(err, FW_ERUN, "it exited (%s %d) before accepting a connection",
                           WIFEXITED(status) ? "exit code" : "signal",
                           WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status));
        }
        if (fw_clock_s() >= deadline)
            return st;
        nanosleep(&(struct timespec){.tv_nsec = 100000000L}, NULL);
    }
}

/* The view settings sumo-gui is given: --gui-settings or fairway's. */
static fw_status view_file(const fw_traffic_def *d, char *buf, size_t n, fw_error *err)
{
    if (d->mode.kind == FW_TRAFFIC_GUI && d->mode.gui.settings)
        return fw_path(buf, n, err, "%s", d->mode.gui.settings);
    return fw_path(buf, n, err, "%s/networks/fairway.view.xml", fw_data_root());
}

/* A sumo-gui with the run's files and the watching settings (traffic.h
 * fw_traffic_gui), its own messages to LOG.gui beside SUMO's log. */
static fw_status start_gui(fw_traffic *t, fw_error *err)
{
    const fw_traffic_def *d = &t->def;
    const fw_traffic_gui *g = &d->mode.gui;
    const char *argv[64];
    char buf[128], num[3][64], settings[1100], out[1100];
    int port;
    fw_status st;
    if ((st = fw_traffic_gui_check("--sumo", err)) || (st = fw_traffic_free_port(&port, err)) ||
        (st = fw_traffic_sumo_args(d, d->sumo_gui, port, argv, 48, buf, sizeof buf, err)))
        return st;
    if ((st = view_file(d, settings, sizeof settings, err)) ||
        (st = fw_path(out, sizeof out, err, "%s.gui", d->log_file ? d->log_file : "/dev/null")))
        return st;
    if (access(settings, R_OK) != 0)
        return fw_fail(err, FW_EINPUT, "--gui-settings %s: cannot be read", settings);
    snprintf(num[0], sizeof num[0], "%.17g", g->delay_ms > 0.0 ? g->delay_ms : 0.0);
    snprintf(num[1], sizeof num[1], "%d,%d", g->width > 0 ? g->width : 1280,
             g->height > 0 ? g->height : 800);
    int n = 0;
    while (argv[n])
        n++;
    const char *extra[] = {"--start", "true", /* run without waiting for the play button */
                           "--delay", num[0], "--window-size", num[1], "--gui-settings-file",
                           settings, "--quit-on-end", g->keep ? "false" : "true", NULL};
    for (int k = 0; extra[k]; k++)
        argv[n++] = extra[k];
    argv[n] = NULL;
    fw_spawn_def sp = {.argv = argv, .log = d->log_file ? out : NULL};
    if ((st = fw_spawn(&sp, &t->child, err)))
        return st;
    bool broken;
    if ((st = connect_quietly(t, "localhost", port, &broken, err)))
        return prefix(err, broken ? "%s on port %d answered wrongly"
                                  : "%s did not accept a connection on port %d",
                      d->sumo_gui, port);
    return FW_OK;
}

static fw_status start(fw_traffic *t, fw_error *err)
{
    const fw_traffic_def *d = &t->def;
    const char *argv[48];
    char buf[128], view[1100];
    /* written first, whatever happens next: what the run asked SUMO for */
    fw_status st = view_file(d, view, sizeof view, err);
    if (st || (st = fw_traffic_write_config(d, access(view, R_OK) == 0 ? view : NULL, err)))
        return st;
    switch (d->mode.kind) {
    case FW_TRAFFIC_EMBEDDED:
        if (embedded_open)
            return fw_fail(err, FW_ERUN, "an embedded SUMO is already running in this process");
        if ((st = fw_sumo_backend_load(false, &t->be, err)) ||
            (st = fw_traffic_sumo_args(d, "sumo", 0, argv, 48, buf, sizeof buf, err)))
            return st;
        /* libsumo only says "Process Error"; SUMO's reasons are in its log,
         * which it flushes when the process ends */
        if ((st = t->be->start(argv, err)))
            return fw_fail(err, FW_ERUN, "SUMO cannot load '%s' (reasons in %s)", d->net_file,
                           d->log_file ? d->log_file : "no log: set a log file");
        embedded_open = true;
        return FW_OK;
    case FW_TRAFFIC_REMOTE:
        own_sigpipe();
        if ((st = fw_sumo_backend_load(true, &t->be, err)))
            return st;
        /* what the sumo there must run, written first: the way out of the
         * errors below */
        if ((st = fw_traffic_write_remote_command(d, err)))
            return st;
        bool broken;
        if ((st = connect_quietly(t, d->mode.host, d->mode.port, &broken, err)))
            return prefix(err, broken ? "the peer at %s:%d is not a SUMO fairway can use"
                                      : "no SUMO at %s:%d (start it with the run's "
                                        "sumo/remote-command.txt)",
                          d->mode.host, d->mode.port);
        char where[300];
        snprintf(where, sizeof where, "%s:%d", d->mode.host, d->mode.port);
        return fw_traffic_net_check(t->be, d->net_file, where, err);
    case FW_TRAFFIC_GUI:
        own_sigpipe();
        if ((st = fw_sumo_backend_load(true, &t->be, err)))
            return st;
        return start_gui(t, err);
    }
    return fw_fail(err, FW_EINPUT, "unknown SUMO mode");
}

/* The screenshot of a sumo-gui run, taken at one more step (sumo-gui draws
 * it then, in its own thread): waited for up to 5 s, so that the window is
 * not closed before the file is there.  No error channel at the end of a
 * run: a failure is a warning. */
static void gui_screenshot(fw_traffic *t)
{
    fw_error err = {0};
    double tm;
    remove(t->screenshot);
    /* the view as shown (-1: its own size, the window less its bars): another
     * size would be the same view stretched */
    if (t->be->gui_screenshot(t->screenshot, -1, -1, &err) ||
        t->be->step(&tm, &err)) {
        fprintf(stderr, "fairway: warning: --gui-screenshot %s: %s\n", t->screenshot, err.msg);
        return;
    }
    struct stat sb;
    double until = fw_clock_s() + 5.0;
    while (!(stat(t->screenshot, &sb) == 0 && sb.st_size > 0) && fw_clock_s() < until)
        nanosleep(&(struct timespec){.tv_nsec = 50000000L}, NULL);
    nanosleep(&(struct timespec){.tv_nsec = 200000000L}, NULL); /* the file is being written */
    if (stat(t->screenshot, &sb) != 0 || sb.st_size == 0)
        fprintf(stderr, "fairway: warning: --gui-screenshot %s: sumo-gui wrote no file\n",
                t->screenshot);
}

void fw_traffic_close(fw_traffic *t)
{
    if (!t)
        return;
    if (t->be && t->child > 0 && t->screenshot[0] && !t->dead)
        gui_screenshot(t);
    if (t->be) {
        t->be->close();
        if (t->def.mode.kind == FW_TRAFFIC_EMBEDDED)
            embedded_open = false;
    }
    fw_traci_guard_stop(t->guard);
    if (t->child > 0 && t->def.mode.gui.keep && !t->dead) {
        fprintf(stderr, "fairway: the sumo-gui window stays open: close it to go on\n");
        fw_spawn_wait(t->child);
    } else if (t->child > 0) {
        fw_spawn_stop(t->child);
    }
    fw_error ferr = {0};
    if (fw_fcd_close(t->fcd, !t->dead, &ferr))
        fprintf(stderr, "fairway: warning: %s\n", ferr.msg);
    fw_free_each(5, t->raw.v, t->ctx.v, t->ships, t->area, t->near);
    fw_idmap_free(&t->ids);
    for (int i = 0; i < t->last_cap; i++)
        fw_hull_track_free(&t->tracks[i]);
    fw_free_each(18, t->conv, t->last_e, t->last_n, t->last_step, t->last_angle, t->last_sin,
                 t->last_cos, t->tracks, t->seed_heading, t->last_bx, t->last_by, t->off_x,
                 t->off_y, t->dir_x, t->dir_y, t->turned, t->last_k, t);
}

fw_status fw_traffic_load(fw_traffic_kind kind, fw_error *err)
{
    const fw_sumo_backend *be;
    return fw_sumo_backend_load(kind != FW_TRAFFIC_EMBEDDED, &be, err);
}

fw_status fw_traffic_open(const fw_traffic_def *def, fw_traffic **out, fw_error *err)
{
    *out = NULL;
    fw_status st = check_def(def, err);
    if (st)
        return st;
    setenv("SUMO_HOME", FW_SUMO_HOME, 0); /* SUMO looks up its XML schemata there */
    fw_traffic *t = calloc(1, sizeof *t);
    if (!t)
        return fw_fail(err, FW_ERUN, "out of memory");
    t->def = *def;
    snprintf(t->own_id, sizeof t->own_id, "%s", def->own_id);
    t->def.own_id = t->own_id;
    if (def->log_file) {
        if ((st = fw_path(t->log_file, sizeof t->log_file, err, "%s", def->log_file))) {
            fw_traffic_close(t);
            return st;
        }
        t->def.log_file = t->log_file;
    }
    if (def->mode.kind == FW_TRAFFIC_GUI && def->mode.gui.screenshot &&
        (st = fw_path(t->screenshot, sizeof t->screenshot, err, "%s", def->mode.gui.screenshot))) {
        fw_traffic_close(t);
        return st;
    }
    if (def->fcd_file) {
        t->fcd_every = def->fcd_period > def->step ? lround(def->fcd_period / def->step) : 1;
        if ((st = fw_fcd_open(def->fcd_file, &t->fcd, err))) {
            fw_traffic_close(t);
            return st;
        }
    }
    /* only the start uses the file names; they are not kept */
    if ((st = start(t, err))) {
        fw_traffic_close(t);
        return st;
    }
    double dt = t->be->step_length();
    if (fabs(dt - def->step) > 1e-9) {
        fw_traffic_close(t);
        return fw_fail(err, FW_EINPUT, "SUMO's step length is %g s, the controller's %g s",
                       dt, def->step);
    }
    /* one range query serves all the queries */
    t->query_radius = def->radius;
    if (def->area_radius > 0.0)
        t->query_radius = fmax(def->radius, def->area_radius + FW_TRAFFIC_HALF_LENGTH_MAX);
    if (def->near_radius > 0.0)
        t->query_radius = fmax(t->query_radius, def->near_radius + FW_TRAFFIC_HALF_LENGTH_MAX);
    t->ctx_step = -1;
    t->near_step = -1;
    if ((st = t->be->add_own(t->own_id, def->own_length, def->own_width, def->own_edge,
                             t->query_radius, err))) {
        fw_traffic_close(t);
        return st;
    }
    *out = t;
    return FW_OK;
}

fw_status fw_traffic_alive(const fw_traffic *t, fw_error *err)
{
    if (t->dead)
        return fw_fail(err, FW_ERUN, "SUMO is no longer usable after an earlier error");
    return FW_OK;
}

fw_status fw_traffic_place(fw_traffic *t, double x, double y, double heading, double speed,
                           fw_error *err)
{
    /* SUMO derives the own ship's speed from the distance moved; the given
     * speed is kept for fw_traffic_area only */
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    if (!isfinite(x) || !isfinite(y) || !isfinite(heading))
        return fw_fail(err, FW_ERUN, "own ship state is not finite (%g, %g, %g)", x, y, heading);
    double fx, fy, a;
    fw_traffic_to_sumo(x, y, heading, t->def.own_length, &fx, &fy, &a);
    fw_status st = t->be->place(t->own_id, fx, fy, a, x, y, err);
    if (st) {
        t->dead = true;
    } else {
        t->placed = true;
        t->own_x = x;
        t->own_y = y;
        t->own_heading = fw_wrap_2pi(heading);
        t->own_speed = speed;
    }
    return st;
}

fw_status fw_traffic_set_speed(fw_traffic *t, const char *id, double speed, fw_error *err)
{
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    if (strcmp(id, t->own_id) == 0)
        return fw_fail(err, FW_ERUN, "the own ship's speed is fairway's, not SUMO's");
    /* a refusal (a ship that has just left) leaves SUMO usable */
    return t->be->set_speed(id, isfinite(speed) ? speed : -1.0, err);
}

fw_status fw_traffic_add_placed(fw_traffic *t, const char *id, double length, double width,
                                fw_error *err)
{
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    if (strcmp(id, t->own_id) == 0 || !(length > 0) || !(width > 0))
        return fw_fail(err, FW_ERUN, "ship '%s': not the own ship's id, a size > 0", id);
    return t->be->add_placed(id, length, width, err);
}

fw_status fw_traffic_move(fw_traffic *t, const char *id, double x, double y, double heading,
                          double length, fw_error *err)
{
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    double fx, fy, a;
    fw_traffic_to_sumo(x, y, heading, length, &fx, &fy, &a);
    /* the range query stays about the own ship */
    return t->be->place(id, fx, fy, a, t->own_x, t->own_y, err);
}

fw_status fw_traffic_take(fw_traffic *t, const char *id, fw_error *err)
{
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    if (strcmp(id, t->own_id) == 0)
        return fw_fail(err, FW_EINPUT, "the own ship is fairway's already");
    return t->be->take(id, err);
}

fw_status fw_traffic_lane(fw_traffic *t, const char *id, double *xy, int max, int *n,
                          double *right, double *left, bool *traffic_lane, bool *changing,
                          fw_error *err)
{
    *n = 0;
    *traffic_lane = *changing = false;
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    if (strcmp(id, t->own_id) == 0)
        return fw_fail(err, FW_EINPUT, "the own ship has no lane");
    return t->be->lane(id, xy, max, n, right, left, traffic_lane, changing, err);
}

fw_status fw_traffic_give_back(fw_traffic *t, const char *id, double x, double y, double heading,
                               double speed, double length, double max_off, fw_error *err)
{
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    double fx, fy, a, off;
    fw_traffic_to_sumo(x, y, heading, length, &fx, &fy, &a);
    fw_status st = t->be->rejoin(id, fx, fy, a, speed, max_off, &off, err);
    /* its last position (SUMO's stale one while fairway had it) is no base
     * for the direction of its motion in the first step back */
    int i = fw_idmap_find(&t->ids, id);
    if (!st && i >= 0 && i < t->last_cap) {
        t->last_step[i] = -2;
        t->seed_heading[i] = heading; /* its hull as fairway left it, not turned to the lane */
    }
    return st;
}

fw_status fw_traffic_remove(fw_traffic *t, const char *id, fw_error *err)
{
    if (fw_traffic_alive(t, err) || fw_traffic_context(t, err))
        return FW_ERUN;
    if (strcmp(id, t->own_id) == 0)
        return fw_fail(err, FW_ERUN, "the own ship cannot be removed");
    fw_status st = t->be->remove(id, err);
    if (st)
        return st;
    /* out of this step's lists at once */
    for (int k = 0; k < t->ctx.n; k++)
        if (strcmp(t->ctx.v[k].id, id) == 0) {
            t->ctx.v[k] = t->ctx.v[t->ctx.n - 1];
            t->conv[k] = t->conv[t->ctx.n - 1];
            t->ctx.n--;
            break;
        }
    return FW_OK;
}

fw_status fw_traffic_pending(fw_traffic *t, char **ids, fw_error *err)
{
    *ids = NULL;
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    return t->be->pending(ids, err);
}

fw_status fw_traffic_step(fw_traffic *t, fw_error *err)
{
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    if (!t->placed)
        return fw_fail(err, FW_ERUN, "own ship not placed before the first step");
    fw_status st = t->be->step(&t->time, err);
    if (st && t->guard && fw_traci_guard_reason(t->guard)[0])
        st = fw_fail(err, FW_ERUN, "SUMO at %s:%d: %s", t->def.mode.host, t->def.mode.port,
                     fw_traci_guard_reason(t->guard));
    if (st)
        t->dead = true;
    else
        t->steps++;
    if (!st && t->fcd && (t->steps - 1) % t->fcd_every == 0 &&
        !(st = t->be->all(&t->raw, err)))
        /* SUMO labels a timestep with the time its step began */
        st = fw_fcd_step(t->fcd, t->time - t->def.step, t->raw.v, t->raw.n, err);
    /* sumo-gui: the own ship is in the simulation from the first step on */
    if (!st && t->child > 0) {
        double w = t->def.mode.gui.view_m > 0.0 ? t->def.mode.gui.view_m : fw_nm_to_m(3.0);
        st = t->be->gui_follow(t->own_id, t->own_x, t->own_y, w, !t->zoomed, err);
        t->zoomed = true;
    }
    return st;
}

double fw_traffic_time(const fw_traffic *t) { return t->time; }
