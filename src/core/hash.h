/* hash.h - the one byte-string hash: 64-bit FNV-1a.  Not cryptographic: a
 * digest to tell inputs apart (a study's input files) or to index a store
 * (the network cache), never the only proof that two inputs are the same. */
#ifndef FW_HASH_H
#define FW_HASH_H

#include <stddef.h>
#include <stdint.h>

/* 64-bit FNV-1a, chained through h (start with FW_FNV_INIT). */
#define FW_FNV_INIT 0xcbf29ce484222325ull
uint64_t fw_fnv1a(uint64_t h, const void *data, size_t n);

#endif
