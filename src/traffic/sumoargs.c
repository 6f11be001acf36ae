/* sumoargs.c - SUMO's side of a run in words: the --sumo mode strings, the
 * display check for sumo-gui, and the command line fairway gives sumo
 * (traffic.h). */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "traffic/traffic.h"

fw_status fw_traffic_mode_parse(const char *text, fw_traffic_mode *out, fw_error *err)
{
    memset(out, 0, sizeof *out);
    if (!text || strcmp(text, "embedded") == 0) {
        out->kind = FW_TRAFFIC_EMBEDDED;
        return FW_OK;
    }
    if (strcmp(text, "gui") == 0) {
        out->kind = FW_TRAFFIC_GUI;
        return FW_OK;
    }
    if (strncmp(text, "remote:", 7) == 0) {
        const char *host = text + 7;
        const char *colon = strrchr(host, ':');
        size_t hl = colon ? (size_t)(colon - host) : 0;
        if (!colon || hl == 0)
            return fw_fail(err, FW_EINPUT, "--sumo '%s': expected remote:HOST:PORT", text);
        if (hl >= sizeof out->host)
            return fw_fail(err, FW_EINPUT, "--sumo '%s': host name too long", text);
        char *end = NULL;
        long port = strtol(colon + 1, &end, 10);
        if (end == colon + 1 || *end != '\0' || port < 1 || port > 65535)
            return fw_fail(err, FW_EINPUT, "--sumo '%s': port must be 1..65535", text);
        memcpy(out->host, host, hl);
        out->host[hl] = '\0';
        out->port = (int)port;
        out->kind = FW_TRAFFIC_REMOTE;
        const char *t = getenv("FAIRWAY_SUMO_TIMEOUT");
        if (t && t[0]) {
            out->timeout = strtod(t, &end);
            if (end == t || *end || !(out->timeout >= 0.1 && out->timeout <= 86400.0))
                return fw_fail(err, FW_EINPUT,
                               "FAIRWAY_SUMO_TIMEOUT '%.40s': expected seconds, 0.1 to 86400 (how "
                               "long the SUMO at %s may take to connect and to begin each answer)",
                               t, text + 7);
        }
        return FW_OK;
    }
    return fw_fail(err, FW_EINPUT,
                   "--sumo '%s': expected embedded, gui or remote:HOST:PORT", text);
}

fw_status fw_traffic_gui_check(const char *opt, fw_error *err)
{
    const char *display = getenv("DISPLAY");
    if (!display || !display[0])
        return fw_fail(err, FW_EINPUT,
                       "%s gui: no display ($DISPLAY is not set): run under xvfb-run, or use "
                       "--sumo embedded",
                       opt);
    return FW_OK;
}

fw_status fw_sumo_path_check(const char *what, const char *path, fw_error *err)
{
    const char *comma = path ? strchr(path, ',') : NULL;
    if (comma) /* up to the name with the comma: what the user gave, not a temporary below */
        return fw_fail(err, FW_EINPUT, "%s: '%.*s' has a comma: SUMO splits its file options at "
                                       "commas (it would look for two files); use a path "
                                       "without one", what,
                       (int)(comma - path + (ptrdiff_t)strcspn(comma, "/")), path);
    return FW_OK;
}

fw_status fw_traffic_sumo_args(const fw_traffic_def *def, const char *program, int remote_port,
                               const char **argv, int max, char *buf, size_t bufsz,
                               fw_error *err)
{
    int n = 0;
    size_t used = 0;
    bool overflow = false;
#define ARG(s)                                                                              \
    do {                                                                                    \
        if (n + 1 < max) argv[n++] = (s); else overflow = true;                             \
    } while (0)
    /* numbers are printed into buf so argv can point at them */
#define NUM(fmt, v)                                                                         \
    do {                                                                                    \
        int k_ = snprintf(buf + used, bufsz - used, fmt, v);                                \
        if (k_ < 0 || (size_t)k_ >= bufsz - used) { overflow = true; break; }               \
        ARG(buf + used);                                                                    \
        used += (size_t)k_ + 1;                                                             \
    } while (0)
    fw_status st;
    if ((st = fw_sumo_path_check("the network file", def->net_file, err)) ||
        (st = fw_sumo_path_check("the types file", def->add_file, err)) ||
        (st = fw_sumo_path_check("the SUMO log", def->log_file, err)))
        return st;
    ARG(program);
    ARG("--net-file");
    ARG(def->net_file);
    if (def->route_file) {
        ARG("--route-files");
        ARG(def->route_file);
    }
    if (def->add_file) {
        ARG("--additional-files");
        ARG(def->add_file);
    }
    ARG("--step-length");
    NUM("%.17g", def->step);
    ARG("--seed");
    NUM("%lu", def->seed);
    /* Ships are never teleported, and collisions are fairway's to judge: its
     * monitors test the hulls of every pair (survey/monitor.h) and its records the own
     * ship's.  SUMO's own check ("warn" only logs) moves no ship, and on the
     * strait's lanes it cost a third of SUMO's step (0.30 s against 0.18 s of
     * CPU for the base hour, same ship positions to the byte in its FCD), so
     * SUMO is told not to look at all. */
    ARG("--time-to-teleport");
    ARG("-1");
    ARG("--collision.action");
    ARG("none");
    /* lane changes as ship manoeuvres, not jumps (traffic.h) */
    if (def->lane_change_s > 0.0) {
        ARG("--lanechange.duration");
        NUM("%.17g", def->lane_change_s);
    }
    ARG("--no-step-log");
    ARG("true");
    ARG("--duration-log.disable");
    ARG("true");
    /* --log alone leaves load errors on stderr: name the file for errors too */
    ARG("--log");
    ARG(def->log_file ? def->log_file : "/dev/null");
    ARG("--error-log");
    ARG(def->log_file ? def->log_file : "/dev/null");
    if (remote_port > 0) {
        ARG("--remote-port");
        NUM("%d", remote_port);
    }
#undef NUM
#undef ARG
    if (overflow)
        return fw_fail(err, FW_ERUN, "sumo command line too long");
    argv[n] = NULL;
    return FW_OK;
}
