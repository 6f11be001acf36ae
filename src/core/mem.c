/* mem.c - see mem.h. */
#include "core/mem.h"

#include <stdarg.h>
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

bool fw_resize_each(size_t n, int k, ...)
{
    va_list ap;
    va_start(ap, k);
    bool ok = true;
    for (int i = 0; i < k && ok; i++) {
        void **p = va_arg(ap, void **);
        size_t elem = va_arg(ap, size_t);
        ok = fw_resize(p, elem, n);
    }
    va_end(ap);
    return ok;
}

void fw_free_each(int n, ...)
{
    va_list ap;
    va_start(ap, n);
    for (int i = 0; i < n; i++)
        free(va_arg(ap, void *));
    va_end(ap);
}
