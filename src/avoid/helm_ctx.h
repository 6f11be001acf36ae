/* helm_ctx.h - the helm search's context and its candidate tracks (internal
 * to src/avoid: helm_search.c and candidates.c).
 *
 * A candidate (side, helm) is a slot: started when a check first looks at it,
 * predicted (or mirrored) only as far as a check has looked along it, boxed
 * chunk by chunk.  candidates.c has the slots, the scans along them and the
 * fallback when no helm clears; helm_search.c the decision around them.
 */
#ifndef FW_HELM_CTX_H
#define FW_HELM_CTX_H

#include "avoid/clearance.h"
#include "avoid/helm_search.h"

struct fw_helm_ctx {
    const fw_ship *ship;
    fw_helm_def def;
    fw_own_state own;
    bool symmetric;  /* start on a straight course with the rudder amidships */
    fw_helm_band band; /* fw_helm_set_band */
    int nh;
    fw_track *tracks; /* [side 0 = starboard, 1 = port][nh], then keep, then spare */
    /* The candidate and keep slots, each predicted only as far as a check
     * has looked along it (most candidates fail within minutes): */
    bool *have;            /* candidate started this decision */
    bool have_keep;
    bool opened;           /* some candidate started since fw_helm_begin */
    fw_track_gen *gen;     /* per slot: the predictor's state */
    fw_track_origin origin[2]; /* what every track of this decision starts from */
    int *ready;            /* samples there */
    int *nbox;             /* chunks with their box */
    int *src;              /* mirrored from this slot; -1: predicted */
    int *fail;             /* chunk where the clearing check found a target inside */
    double *ub2;           /* a value of lambda^2 met along the candidate: >= its minimum */
    int *lim;              /* the target ub2 was met for (the lowest index of those that meet it) */
    int *next, *nextp;     /* the fallback's next chunk to scan, and target in its list */
    int *ord;              /* [3][2 nh] the fallback's order of the candidates, its heap,
                              and each slot's place in the order */
    fw_chunk_boxes *boxes; /* per track slot */
    int nchunks;           /* chunks of a track */
    int computed;
    long samples;          /* predicted (not mirrored) this decision */
    double umax;           /* m/s, no candidate goes faster; < 0: no bound known */
    /* per-decision scratch over the targets (grown on demand): the order in
     * which targets are checked (threats first), each one's reach window
     * (clearance.h) and per chunk the targets whose window holds it */
    int cap;
    int *idx;
    int *jlo, *jhi;
    int *act, *nact;       /* act[j cap + p], p < nact[j] */
    fw_prep_target *prep;
    fw_prep_memo *memo;    /* per target slot, kept from decision to decision */
    const fw_target *prep_t; /* prep holds these n targets (this decision's search) */
    int prep_n;
    double *paths;         /* the predicted targets' paths (clearance.h) */
    size_t paths_cap;      /* doubles */
    double *pbox;          /* [cap][fw_prep_box_len] the targets' grown chunk boxes */
};

/* Starts candidate (side, i) if this decision has not; *slot gets its slot. */
fw_status fw_cand_open(fw_helm_ctx *c, int side, int i, int *slot, fw_error *err);
/* Samples and boxes of a slot through chunk j. */
void fw_cand_chunk(fw_helm_ctx *c, int slot, int j);
/* Does some target come inside lambda^2 < stop2 along slot (see candidates.c)? */
double fw_cand_fails(fw_helm_ctx *c, int slot, double stop2);
/* No helm clears: the reference search's pick (slot's helm index, side 0/1)
 * among the candidates that keep within the band; *pick -1: none does. */
fw_status fw_cand_best_available(fw_helm_ctx *c, int allowed, int *pick, int *side,
                                 fw_error *err);
/* Does candidate slot leave the band (predicted to its end to know)? */
bool fw_cand_leaves_band(fw_helm_ctx *c, int slot);

#endif
