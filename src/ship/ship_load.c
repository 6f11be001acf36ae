/* Ship files: the schema, checked field by field. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "core/units.h"
#include "ship/ship.h"
#include "yaml/yaml_tree.h"

typedef struct field {
    const char *key;
    size_t offset;
    double lo, hi;
    double scale;  /* file unit -> SI (deg -> rad, deg/s -> rad/s) */
    bool optional; /* keeps the value set before loading when absent */
} field;

#define F(k, member, lo, hi) {k, offsetof(fw_ship, member), lo, hi, 1.0, false}
#define FDEG(k, member, lo, hi) {k, offsetof(fw_ship, member), lo, hi, FW_PI / 180.0, false}
#define FOPT(k, member, lo, hi) {k, offsetof(fw_ship, member), lo, hi, 1.0, true}

/* Ranges are wide physical bounds: they catch typos and unit slips (a length
 * in km, an angle in radians), not unusual ships. */
static const field particulars[] = {
    F("L", L, 0.5, 600.0),
    FOPT("Loa", Loa, 0.5, 650.0),
    F("B", B, 0.05, 100.0),
    F("d", d, 0.01, 40.0),
    F("Cb", Cb, 0.3, 0.95),
    FOPT("volume", volume, 1e-3, 2e6),
    F("x_G", x_G, -60.0, 60.0),
    F("k_zz", k_zz, 0.1, 0.5),
    F("rho", rho, 990.0, 1040.0),
    F("rudder_rate", rudder_rate, 0.5, 30.0),  /* deg/s, scaled below */
    FDEG("rudder_max", rudder_max, 5.0, 60.0),
};

static const field hull[] = {
    F("m_x", m_x, 0.0, 0.2),       F("m_y", m_y, 0.0, 2.0),      F("J_z", J_z, 0.0, 0.2),
    F("R_0", R_0, 0.0, 0.2),       F("X_vv", X_vv, -2.0, 2.0),   F("X_vr", X_vr, -2.0, 2.0),
    F("X_rr", X_rr, -2.0, 2.0),    F("X_vvvv", X_vvvv, -10.0, 10.0),
    F("Y_v", Y_v, -3.0, 0.0),      F("Y_r", Y_r, -2.0, 2.0),     F("Y_vvv", Y_vvv, -10.0, 10.0),
    F("Y_vvr", Y_vvr, -10.0, 10.0), F("Y_vrr", Y_vrr, -10.0, 10.0), F("Y_rrr", Y_rrr, -2.0, 2.0),
    F("N_v", N_v, -2.0, 2.0),      F("N_r", N_r, -2.0, 0.0),     F("N_vvv", N_vvv, -5.0, 5.0),
    F("N_vvr", N_vvr, -5.0, 5.0),  F("N_vrr", N_vrr, -5.0, 5.0), F("N_rrr", N_rrr, -2.0, 2.0),
};

static const field propeller[] = {
    F("D_P", D_P, 0.01, 15.0),   F("t_P", t_P, 0.0, 0.6),     F("w_P0", w_P0, 0.0, 0.8),
    F("x_P", x_P, -0.8, 0.0),    F("k0", k0, 0.05, 1.0),      F("k1", k1, -1.5, 0.5),
    F("k2", k2, -1.0, 1.0),      F("C_1", C_1, 0.0, 10.0),    F("C_2_plus", C_2_plus, 0.0, 5.0),
    F("C_2_minus", C_2_minus, 0.0, 5.0),
};

