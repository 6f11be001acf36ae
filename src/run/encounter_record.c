/* encounter_record.c - the encounter record's field table and its writers
 * (encounter_record.h). */
#include "run/encounter_record.h"

#include <math.h>
#include <string.h>

#include "core/fmt.h"
#include "core/json.h"
#include "core/units.h"

/* An accessor per field: the value from the encounter (and, for the study's
 * columns, the verdict).  `db` picks the database's form where it differs. */
#define GET(fn, body)                                                                      \
    static void fn(const fw_encounter *e, const fw_enc_verdict *v, bool db, fw_enc_value *o) \
    {                                                                                      \
        (void)e;                                                                           \
        (void)v;                                                                           \
        (void)db;                                                                          \
        body;                                                                              \
    }

GET(g_id, o->text = e->id)
GET(g_type, o->text = e->type)
GET(g_length, o->num = e->length)
GET(g_breadth, o->num = e->breadth)
GET(g_situation, o->text = fw_situation_name(e->situation))
GET(g_t_detect, o->num = e->t_detect)
GET(g_dcpa0, o->num = e->dcpa0)
GET(g_tcpa0, o->num = e->tcpa0)
GET(g_threat, o->num = e->threat)
GET(g_acted, o->num = e->acted)
GET(g_t_act, o->num = db && !e->acted ? NAN : e->t_act)
GET(g_act_side, o->text = fw_side_name(e->act_side))
/* the files: the angle; the database: signed (+ starboard), NULL if it never acted */
GET(g_act_helm, o->num = !db ? fw_rad_to_deg(fabs(e->act_helm))
                       : e->acted ? fw_rad_to_deg(e->act_helm) : NAN)
GET(g_primary, o->num = e->primary)
GET(g_min_dist, o->num = e->min_dist)
GET(g_t_min, o->num = e->t_min)
GET(g_min_lambda, o->num = e->min_lambda)
GET(g_domain_entered, o->num = e->domain_entered)
GET(g_near_miss, o->num = v->near_miss)
GET(g_near_miss_centre, o->num = v->near_miss_centre)
GET(g_closeness, o->num = v->closeness)
GET(g_collision, o->num = e->collision)
GET(g_colregs_ok, o->num = e->colregs_ok)
GET(g_min_hull, o->num = e->min_hull)
GET(g_candidate, o->num = e->cand_miss == 0.0)
GET(g_cand_miss, o->num = e->cand_miss)
GET(g_outcome, o->text = v->outcome)
GET(g_rule, o->num = e->audit.rule)
GET(g_role, o->text = fw_audit_role_name(e->audit.role))
GET(g_t_risk, o->num = e->audit.t_risk)
GET(g_tcpa_risk, o->num = e->audit.tcpa_risk)
GET(g_tcpa_act, o->num = e->audit.tcpa_act)
GET(g_course_change, o->num = e->audit.acted ? fw_rad_to_deg(e->audit.course_change) : NAN)
GET(g_speed_change, o->num = e->audit.acted ? e->audit.speed_change : NAN)
GET(g_early, o->num = e->audit.early)
GET(g_substantial, o->num = e->audit.substantial)
GET(g_phase, o->num = e->audit.phase)
/* NULL: not audited (no risk of collision) */
GET(g_compliant, o->null = e->audit.compliant < 0; o->num = e->audit.compliant)
GET(g_note, o->text = e->audit.note)

enum { F = FW_ENC_CSV | FW_ENC_JSON, ALL = F | FW_ENC_SQL, NN = FW_ENC_NOT_NULL };

