/* names.h - the names of an enum's values, as one table per enum.
 *
 * Settings read from files (a behaviour, a return, ...) are enums inside the
 * program and words in the files; each enum keeps its words in one array in
 * value order, written once, and these two read it both ways.
 */
#ifndef FW_NAMES_H
#define FW_NAMES_H

/* names[v], or "?" for a value outside the table. */
const char *fw_name_of(const char *const *names, int n, int v);
/* The value whose name is text, or -1. */
int fw_name_find(const char *const *names, int n, const char *text);

#endif
