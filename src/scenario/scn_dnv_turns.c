/* scn_dnv_turns.c - the turns a situation's target was seen making (scn_dnv.h). */
#include <math.h>
#include <stdlib.h>

#include "core/units.h"
#include "scenario/scn_dnv.h"

fw_status fw_scn_dnv_read_turns(const fw_jnode *fairway, double appear, fw_scn_turn **out,
                                int *n, fw_error *err)
{
    fw_jnode arr;
    size_t len = 0;
    *n = 0;
    if (out)
        *out = NULL;
    fw_status st = fw_jnode_type(fairway) == FW_J_ABSENT
                       ? FW_OK
                       : fw_jmember(fairway, "turns", false, &arr, err);
    if (st || fw_jnode_type(fairway) == FW_J_ABSENT || fw_jnode_type(&arr) == FW_J_ABSENT ||
        (st = fw_jarray(&arr, 0, &len, err)) || len == 0)
        return st;
    fw_scn_turn *u = out ? malloc(sizeof *u * len) : NULL;
    if (out && !u)
        return fw_fail(err, FW_ERUN, "out of memory");
    double t_prev = -INFINITY;
    for (size_t i = 0; i < len && !st; i++) {
        fw_jnode e = fw_jelement(&arr, i), x[5];
        size_t m = 0;
        double v[5];
        if ((st = fw_jarray(&e, 5, &m, err)))
            break;
        if (m != 5) {
            st = fw_jfail(&e, err, "%zu numbers: a turn is [t_s, heading_deg, sog_kn, "
                                   "rate_degps, to_deg]", m);
            break;
        }
        for (int k = 0; k < 5; k++)
            x[k] = fw_jelement(&e, (size_t)k);
        if ((st = fw_jnumber(&x[0], appear, 86400, &v[0], err)) ||
            (st = fw_jnumber(&x[1], 0, 360, &v[1], err)) ||
            (st = fw_jnumber(&x[2], 0, 60, &v[2], err)) ||
            (st = fw_jnumber(&x[3], 0, 90, &v[3], err)) ||
            (st = fw_jnumber(&x[4], 0, 360, &v[4], err)))
            break;
        if (!(v[0] > t_prev)) {
            st = fw_jfail(&x[0], err, "%.15g s: not after the turn before (%.15g s)", v[0], t_prev);
            break;
        }
        t_prev = v[0];
        if (u)
            u[i] = (fw_scn_turn){.t = v[0], .heading = fw_deg_to_rad(v[1]),
                                 .speed = fw_kn_to_ms(v[2]), .rate = fw_deg_to_rad(v[3]),
                                 .to = fw_deg_to_rad(v[4])};
    }
    if (st) {
        free(u);
        return st;
    }
    if (out)
        *out = u;
    *n = (int)len;
    return FW_OK;
}

fw_status fw_scn_dnv_turns(const char *path, int i, fw_scn_turn **out, int *n, fw_error *err)
{
    fw_jdoc *doc = NULL;
    *out = NULL;
    *n = 0;
    fw_status st = fw_jdoc_load(path, &doc, err);
    if (st)
        return st;
    fw_jnode root = fw_jdoc_root(doc), arr, ship, f, when;
    size_t len = 0;
    double appear = 0.0;
    if (!(st = fw_jobject(&root, err)) && !(st = fw_jmember(&root, "targetShips", true, &arr, err)) &&
        !(st = fw_jarray(&arr, (size_t)i + 1, &len, err))) {
        ship = fw_jelement(&arr, (size_t)i);
        if (!(st = fw_jobject(&ship, err)) && !(st = fw_jmember(&ship, "fairway", false, &f, err)) &&
            fw_jnode_type(&f) != FW_J_ABSENT && !(st = fw_jobject(&f, err)) &&
            !(st = fw_jmember(&f, "appearS", false, &when, err)) &&
            (fw_jnode_type(&when) == FW_J_ABSENT ||
             !(st = fw_jnumber(&when, 0, 86400, &appear, err))))
            st = fw_scn_dnv_read_turns(&f, appear, out, n, err);
    }
    fw_jdoc_free(doc);
    return st;
}