static const fw_enc_field kFields[] = {
    {"id", "target", FW_ENC_TEXT, "", 0, ALL | NN, g_id},
    {"type", "target_type", FW_ENC_TEXT, "", 0, ALL | NN, g_type},
    {"length_m", NULL, FW_ENC_REAL, "m", 1, FW_ENC_CSV, g_length},
    {"breadth_m", NULL, FW_ENC_REAL, "m", 1, FW_ENC_CSV, g_breadth},
    {"situation", "situation", FW_ENC_TEXT, "", 0, ALL | NN, g_situation},
    {"t_detect_s", "t_detect_s", FW_ENC_REAL, "s", 1, ALL, g_t_detect},
    {"dcpa_m", "dcpa0_m", FW_ENC_REAL, "m", 1, ALL, g_dcpa0},
    {"tcpa_s", "tcpa0_s", FW_ENC_REAL, "s", 1, ALL, g_tcpa0},
    {"threat", "threat", FW_ENC_FLAG, "", 0, ALL, g_threat},
    {NULL, "acted", FW_ENC_FLAG, "", 0, FW_ENC_SQL, g_acted},
    {"t_act_s", "t_act_s", FW_ENC_REAL, "s", 1, ALL | FW_ENC_NULLABLE, g_t_act},
    {"act_side", "act_side", FW_ENC_TEXT, "", 0, ALL, g_act_side},
    {"act_helm_deg", "act_helm_deg", FW_ENC_REAL, "deg", 1, ALL, g_act_helm},
    {"primary", NULL, FW_ENC_FLAG, "", 0, F, g_primary},
    {"min_distance_m", "min_dist_m", FW_ENC_REAL, "m", 1, ALL, g_min_dist},
    {"t_min_s", "t_min_s", FW_ENC_REAL, "s", 1, ALL, g_t_min},
    {"min_domain_ratio", "min_lambda", FW_ENC_REAL, "", 3, ALL, g_min_lambda},
    {"domain_entered", "domain_entered", FW_ENC_FLAG, "", 0, ALL, g_domain_entered},
    {NULL, "near_miss", FW_ENC_FLAG, "", 0, FW_ENC_SQL, g_near_miss},
    {NULL, "near_miss_centre", FW_ENC_FLAG, "", 0, FW_ENC_SQL, g_near_miss_centre},
    {"collision", "collision", FW_ENC_FLAG, "", 0, ALL, g_collision},
    {"colregs_ok", "colregs_ok", FW_ENC_FLAG, "", 0, ALL, g_colregs_ok},
    {"min_hull_m", "min_hull_m", FW_ENC_REAL, "m", 1, ALL | FW_ENC_NULLABLE, g_min_hull},
    {NULL, "closeness", FW_ENC_REAL, "", 4, FW_ENC_SQL, g_closeness},
    {NULL, "candidate", FW_ENC_FLAG, "", 0, FW_ENC_SQL, g_candidate},
    {NULL, "cand_miss_m", FW_ENC_REAL, "m", 1, FW_ENC_SQL, g_cand_miss},
    {NULL, "outcome", FW_ENC_TEXT, "", 0, FW_ENC_SQL, g_outcome},
    {NULL, "rule", FW_ENC_INT, "", 0, FW_ENC_SQL, g_rule},
    {NULL, "role", FW_ENC_TEXT, "", 0, FW_ENC_SQL, g_role},
    {NULL, "t_risk_s", FW_ENC_REAL, "s", 1, FW_ENC_SQL, g_t_risk},
    {NULL, "tcpa_risk_s", FW_ENC_REAL, "s", 1, FW_ENC_SQL, g_tcpa_risk},
    {NULL, "tcpa_act_s", FW_ENC_REAL, "s", 1, FW_ENC_SQL, g_tcpa_act},
    {NULL, "course_change_deg", FW_ENC_REAL, "deg", 1, FW_ENC_SQL, g_course_change},
    {NULL, "speed_change", FW_ENC_REAL, "", 3, FW_ENC_SQL, g_speed_change},
    {NULL, "early", FW_ENC_INT, "", 0, FW_ENC_SQL, g_early},
    {NULL, "substantial", FW_ENC_INT, "", 0, FW_ENC_SQL, g_substantial},
    {NULL, "rule17_phase", FW_ENC_INT, "", 0, FW_ENC_SQL, g_phase},
    {NULL, "compliant", FW_ENC_INT, "", 0, FW_ENC_SQL, g_compliant},
    {NULL, "audit_note", FW_ENC_TEXT, "", 0, FW_ENC_SQL, g_note},
};
enum { NFIELDS = sizeof kFields / sizeof kFields[0] };

