/* scn_ais.h - a scenario's AIS traffic (traffic: ais: FILE and its window,
 * gap and column keys) and the file keys of a scenario, resolved relative to
 * the scenario file.  Internal to the scenario loader. */
#ifndef FW_SCENARIO_SCN_AIS_H
#define FW_SCENARIO_SCN_AIS_H

#include "scenario/scenario.h"
#include "yaml/yaml_tree.h"

/* traffic.network's value as fw_network_find takes it: a network's name as
 * it is, a directory's path (it holds a '/') relative to the directory of
 * scenario_file unless absolute.  False when out is too short. */
bool fw_scn_network_ref(const char *scenario_file, const char *value, char *out, size_t n);

/* The optional file key of map (at path) into out: relative to the
 * directory of scenario_file unless absolute; it must open.  out is "" when
 * the key is absent. */
fw_status fw_scn_file_key(const yt_doc *doc, const yt_node *map, const char *path,
                          const char *key, const char *scenario_file, char *out, size_t n,
                          fw_error *err);

/* traffic.ais, ais_start, ais_end ("YYYY-MM-DD HH:MM:SS" UTC or seconds after
 * the file's first report), ais_max_gap_s, ais_columns into s->ais; the file's
 * header is read now, so a bad one is refused at load. */
fw_status fw_scn_load_ais(const yt_doc *doc, const yt_node *tr, fw_scenario *s, fw_error *err);

#endif