static const field rudder[] = {
    F("A_R", A_R, 1e-4, 400.0),  F("H_R", H_R, 0.01, 30.0),   F("aspect_ratio", aspect_ratio, 0.3, 6.0),
    F("t_R", t_R, 0.0, 0.8),     F("a_H", a_H, 0.0, 1.5),     F("x_H", x_H, -1.0, 0.0),
    F("x_R", x_R, -0.6, -0.3),   F("eps", eps, 0.3, 2.0),     F("kappa", kappa, 0.0, 1.5),
    F("l_R", l_R, -2.0, 0.0),    F("gamma_R_plus", gamma_R_plus, 0.0, 1.5),
    F("gamma_R_minus", gamma_R_minus, 0.0, 1.5),
};

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static fw_status read_section(const yt_doc *doc, const yt_node *root, const char *section,
                              const field *fields, size_t nfields, fw_ship *ship, fw_error *err)
{
    const yt_node *map;
    fw_status st = yt_req_map(doc, root, "", section, &map, err);
    if (st)
        return st;
    const char *allowed[40];
    for (size_t i = 0; i < nfields; i++)
        allowed[i] = fields[i].key;
    allowed[nfields] = NULL;
    if ((st = yt_check_keys(doc, map, section, allowed, err)))
        return st;
    for (size_t i = 0; i < nfields; i++) {
        const field *f = &fields[i];
        double *dst = (double *)((char *)ship + f->offset);
        double v;
        if (f->optional) {
            if (!yt_get(map, f->key))
                continue;
        }
        if ((st = yt_req_number(doc, map, section, f->key, f->lo, f->hi, &v, err)))
            return st;
        *dst = v * f->scale;
    }
    return FW_OK;
}

static fw_status read_index(const yt_doc *doc, const yt_node *kb, const char *P, const char *key,
                            fw_nomoto_index *ix, fw_error *err)
{
    char path[64];
    yt_path(path, sizeof path, P, key);
    const yt_node *map;
    fw_status st = yt_req_map(doc, kb, P, key, &map, err);
    if (st)
        return st;
    const char *allowed[FW_NB_COUNT + 1];
    for (int b = 0; b < FW_NB_COUNT; b++)
        allowed[b] = fw_nomoto_basis_names[b];
    allowed[FW_NB_COUNT] = NULL;
    if ((st = yt_check_keys(doc, map, path, allowed, err)))
        return st;
    ix->n = 0;
    for (int b = 0; b < FW_NB_COUNT; b++) {
        if (!yt_get(map, fw_nomoto_basis_names[b]))
            continue;
        double c;
        if ((st = yt_req_number(doc, map, path, fw_nomoto_basis_names[b], -1e7, 1e7, &c, err)))
            return st;
        ix->basis[ix->n] = (fw_nomoto_basis)b;
        ix->coef[ix->n++] = c;
    }
    if (ix->n == 0)
        return fw_fail_at(err, doc->file, map->line, path, "needs at least one term");
    return FW_OK;
}

/* The knowledge-base block P ("nomoto" or "nomoto_port"), if present. */
static fw_status read_nomoto(const yt_doc *doc, const yt_node *root, const char *P,
                             fw_nomoto_kb *kb, fw_error *err)
{
    const yt_node *map;
    fw_status st = yt_opt_map(doc, root, "", P, &map, err);
    if (st || !map)
        return st;
    static const char *const allowed[] = {"source", "speed_min_kn", "speed_max_kn",
                                          "rudder_min_deg", "rudder_max_deg", "K", "T1", "T2",
                                          "T3", "drift", "drift_lag_s", "speed_loss",
                                          "speed_loss_drift", "speed_lag_s", NULL};
    if ((st = yt_check_keys(doc, map, P, allowed, err)))
        return st;
    char source[256], field[64];
    if ((st = yt_opt_string(doc, map, P, "source", source, sizeof source, err)))
        return st;
    if ((st = yt_req_number(doc, map, P, "speed_min_kn", 0.1, 60.0, &kb->speed_min_kn, err)) ||
        (st = yt_req_number(doc, map, P, "speed_max_kn", 0.1, 60.0, &kb->speed_max_kn, err)) ||
        (st = yt_req_number(doc, map, P, "rudder_min_deg", 0.5, 60.0, &kb->rudder_min_deg, err)) ||
        (st = yt_req_number(doc, map, P, "rudder_max_deg", 0.5, 60.0, &kb->rudder_max_deg, err)))
        return st;
    if (kb->speed_max_kn < kb->speed_min_kn)
        return fw_fail_at(err, doc->file, yt_key_line(map, "speed_max_kn"),
                          yt_path(field, sizeof field, P, "speed_max_kn"),
                          "must not be below speed_min_kn");
    if (kb->rudder_max_deg < kb->rudder_min_deg)
        return fw_fail_at(err, doc->file, yt_key_line(map, "rudder_max_deg"),
                          yt_path(field, sizeof field, P, "rudder_max_deg"),
                          "must not be below rudder_min_deg");
    if ((st = read_index(doc, map, P, "K", &kb->K, err)) ||
        (st = read_index(doc, map, P, "T1", &kb->T1, err)) ||
        (st = read_index(doc, map, P, "T2", &kb->T2, err)) ||
        (st = read_index(doc, map, P, "T3", &kb->T3, err)))
        return st;
    kb->drift = kb->drift_lag_s = kb->speed_loss = kb->speed_loss_drift = kb->speed_lag_s = 0.0;
    if ((st = yt_opt_number(doc, map, P, "drift", 0.0, 5.0, &kb->drift, err)) ||
        (st = yt_opt_number(doc, map, P, "drift_lag_s", 0.0, 3600.0, &kb->drift_lag_s, err)) ||
        /* negative: a gain in the turn's oblique inflow (ship.h) */
        (st = yt_opt_number(doc, map, P, "speed_loss", -1.0, 2.0, &kb->speed_loss, err)) ||
        (st = yt_opt_number(doc, map, P, "speed_loss_drift", 0.0, 20.0, &kb->speed_loss_drift,
                            err)) ||
        (st = yt_opt_number(doc, map, P, "speed_lag_s", 0.0, 3600.0, &kb->speed_lag_s, err)))
        return st;
    kb->present = true;
    return FW_OK;
}

