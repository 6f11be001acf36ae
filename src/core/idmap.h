/* idmap.h - ship ids interned to small integers: the one string hash table.
 *
 * Ids get indices 0, 1, 2, ... in the order first seen, so a caller keeps
 * its per-ship data in plain arrays indexed by them (the encounter book, the
 * survey's per-ship arrays).  Open addressing with linear probing in a
 * power-of-two table kept at most half full; nothing is ever deleted.
 * Functions that allocate return 0, or -1 when out of memory (the map is
 * then as it was).  A zeroed fw_idmap is an empty one.
 *
 * The _keyed calls take the per-run key a traffic source gave the id
 * (fw_target.key, geom/target.h): a key seen before maps to its index
 * through a plain array, without hashing or comparing the id (the same ships
 * are looked up by several modules every step); key 0 looks the id up.
 */
#ifndef FW_IDMAP_H
#define FW_IDMAP_H

#include <stddef.h>
#include <stdint.h>

typedef struct fw_idmap {
    int *slot;        /* cap entries: interned index + 1, 0 = empty */
    size_t cap;
    char **name;      /* interned index -> id */
    uint64_t *hash;
    int n, name_cap;
    int *by_key;      /* key_cap entries: key - 1 -> interned index + 1, 0 = not seen */
    int key_cap;
    int keyless;      /* ids interned with no key: while none, a key not seen is an id not seen */
} fw_idmap;

/* The index of id, -1 if it has not been interned. */
int fw_idmap_find(const fw_idmap *t, const char *id);
/* *out = the index of id, interning it if new. */
int fw_idmap_intern(fw_idmap *t, const char *id, int *out);
/* The same with the id's key (> 0, or 0 for none): a key must stand for one
 * id only, for the map's life. */
int fw_idmap_find_keyed(const fw_idmap *t, int key, const char *id);
int fw_idmap_intern_keyed(fw_idmap *t, int key, const char *id, int *out);
void fw_idmap_free(fw_idmap *t);

#endif
