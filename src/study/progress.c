/* progress.c - how far a sweep is: a bar on a terminal, one line per run
 * otherwise (logs and CI keep every line). */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "study/sweep.h"

struct fw_progress {
    FILE *f;
    bool bar;
    bool quiet;
    int todo, total, skipped;
    double t0, last;
};

fw_progress *fw_progress_start(const fw_sweep_def *def, int todo, int total, int skipped)
{
    fw_progress *p = calloc(1, sizeof *p);
    if (!p)
        return NULL;
    p->f = def->progress_out ? def->progress_out : stderr;
    p->quiet = def->progress == FW_PROGRESS_NONE;
    p->bar = def->progress == FW_PROGRESS_BAR ||
             (def->progress == FW_PROGRESS_AUTO && isatty(fileno(p->f)));
    p->todo = todo;
    p->total = total;
    p->skipped = skipped;
    p->t0 = p->last = fw_sweep_now();
    if (!p->quiet)
        fprintf(p->f, "sweep %s: %d runs, %d already in the database, %d to run\n",
                def->study->name, total, skipped, todo);
    return p;
}

static void eta_text(const fw_progress *p, int finished, char *out, size_t outsz)
{
    double el = fw_sweep_now() - p->t0;
    if (finished <= 0) {
        snprintf(out, outsz, "ETA --");
        return;
    }
    double left = el / finished * (p->todo - finished);
    int sec = (int)(left + 0.5);
    if (sec >= 3600)
        snprintf(out, outsz, "ETA %dh%02dm", sec / 3600, sec / 60 % 60);
    else
        snprintf(out, outsz, "ETA %dm%02ds", sec / 60, sec % 60);
}

static void draw_bar(fw_progress *p, int done, int failed, int running)
{
    int finished = done + failed, width = 30;
    int fill = p->todo > 0 ? finished * width / p->todo : width;
    char bar[64];
    for (int i = 0; i < width; i++)
        bar[i] = i < fill ? '#' : '.';
    bar[width] = '\0';
    char eta[32];
    eta_text(p, finished, eta, sizeof eta);
    double el = fw_sweep_now() - p->t0;
    fprintf(p->f, "\r[%s] %d/%d runs", bar, finished, p->todo);
    if (failed)
        fprintf(p->f, ", %d failed", failed);
    if (running >= 0)
        fprintf(p->f, ", %d running", running);
    fprintf(p->f, ", %.1f runs/min, %s  ", el > 0 ? finished * 60.0 / el : 0.0, eta);
    fflush(p->f);
    p->last = fw_sweep_now();
}

void fw_progress_run(fw_progress *p, const fw_study *s, const fw_outcome *o, int done,
                     int failed)
{
    if (!p || p->quiet)
        return;
    if (p->bar) {
        draw_bar(p, done, failed, -1);
        return;
    }
    fw_study_run r = fw_study_run_at(s, o->run_id);
    char eta[32];
    eta_text(p, done + failed, eta, sizeof eta);
    fprintf(p->f, "[%d/%d] run %d (domain %.0f m, density %g, %s, replication %d): %s",
            done + failed, p->todo, o->run_id, r.domain, r.density, fw_behaviour_name(r.behaviour),
            r.replication, o->status);
    if (strcmp(o->status, "ok") == 0)
        fprintf(p->f, ", %d encounters, %.1f s", o->n_enc, o->wall_s);
    else
        fprintf(p->f, ": %s", o->reason);
    fprintf(p->f, ", %s\n", eta);
    fflush(p->f);
}

void fw_progress_tick(fw_progress *p, int done, int failed, int running)
{
    if (p && !p->quiet && p->bar && fw_sweep_now() - p->last >= 1.0)
        draw_bar(p, done, failed, running);
}

void fw_progress_end(fw_progress *p, int done, int failed)
{
    if (!p)
        return;
    if (!p->quiet) {
        if (p->bar)
            draw_bar(p, done, failed, -1), fputc('\n', p->f);
        fprintf(p->f, "sweep: %d runs finished (%d failed) in %.1f s\n", done + failed, failed,
                fw_sweep_now() - p->t0);
    }
    free(p);
}

void fw_progress_count(fw_progress *p, const fw_study *s, const fw_outcome *o,
                       fw_sweep_result *res)
{
    if (strcmp(o->status, "ok") == 0)
        res->done++;
    else
        res->failed++;
    fw_progress_run(p, s, o, res->done, res->failed);
}
