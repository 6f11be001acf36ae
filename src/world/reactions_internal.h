/* reactions_internal.h - the reactive traffic's state, shared by reactions.c
 * (speed orders) and reactions_course.c (course alterations).  Internal to
 * src/world. */
#ifndef FW_WORLD_REACTIONS_INTERNAL_H
#define FW_WORLD_REACTIONS_INTERNAL_H

#include "core/idmap.h"
#include "world/reactions.h"

/* What a ship is doing, by its interned id. */
typedef struct react_state {
    bool seen;
    bool holding;    /* told to hold `hold` m/s */
    double v0;       /* m/s, its own speed: the fastest seen while not told */
    double hold;     /* m/s */
    char other[FW_TARGET_ID_MAX]; /* the ship it last gave way to */
    bool rule17;     /* holding as a stand-on ship's last action (rule 17(b)) */
    double t_next;   /* s, when it looks round again (every interval s) */
    /* its course when last seen with that course's sine and cosine, reused
     * while the course stays; trig_ok false: none yet */
    double course, sin_c, cos_c;
    bool trig_ok;
    /* sensing (reactions_sense.c): its AIS as the others hear it, its radar */
    fw_ais_tx ais;
    fw_sensor *radar;
} react_state;

struct fw_reactions {
    fw_reactions_def def;
    fw_idmap ids;
    react_state *s;
    int cap;
    fw_reaction *log;
    int nlog, logcap;
    int *list;       /* scratch: the ships one ship gives way to */
    int list_cap;
    int *nb;         /* scratch: the ships within range of the one deciding */
    fw_target *all_buf; /* scratch: the ships and the own ship (list_cap of them) */
    int *idx;        /* scratch: this step's ships' states (indices into s) */
    int nnb;
    /* this step's ships (the own ship last) and the sines and cosines of
     * their courses, computed once: the pair loops' trigonometry */
    const fw_target *all;
    double *sn, *cs;
    double cos_parallel;
    fw_watch *watch;
    fw_take_order *takes; /* this step's ships to take and steer (course alterations) */
    int ntakes, takes_cap;
    /* sensing (reactions_sense.c; NULL truth: perfect): the list's truth,
     * how each entry of the list is known, the entries one ship's look
     * changed (put back after it), the radar's scratch */
    fw_rng_getter rng;
    void *rng_ctx;
    fw_target *truth;
    fw_known *how;
    int *undo_j;
    fw_target *undo_t;
    fw_known *undo_how;
    int n_undo;
    int *radar_in;
    fw_target *radar_truth, *radar_known;
    int sense_cap;
    fw_sensing_counts ais_counts;
    /* the background ships' lanes (classification: fw_react_classify), the
     * step's source and time, and the first failure reading them */
    struct react_lanes {
        fw_lane_cache cache;
        fw_source *src;
        double t;
        fw_error err;
    } *lanes;
};

/* fw_classify from a's side (its own state me), with both ships' lanes
 * where they are known: two background ships meeting along one waterway are
 * head-on (encounter.h fw_classify_lanes). */
fw_situation fw_react_classify(const fw_reactions *r, const fw_own_state *me,
                               const fw_target *a, const fw_target *b);

/* Judgement (reactions_judge.c, each explained there): the closest approach
 * of a at speed va and b as it goes; does a, at va or at the speed it holds
 * vh (< 0: none), give way to b; how many of the ships near self it gives way
 * to (the nearest in time, its situation and DCPA), and which (into list);
 * the nearest in time of list; does self pass every ship near it at cpa or
 * more at speed v; the speed that gives way to list. */
void fw_react_cpa_at(const fw_reactions *r, const fw_target *a, double va, const fw_target *b,
                     double *tcpa, double *dcpa);
bool fw_react_is_threat(const fw_reactions *r, const fw_target *a, double va, double vh,
                        const fw_target *b, double cpa, const char *keep, fw_situation *sit,
                        double *tcpa, double *dcpa);
int fw_react_threats(const fw_reactions *r, int self, const fw_target *all, double va,
                     double vh, double cpa, const char *keep, int *nearest, fw_situation *sit,
                     double *dcpa);
int fw_react_threat_list(const fw_reactions *r, int self, const fw_target *all, double v0,
                         double vh, const char *keep, int *list);
void fw_react_nearest_of(const fw_reactions *r, int self, const fw_target *all, const int *list,
                         int m, double v0, int *nearest, fw_situation *sit, double *dcpa);
bool fw_react_clears_at(const fw_reactions *r, int self, const fw_target *all, double v,
                        double *dcpa);
double fw_react_yielding_speed(const fw_reactions *r, int self, const fw_target *all,
                               const int *list, int m, double v0, double vh, bool *enough,
                               double *dcpa_after);

/* The closest a, at speed v, would pass any ship near it (r->nb) other than
 * skip (-1: none) within the horizon, stopping at the first below floor. */
double fw_react_min_pass(const fw_reactions *r, int self, const fw_target *all, double v,
                         int skip, double floor);
fw_status fw_react_record(fw_reactions *r, const fw_reaction *x, fw_error *err);

/* Ship self (of all, its state st) gives way to the m ships of list, the
 * nearest in time all[nearest] (situation sit, closest approach dcpa), by
 * altering course, if it can (reactions.h): 1 when
 * ordered (taken: r->takes), 0 when it cannot (no alteration clears, no sea
 * room, no lane: *why says which), -1 with *err set on a failure. */
int fw_react_alter(fw_reactions *r, double t, int self, const fw_target *all, react_state *st,
                   const int *list, int m, int nearest, fw_situation sit, double dcpa,
                   fw_source *src, fw_speed_why *why, fw_error *err);

/* Overtaking a ship fairway steers (reactions_course.c): a (of r->all, at
 * speed va) overtaking b, a ship taken to steer, that leaves a's way (on the
 * course it turns to it passes at half cpa or more, not closing a's track
 * sideways): a need not act; with v, and a overtaking b by the encounter's
 * classification too (a ship held for b is given its speed back); b on
 * a's port side: a alters course to starboard to pass it rather than
 * slowing behind it. */
bool fw_react_leaves_way(const fw_reactions *r, const fw_target *a, double va,
                         const fw_target *b);
bool fw_react_overtakes_clear(const fw_reactions *r, const fw_target *a, double v,
                              const fw_target *b);
bool fw_react_passes_to_starboard(const fw_reactions *r, const fw_target *a,
                                  const fw_target *b);

/* Sensing (reactions_sense.c): is it not perfect; room for m ships; every
 * ship's AIS stepped and all[i] made what its reports say of it (the truth
 * kept in r->truth, how[i] AIS or not known); ship self's look begins
 * (itself the truth, a ship without a report seen in sight, tracked by its
 * radar out of sight) and ends (the list as before); what the record x says
 * of entry j (known and true position). */
bool fw_react_sensing(const fw_reactions *r);
fw_status fw_react_sense_reserve(fw_reactions *r, int m, fw_error *err);
fw_status fw_react_sense_step(fw_reactions *r, double t, fw_target *all, const int *idx, int m,
                              fw_error *err);
fw_status fw_react_sense_begin(fw_reactions *r, double t, int self, int m, react_state *st,
                               fw_error *err);
void fw_react_sense_end(fw_reactions *r);
void fw_react_sense_note(const fw_reactions *r, int j, fw_reaction *x);
void fw_react_sense_free(fw_reactions *r);

#endif