/* windage: {type: container_loaded, A_F: m^2, A_L: m^2, s_L: m} (windage.h),
 * optional.  The areas are above the waterline: A_L at most Loa times 60 m,
 * A_F at most B times 60 m, the centroid within half Loa of midship. */
static fw_status read_windage(const yt_doc *doc, const yt_node *root, fw_ship *ship,
                              fw_error *err)
{
    static const char *const allowed[] = {"type", "A_F", "A_L", "s_L", NULL};
    const char *P = "windage";
    const yt_node *map;
    fw_status st = yt_opt_map(doc, root, "", P, &map, err);
    if (st || !map)
        return st;
    fw_windage *w = &ship->windage;
    char type[64];
    if ((st = yt_check_keys(doc, map, P, allowed, err)) ||
        (st = yt_req_string(doc, map, P, "type", type, sizeof type, err)))
        return st;
    if (!fw_windage_type_parse(type, &w->type)) {
        char names[1024] = "";
        for (int i = 0; i < FW_WT_COUNT; i++)
            snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", i ? ", " : "",
                     fw_blendermann_table[i].name);
        return yt_fail_key(doc, map, P, "type", err,
                           "'%s' is not one of Blendermann's ship types (%s)", type, names);
    }
    double h = 60.0; /* m: no superstructure stands higher above the water */
    if ((st = yt_req_number(doc, map, P, "A_F", 1e-4, ship->B * h, &w->A_F, err)) ||
        (st = yt_req_number(doc, map, P, "A_L", 1e-4, ship->Loa * h, &w->A_L, err)) ||
        (st = yt_req_number(doc, map, P, "s_L", -0.5 * ship->Loa, 0.5 * ship->Loa, &w->s_L,
                            err)))
        return st;
    w->Loa = ship->Loa;
    w->present = true;
    return FW_OK;
}

