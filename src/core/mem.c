/* mem.c - see mem.h. */
#include "core/mem.h"

#include <stdint.h>
#include <stdlib.h>

bool fw_resize(void **p, size_t elem, size_t n)
{
    if (n == 0)
        n = 1; /* realloc(p, 0) may free p and return NULL */
    if (elem && n > SIZE_MAX / elem)
        return false;
    void *q = realloc(*p, elem * n);
    if (!q)
        return false;
    *p = q;
    return true;
}