const fw_enc_field *fw_enc_fields(int *n)
{
    *n = NFIELDS;
    return kFields;
}

int fw_enc_csv_column(const char *name)
{
    for (int i = 0, k = 0; i < NFIELDS; i++) {
        if (!(kFields[i].flags & FW_ENC_CSV))
            continue;
        if (strcmp(kFields[i].name, name) == 0)
            return k;
        k++;
    }
    return -1;
}

void fw_enc_csv_header(FILE *f)
{
    const char *sep = "";
    for (int i = 0; i < NFIELDS; i++)
        if (kFields[i].flags & FW_ENC_CSV) {
            fprintf(f, "%s%s", sep, kFields[i].name);
            sep = ",";
        }
    fputc('\n', f);
}

/* A number in the files: "%.Nf", or null when not finite for a nullable field. */
static void put_num(FILE *f, const fw_enc_field *x, double v)
{
    char fmt[8];
    snprintf(fmt, sizeof fmt, "%%.%df", x->decimals);
    if (x->flags & FW_ENC_NULLABLE)
        fw_json_number(f, v, fmt);
    else
        fprintf(f, fmt, v);
}

/* One field's value as the files write it (json: strings quoted, flags as
 * true/false). */
static void put_value(FILE *f, const fw_enc_field *x, const fw_encounter *e, bool json)
{
    fw_enc_value v = {0};
    x->get(e, NULL, false, &v);
    if (x->type == FW_ENC_TEXT && json)
        fw_json_string(f, v.text);
    else if (x->type == FW_ENC_TEXT)
        fputs(v.text, f);
    else if (x->type == FW_ENC_REAL)
        put_num(f, x, v.num);
    else if (json)
        fputs(v.num != 0.0 ? "true" : "false", f);
    else
        fprintf(f, "%d", (int)v.num);
}

void fw_enc_csv_row(FILE *f, const fw_encounter *e)
{
    const char *sep = "";
    for (int i = 0; i < NFIELDS; i++)
        if (kFields[i].flags & FW_ENC_CSV) {
            fputs(sep, f);
            put_value(f, &kFields[i], e, false);
            sep = ",";
        }
    fputc('\n', f);
}

void fw_enc_json(FILE *f, const fw_encounter *e)
{
    const char *sep = "";
    fputc('{', f);
    for (int i = 0; i < NFIELDS; i++)
        if (kFields[i].flags & FW_ENC_JSON) {
            fprintf(f, "%s\"%s\": ", sep, kFields[i].name);
            put_value(f, &kFields[i], e, true);
            sep = ", ";
        }
    fputc('}', f);
}

int fw_enc_sql_table(char *buf, size_t n)
{
    static const char *const decl[] = {[FW_ENC_TEXT] = "TEXT", [FW_ENC_REAL] = "REAL",
                                       [FW_ENC_FLAG] = "INTEGER", [FW_ENC_INT] = "INTEGER"};
    size_t k = 0;
#define PUT(...) k += (size_t)snprintf(buf + (k < n ? k : n), k < n ? n - k : 0, __VA_ARGS__)
    PUT("CREATE TABLE IF NOT EXISTS encounters(\n"
        "  run_id INTEGER NOT NULL REFERENCES runs(run_id),\n");
    for (int i = 0; i < NFIELDS; i++)
        if (kFields[i].flags & FW_ENC_SQL)
            PUT("  %s %s%s,\n", kFields[i].sql, decl[kFields[i].type],
                kFields[i].flags & FW_ENC_NOT_NULL ? " NOT NULL" : "");
    PUT("  PRIMARY KEY(run_id, target));\n");
#undef PUT
    return (int)k;
}