static fw_status load_doc(const yt_doc *doc, fw_ship *ship, fw_error *err)
{
    const yt_node *root = doc->root;
    static const char *const allowed[] = {"name", "description", "particulars", "hull",
                                          "propeller", "rudder", "nomoto", "nomoto_port",
                                          "windage", NULL};
    fw_status st = yt_check_keys(doc, root, "", allowed, err);
    if (st)
        return st;
    char description[1024];
    if ((st = yt_req_string(doc, root, "", "name", ship->name, sizeof ship->name, err)) ||
        (st = yt_opt_string(doc, root, "", "description", description, sizeof description, err)))
        return st;
    ship->Loa = -1.0;
    ship->volume = -1.0;
    if ((st = read_section(doc, root, "particulars", particulars, COUNT(particulars), ship, err)))
        return st;
    ship->rudder_rate = fw_deg_to_rad(ship->rudder_rate);
    if (ship->Loa < 0.0)
        ship->Loa = ship->L;
    if (ship->volume < 0.0)
        ship->volume = ship->Cb * ship->L * ship->B * ship->d;
    const yt_node *pm = yt_get(root, "particulars");
    if (ship->Loa < ship->L)
        return fw_fail_at(err, doc->file, yt_key_line(pm, "Loa"), "particulars.Loa",
                          "must not be shorter than L");
    if (ship->d > ship->B)
        return fw_fail_at(err, doc->file, yt_key_line(pm, "d"), "particulars.d",
                          "draft larger than breadth: check units");
    if (fabs(ship->x_G) > 0.2 * ship->L)
        return fw_fail_at(err, doc->file, yt_key_line(pm, "x_G"), "particulars.x_G",
                          "more than 0.2 L from midship");
    if ((st = read_section(doc, root, "hull", hull, COUNT(hull), ship, err)) ||
        (st = read_section(doc, root, "propeller", propeller, COUNT(propeller), ship, err)) ||
        (st = read_section(doc, root, "rudder", rudder, COUNT(rudder), ship, err)))
        return st;
    const yt_node *rm = yt_get(root, "rudder");
    if (ship->D_P > ship->d * 1.6)
        return fw_fail_at(err, doc->file, yt_key_line(yt_get(root, "propeller"), "D_P"),
                          "propeller.D_P", "propeller larger than the draft allows");
    if (ship->A_R > 0.1 * ship->L * ship->d)
        return fw_fail_at(err, doc->file, yt_key_line(rm, "A_R"), "rudder.A_R",
                          "rudder area above 10%% of L*d: check units");
    if ((st = read_nomoto(doc, root, "nomoto", &ship->nomoto, err)) ||
        (st = read_nomoto(doc, root, "nomoto_port", &ship->nomoto_port, err)) ||
        (st = read_windage(doc, root, ship, err)))
        return st;
    if (ship->nomoto_port.present && !ship->nomoto.present)
        return fw_fail_at(err, doc->file, yt_key_line(root, "nomoto_port"), "nomoto_port",
                          "a port knowledge base needs the nomoto: block as well");
    return FW_OK;
}

fw_status fw_ship_load(const char *name_or_path, fw_ship *ship, fw_error *err)
{
    memset(ship, 0, sizeof *ship);
    char path[512];
    if (!fw_ship_path(name_or_path, path, sizeof path))
        return fw_fail(err, FW_EINPUT, "ship '%.100s...': path longer than %zu characters",
                       name_or_path, sizeof path - 1);
    bool by_name = strcmp(path, name_or_path) != 0;
    FILE *probe = fopen(path, "rb");
    if (!probe) {
        if (by_name)
            return fw_fail(err, FW_EINPUT, "unknown ship '%s' (no file %s)", name_or_path, path);
        return fw_fail(err, FW_EINPUT, "%s: cannot open ship file", path);
    }
    fclose(probe);
    yt_doc *doc;
    fw_status st = yt_load_file(path, &doc, err);
    if (st)
        return st;
    snprintf(ship->file, sizeof ship->file, "%s", path);
    st = load_doc(doc, ship, err);
    yt_free(doc);
    return st;
}

double *fw_ship_field(fw_ship *ship, const char *key, const char **section, double *scale)
{
    static const struct {
        const char *name;
        const field *fields;
        size_t n;
    } sections[] = {
        {"particulars", particulars, COUNT(particulars)},
        {"hull", hull, COUNT(hull)},
        {"propeller", propeller, COUNT(propeller)},
        {"rudder", rudder, COUNT(rudder)},
    };
    for (size_t s = 0; s < COUNT(sections); s++)
        for (size_t i = 0; i < sections[s].n; i++)
            if (strcmp(sections[s].fields[i].key, key) == 0) {
                const field *f = &sections[s].fields[i];
                if (section)
                    *section = sections[s].name;
                if (scale)
                    /* rudder_rate is read in deg/s and converted after the table pass */
                    *scale = strcmp(key, "rudder_rate") == 0 ? FW_PI / 180.0 : f->scale;
                return (double *)((char *)ship + f->offset);
            }
    return NULL;
}
