/* audit.h - the COLREGs audit of one own-ship encounter: did the own ship do
 * what rules 8, 13-17 ask of it?
 *
 * The rule and the role come from the situation at first detection (rule 13
 * overtaking and rule 14 head-on: the own ship keeps out of the way / alters;
 * rule 15 crossing: give-way with the target on the starboard side, stand-on
 * with it on the port side; being overtaken: stand-on).  Risk of collision
 * (rule 7) is taken to exist from the first step at which the predicted CPA
 * is nearer than risk_dcpa and reached within risk_tcpa.  The own ship's
 * action is its first avoidance action for the target; how large it was is
 * read from its heading and speed between the action and the closest
 * approach.
 *
 *   give-way (13, 14, 16; rule 8): the action is early (TCPA at the action at
 *     least early_tcpa, or taken within prompt of the risk's first appearing:
 *     a ship first seen at TCPA 5 min cannot have acted at 8) and substantial (a course change of at least
 *     course_change or a speed reduction of at least speed_change, "large
 *     enough to be readily apparent", 8(b)), head-on and crossing to starboard
 *     (14(a); 15: not ahead of the other, which a starboard turn achieves).
 *     No action while the risk lasted to must_tcpa is a breach; a risk that
 *     went away without one needed none.
 *   stand-on (17): phase 1, TCPA above may_tcpa: keep course and speed (17(a)(i));
 *     phase 2, below it: may act (17(a)(ii)); phase 3, below must_tcpa with
 *     the risk still there: must act (17(b)); a crossing stand-on ship does
 *     not turn to port for a ship on her port side (17(c)).
 *
 * The thresholds are study settings (study.h `audit:`); the defaults are
 * stated in fw_default_audit_def and chosen as an open-sea reading of the
 * rules, which give no numbers: 0.5 nm and 20 min for risk, 30 deg or a
 * quarter of the speed for "substantial", 8 min TCPA (or within a minute
 * of the risk appearing) for "early", 10 and
 * 4 min for the rule 17 phases.
 *
 * Where ships pass closer by the nature of the water, the risk distance
 * shrinks with it (fw_audit_def_for, the scenario's traffic.waterway): a
 * passing distance that is normal in a channel is no breach there.
 *   open-sea  0.5 nm: within the sector radii Goodwin and Kemp (1975)
 *             measured in the southern North Sea (0.45 nm astern, 0.7 nm to
 *             port, 0.85 nm to starboard);
 *   tss       1.6 own-ship lengths: the transverse semi-axis of Fujii and
 *             Tanaka's (1971) domain (8 L x 3.2 L) in Japan's congested
 *             coastal waters, where lanes keep ships on parallel courses;
 *   channel   0.8 lengths: their harbour and narrow-water domain (6 L x
 *             1.6 L).  For the 333 m C-3: 533 m and 266 m.
 * Only the distance changes; the rules' times and the size of an action
 * that is readily apparent do not depend on the water.
 */
#ifndef FW_AUDIT_H
#define FW_AUDIT_H

#include <stdbool.h>
#include <stddef.h>

#include "avoid/encounter.h"
#include "core/error.h"

typedef struct fw_audit_def {
    double risk_dcpa;     /* m, 926 (0.5 nm) */
    double risk_tcpa;     /* s, 1200 */
    double course_change; /* rad, 30 deg */
    double speed_change;  /* fraction of the speed at the action, 0.25 */
    double early_tcpa;    /* s, 480 */
    double prompt;        /* s, 60 */
    double may_tcpa;      /* s, 600: rule 17 phase 2 begins */
    double must_tcpa;     /* s, 240: rule 17 phase 3 begins */
} fw_audit_def;

fw_audit_def fw_default_audit_def(void);

typedef enum fw_waterway { FW_WATERWAY_OPEN_SEA, FW_WATERWAY_TSS, FW_WATERWAY_CHANNEL } fw_waterway;
/* "open-sea", "tss", "channel". */
const char *fw_waterway_name(fw_waterway w);
/* 0 and *w set, or -1 for a name that is none of them. */
int fw_waterway_parse(const char *name, fw_waterway *w);
/* The default thresholds for a kind of water and the own ship's length (m). */
fw_audit_def fw_audit_def_for(fw_waterway w, double own_length);
/* FW_EINPUT naming the first setting out of range (message "FIELD: ..."). */
fw_status fw_audit_check(const fw_audit_def *d, char *field, size_t fieldsz, fw_error *err);

/* What the encounter book notes about one target while the run goes on. */
typedef struct fw_audit_obs {
    bool risk;             /* risk of collision seen */
    double t_risk, tcpa_risk;
    bool must_seen;        /* TCPA came down to must_tcpa */
    bool risk_at_must;     /* ... with the risk still there */
    double tcpa_act;       /* s, TCPA when the own ship first acted for it (NAN) */
} fw_audit_obs;

void fw_audit_obs_init(fw_audit_obs *o);
/* One step's assessment of the target (DCPA m, TCPA s). */
void fw_audit_observe(fw_audit_obs *o, const fw_audit_def *d, double t, double dcpa,
                      double tcpa);

/* The own ship's heading (rad, unwrapped or not) and speed (m/s) at times t
 * (ascending): what it did after acting. */
typedef struct fw_audit_history {
    const double *t, *psi, *speed;
    int n;
} fw_audit_history;

typedef enum fw_audit_role { FW_ROLE_GIVE_WAY, FW_ROLE_STAND_ON } fw_audit_role;

typedef struct fw_audit_result {
    int rule;              /* 13, 14 or 15; 19 out of sight (fw_audit_evaluate_rule19) */
    fw_audit_role role;
    bool risk;
    double t_risk, tcpa_risk; /* NAN without risk */
    bool acted;
    double tcpa_act;       /* NAN if it did not act */
    double course_change;  /* rad, largest |heading - heading at the action| up to the CPA */
    double speed_change;   /* largest speed reduction as a fraction of the speed at the action */
    bool early, substantial;
    int phase;             /* rule 17 phase of the action, 1-3; 0: no action or give-way */
    int compliant;         /* 1 yes, 0 no, -1 not audited (no risk of collision) */
    char note[48];         /* why not: "late", "not substantial", "to port", ... */
} fw_audit_result;

/* "give-way", "stand-on" */
const char *fw_audit_role_name(fw_audit_role r);

/* The audit of an encounter: its situation at first detection, what the book
 * noted, the own ship's first action for it (acted, t_act, side FW_SIDE_*),
 * the time of the closest approach and the own ship's history. */
void fw_audit_evaluate(const fw_audit_def *d, fw_situation situation, const fw_audit_obs *o,
                       bool acted, double t_act, int side, double t_cpa,
                       const fw_audit_history *h, fw_audit_result *out);

/* The audit of an encounter met out of sight in restricted visibility (rule
 * 19: rule 19, role give-way, since there is no stand-on ship): it acts in
 * ample time (early, as a give-way ship) and substantially, and side_ok says
 * whether its side was 19(d)'s (the caller's reading: no alteration to port
 * for a ship forward of the beam other than one being overtaken, none
 * towards one abeam or abaft); no action while the risk lasted: a breach. */
void fw_audit_evaluate_rule19(const fw_audit_def *d, const fw_audit_obs *o, bool acted,
                              double t_act, bool side_ok, double t_cpa,
                              const fw_audit_history *h, fw_audit_result *out);

#endif
