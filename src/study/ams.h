/* ams.h - adaptive multilevel splitting: the probability of a rare event within a
 * fixed horizon, from far fewer simulations than counting it would need.
 *
 * The question: how likely is a trajectory's score, a continuous measure of
 * closeness that reaches 1 exactly at the event (study/outcome.h
 * fw_closeness: hull contact), to reach 1 before the horizon?  Crude Monte
 * Carlo needs about (1 - p) / (p RE^2) runs for a relative error RE: 1.1e6
 * runs for p = 1e-5 at 30%.  Splitting keeps N trajectories ("particles")
 * and, again and again, drops the ones whose largest score is the lowest,
 * replacing each by a copy of a better one taken at the moment that one
 * first passed the dropped level, continued with fresh randomness; each
 * round multiplies the estimate by the share that survived.
 *
 * This is the generalised, tie-safe form of Brehier, Lelievre and Rousset
 * (ESAIM:PS 2015, "Analysis of AMS ... unbiasedness", after Cerou and
 * Guyader 2007) for a fixed time horizon (trajectory AMS: Lestang, Ragone,
 * Brehier, Herbert and Bouchet, J. Stat. Mech. 2018):
 *   1. simulate N trajectories to the horizon; S_i their largest scores;
 *   2. z = min S_i; stop when z >= 1 (every particle has the event);
 *      K = #{S_i <= z}; stop with the estimate 0 when K = N (extinction);
 *      p *= 1 - K / N;
 *      each of the K is replaced by a branch of a survivor (S_j > z, drawn
 *      uniformly) taken where that survivor's score first exceeded z;
 *   3. at the end p *= (the share of particles with S_i >= 1).
 * The estimate is unbiased for any N >= 2 (their Theorem 4.1), so batches
 * can be averaged: fw_ams_batches runs B independent ones and gives their
 * mean, with an interval made on their logarithms (ams.c batch_interval:
 * splitting estimates are skewed to the right, and a t interval on them
 * falls short).  In the ideal case its relative variance
 * is about ln(1 / p) / N per batch (shared reference: 11.5 / N at 1e-5).
 *
 * The engine knows only scores.  What a trajectory is, how a branch is made
 * (a snapshot restored, a path replayed) and what it costs belong to the
 * model (fw_ams_model); the engine's own draws (which survivor each dropped
 * particle copies) and the particles' fresh streams come from `seed`, so the
 * same seed gives the same estimate.
 */
#ifndef FW_STUDY_AMS_H
#define FW_STUDY_AMS_H

#include <stdbool.h>
#include <stdint.h>

#include "core/error.h"
#include "core/rng.h"
#include "study/stats.h"

/* One trajectory's simulation, handed back by the model. */
typedef struct fw_ams_sim {
    void *traj;   /* the model's trajectory (the engine only keeps it and hands it back) */
    double score; /* its largest score over [0, horizon] */
    double cost;  /* what was simulated for it, in whole trajectories (a branch at
                     half the horizon: 0.5) */
} fw_ams_sim;

typedef struct fw_ams_model {
    void *ctx;
    /* A trajectory from the start to the horizon, its randomness from rng. */
    fw_status (*start)(void *ctx, fw_rng rng, fw_ams_sim *out, fw_error *err);
    /* A trajectory that is `parent` up to the first moment parent's score
     * exceeded `level`, continued from there with randomness from rng. */
    fw_status (*branch)(void *ctx, const void *parent, double level, fw_rng rng, fw_ams_sim *out,
                        fw_error *err);
    void (*drop)(void *ctx, void *traj);
    /* Optional: the particles as they are at the end of a run (before they
     * are dropped), to keep what the model wants of them (the closest). */
    void (*final)(void *ctx, const fw_ams_sim *particles, int n);
} fw_ams_model;

/* Lower levels whose probabilities one estimate gives as well (a near
 * miss's closeness below the collision's 1): at most this many. */
#define FW_AMS_MAX_LEVELS 4

typedef struct fw_ams_def {
    int particles;   /* N >= 2 */
    /* levels in (0, 1) whose P(score >= level) the estimate also gives, in
     * increasing order: at the first round whose lowest score reaches one,
     * the product so far (every particle is then at or beyond it), or, when
     * the run ends below it, the product times the share at or beyond it.
     * The same argument as the event's gives each estimate unbiased: the
     * engine run with that level as its event takes the same rounds up to
     * there. */
    int n_levels;
    double levels[FW_AMS_MAX_LEVELS];
    int max_rounds;  /* a bound on the rounds (FW_ERUN beyond it): 0 = 1000 N */
    uint64_t seed;
} fw_ams_def;

fw_ams_def fw_default_ams_def(void); /* 100 particles, seed 1 */
/* FW_EINPUT naming the field ("particles: ...") when the definition cannot run. */
fw_status fw_ams_check(const fw_ams_def *def, fw_error *err);

typedef struct fw_ams_result {
    double p;        /* the estimate */
    int rounds;      /* J */
    int reached;     /* particles with the event at the end */
    double cost;     /* trajectories simulated in all (start and branches) */
    double p_level[FW_AMS_MAX_LEVELS]; /* P(score >= def->levels[i]) */
} fw_ams_result;

/* One splitting estimate. */
fw_status fw_ams_run(const fw_ams_def *def, const fw_ams_model *m, fw_ams_result *out,
                     fw_error *err);

/* `batches` independent estimates (seeds derived from def->seed): their
 * mean with its interval at `level` (est->n = batches), and the cost of all
 * of them (trajectories).  est has room for 1 + def->n_levels: est[0] the
 * event's, est[1 + i] level i's. */
fw_status fw_ams_batches(const fw_ams_def *def, const fw_ams_model *m, int batches, double level,
                         fw_estimate *est, double *cost, fw_error *err);

/* The mean of b independent estimates with its interval at `level`, as
 * fw_ams_batches makes it (Cox's log-normal interval; a t interval cut at 0
 * when an estimate is 0). */
fw_estimate fw_ams_interval(const double *v, int b, double level);

/* The crude Monte Carlo runs needed for relative error re at probability p:
 * (1 - p) / (p re^2). */
double fw_crude_runs(double p, double re);

#endif
