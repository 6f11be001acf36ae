/* sumofiles.c - the files with which a sumo outside fairway runs what a run
 * ran (backend.h): the command line a remote sumo needs, and the run's
 * .sumocfg for sumo-gui. */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/files.h"
#include "traffic/backend.h"
#include "traffic/fcd.h"

/* The run's sumo/ directory: the log file's. */
static void sumo_dir(const fw_traffic_def *d, char *dir, size_t n)
{
    const char *slash = strrchr(d->log_file, '/');
    snprintf(dir, n, "%.*s", slash ? (int)(slash - d->log_file) : 1,
             slash ? d->log_file : ".");
}

/* Options whose values are files (comma-joined lists for some). */
static bool is_file_option(const char *opt)
{
    static const char *const files[] = {"--net-file", "--route-files", "--additional-files",
                                        "--gui-settings-file", "--log", "--error-log", NULL};
    for (int i = 0; files[i]; i++)
        if (strcmp(opt, files[i]) == 0)
            return true;
    return false;
}

/* arg through put(c, f) one character at a time; when it names files
 * (paths), those under dir made relative to dir and the other relative ones
 * absolute: the file is read from dir, and the run's directory has its final
 * name only once the run is over. */
static void put_relative(FILE *f, const char *arg, bool paths, const char *dir,
                         void (*put)(int, FILE *))
{
    size_t dl = strlen(dir);
    char cwd[1024];
    if (!getcwd(cwd, sizeof cwd))
        cwd[0] = '\0';
    for (const char *p = arg; *p;) {
        size_t k = paths ? strcspn(p, ",") : strlen(p); /* route files are comma-joined */
        if (paths && strncmp(p, dir, dl) == 0 && p[dl] == '/' && dl < k)
            p += dl + 1, k -= dl + 1;
        else if (paths && p[0] != '/' && cwd[0]) {
            for (const char *c = cwd; *c; c++)
                put(*c, f);
            put('/', f);
        }
        for (size_t i = 0; i < k; i++)
            put(p[i], f);
        p += k;
        if (*p == ',')
            put(*p++, f);
    }
}

static void put_sh(int c, FILE *f) { c == '\'' ? fputs("'\\''", f) : fputc(c, f); }

fw_status fw_traffic_write_remote_command(const fw_traffic_def *d, fw_error *err)
{
    if (!d->log_file)
        return FW_OK;
    char dir[1024], path[1100], tmp[1110], buf[128];
    sumo_dir(d, dir, sizeof dir);
    const char *argv[48];
    fw_status st;
    if ((st = fw_traffic_sumo_args(d, "sumo", d->mode.port, argv, 48, buf, sizeof buf, err)) ||
        (st = fw_path(path, sizeof path, err, "%s/remote-command.txt", dir)))
        return st;
    FILE *f = fw_file_begin(path, tmp, sizeof tmp, err);
    if (!f)
        return err->status;
    fprintf(f, "# The sumo a remote run of this scenario needs (fairway run --sumo "
               "remote:%s:%d): run\n# it on %s in this directory, e.g. sh remote-command.txt, "
               "then start the run.\ncd \"$(dirname \"$0\")\" &&", d->mode.host, d->mode.port,
            d->mode.host);
    fputs(" sumo", f);
    for (int i = 1; argv[i]; i++) {
        fputs(" '", f);
        put_relative(f, argv[i], i > 1 && is_file_option(argv[i - 1]), dir, put_sh);
        fputc('\'', f);
    }
    fputc('\n', f);
    return fw_file_commit(f, tmp, path, err);
}

/* Options of the run's command line that a replay must not repeat: the
 * replay would overwrite the run's log and FCD. */
static bool run_only(const char *opt)
{
    static const char *const skip[] = {"--log", "--error-log", "--fcd-output",
                                       "--device.fcd.period", "--remote-port", NULL};
    for (int i = 0; skip[i]; i++)
        if (strcmp(opt, skip[i]) == 0)
            return true;
    return false;
}

static void put_option(FILE *f, const char *opt, const char *value, const char *dir)
{
    fprintf(f, "    <%s value=\"", opt + 2);
    put_relative(f, value, is_file_option(opt), dir, fw_xml_putc);
    fputs("\"/>\n", f);
}

fw_status fw_traffic_write_config(const fw_traffic_def *d, const char *view, fw_error *err)
{
    if (!d->log_file)
        return FW_OK;
    char dir[1024], path[1100], tmp[1110], buf[128], num[64];
    sumo_dir(d, dir, sizeof dir);
    const char *argv[48];
    fw_status st;
    if ((st = fw_traffic_sumo_args(d, "sumo", 0, argv, 48, buf, sizeof buf, err)) ||
        (st = fw_path(path, sizeof path, err, "%s/run.sumocfg", dir)))
        return st;
    FILE *f = fw_file_begin(path, tmp, sizeof tmp, err);
    if (!f)
        return err->status;
    fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
          "<!-- written by fairway: the SUMO side of this run (network, routes, ship types,\n"
          "     step, seed, lane-change time, to its end).  `sumo-gui -c run.sumocfg` moves the\n"
          "     background ships as the run had them where fairway ordered none of them and took\n"
          "     none out at the start (behaviour: blind, fill 0: exactly; else run.log's traffic:\n"
          "     lines say what differs), without the own ship, which fairway stepped.  The run\n"
          "     itself, every ship where it was: outputs: fcd: true in the scenario, then\n"
          "     python3 analysis/replay_gui.py on the run's directory. -->\n"
          "<configuration>\n", f);
    for (int i = 1; argv[i] && argv[i + 1]; i += 2)
        if (!run_only(argv[i]))
            put_option(f, argv[i], argv[i + 1], dir);
    put_option(f, "--begin", "0", dir);
    if (d->end > 0.0) {
        snprintf(num, sizeof num, "%.17g", d->end);
        put_option(f, "--end", num, dir);
    }
    if (view)
        put_option(f, "--gui-settings-file", view, dir);
    fputs("</configuration>\n", f);
    return fw_file_commit(f, tmp, path, err);
}
