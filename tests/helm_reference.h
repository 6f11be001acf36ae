/* helm_reference.h - the helm search as it stood before the decision was made
 * cheaper (commit f49b4df), kept for tests and benchmarks only.
 *
 * The same algorithm as src/avoid/helm_search.c had then (threats first,
 * a failing target moved to the front, the fallback pruned to the targets that
 * can reach some candidate's domain, branch and bound), written over the
 * public track API and clearance.h: test_decide compares its results with
 * fw_helm_search's bit for bit, bench_helm times the two in the same run.
 */
#ifndef FW_HELM_REFERENCE_H
#define FW_HELM_REFERENCE_H

#include "avoid/helm_search.h"

typedef struct fw_helm_ref fw_helm_ref;

/* For searches with ctx (whose helm definition it reads). */
fw_status fw_helm_ref_create(const fw_helm_def *def, int nh, fw_helm_ref **out, fw_error *err);
void fw_helm_ref_destroy(fw_helm_ref *r);

/* The band its searches keep to (fw_helm_set_band's, checked here
 * independently: a candidate that leaves it neither clears nor falls back;
 * NULL: none). */
void fw_helm_ref_set_band(fw_helm_ref *r, const fw_helm_band *band);

/* fw_helm_search as it was (with the band added): call after
 * fw_helm_begin(ctx, own). */
fw_status fw_helm_search_reference(fw_helm_ref *r, fw_helm_ctx *ctx, const fw_target *t, int n,
                                   int allowed, fw_helm_result *res, fw_error *err);

#endif
