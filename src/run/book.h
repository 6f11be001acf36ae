/* book.h - the encounter book: what a run keeps per target and per step.
 *
 * One fw_encounter (records.h) per ship met, keyed by its id: first sight
 * (situation, DCPA/TCPA), closest approach, domain, hull to hull, collision,
 * the candidate's straight-track miss, the COLREGs audit's observations, the
 * own ship's action for it; and the own ship's heading and speed at each step
 * with a target in sight (the audit reads its manoeuvres from them).  At the
 * end fw_book_judge reads each entry (COLREGs, the audit) and sums the book
 * into the summary.  Computing only: records.c writes the files from it.
 */
#ifndef FW_RUN_BOOK_H
#define FW_RUN_BOOK_H

#include "run/records.h"

typedef struct fw_book fw_book;

fw_status fw_book_create(const fw_scenario *s, fw_book **out, fw_error *err);
/* Safe on NULL. */
void fw_book_destroy(fw_book *b);
/* One target seen at t with its assessment.  FW_ERUN when the book cannot
 * grow: a run never goes on missing a ship. */
fw_status fw_book_target(fw_book *b, double t, const fw_target *ts, const fw_mmg_state *own,
                         const fw_assessment *as, fw_error *err);
/* The own ship acted at t (side, helm) for primary_id; the targets tg[0..n-1]
 * whose assessment says they enter the domain are the ones it acted for. */
void fw_book_action(fw_book *b, double t, int side, double helm, const char *primary_id,
                    const fw_target *tg, const fw_assessment *as, int n);
fw_encounter *fw_book_entries(fw_book *b, int *n);
/* The end: each entry's COLREGs reading and audit; the summary's encounter
 * totals (n_encounters, min_dist and its target, min_hull, domain_entered,
 * collision, colregs_ok). */
void fw_book_judge(fw_book *b, fw_run_summary *sum);

#endif
