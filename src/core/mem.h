/* mem.h - growing arrays without the `p = realloc(p, ...)` leak.
 *
 * fw_resize gives *p room for n elements of elem bytes and keeps the old
 * block (and returns false) when memory runs out, so a caller can report the
 * failure with everything it had still owned and freed once.  The pointer is
 * passed as void ** (the address of any object pointer, cast).
 */
#ifndef FW_MEM_H
#define FW_MEM_H

#include <stdbool.h>
#include <stddef.h>

bool fw_resize(void **p, size_t elem, size_t n);

/* fw_resize of k arrays to n elements each; the arguments after k are k
 * pairs (void **p, size_t elem).  False (every array as it then is, none
 * lost) when memory runs out: the caller keeps its capacity unchanged. */
bool fw_resize_each(size_t n, int k, ...);

/* free() of each of the n pointers given (any may be NULL): a destructor's
 * blocks in one line. */
void fw_free_each(int n, ...);

/* Capacity for n when cap is too small: at least double, at least n. */
static inline int fw_grown_cap(int cap, int n) { return n > 2 * cap ? n : 2 * cap; }

/* Room for n elements in *p, whose capacity *cap grows by fw_grown_cap;
 * false (the block and *cap kept) when memory runs out. */
static inline bool fw_reserve(void **p, size_t elem, int *cap, int n)
{
    if (n <= *cap)
        return true;
    int c = fw_grown_cap(*cap, n);
    if (!fw_resize(p, elem, (size_t)c))
        return false;
    *cap = c;
    return true;
}

#endif
