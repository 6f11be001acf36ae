/* study_axes.h - a study's axes (internal to src/study: study.c reads a
 * study file with them).
 *
 * `axes:` maps dotted keys of the scenario file to lists of values; every
 * combination is a setting (the last axis fastest) whose scenario is the base
 * file with those values laid over it (scenario.h fw_scenario_load_with), so
 * the scenario's own reader checks each value.  Keys the study sweeps, draws
 * or holds fixed itself are refused, naming what to use instead.
 */
#ifndef FW_STUDY_AXES_H
#define FW_STUDY_AXES_H

#include "study/study.h"
#include "yaml/yaml_tree.h"

/* axes: of the study file into s->axes, s->n_axes and s->n_settings (their
 * form: keys, values, counts); nothing when the file has none. */
fw_status fw_study_read_axes(const yt_doc *doc, const yt_node *root, fw_study *s, fw_error *err);

/* Each setting's scenario into s->settings, once s->base and its audit are
 * loaded: an error names the study file's axes and the setting, then the
 * scenario's own message. */
fw_status fw_study_load_settings(const yt_doc *doc, fw_study *s, fw_error *err);

#endif
