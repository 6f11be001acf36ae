/* backend_load.c - the SUMO back ends as modules opened on first use (see
 * backend.h).  RTLD_LOCAL: the two modules export the same entry name and
 * link different SUMO libraries; neither is seen by the other.  RTLD_NOW:
 * SUMO's libraries bind immediately anyway (they are linked BIND_NOW), and a
 * missing symbol is better found at the load than in the middle of a run. */
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "core/files.h"
#include "traffic/backend.h"

static const char *const kModule[2] = {"fairway-libsumo.so", "fairway-libtraci.so"};
static const fw_sumo_backend *g_table[2];
static pthread_mutex_t g_lock = PTHREAD_MUTEX_INITIALIZER;

static fw_status open_module(int k, fw_error *err)
{
    char path[4096];
    fw_status st = fw_path(path, sizeof path, err, "%s/%s", fw_module_dir(), kModule[k]);
    if (st)
        return st;
    void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        /* the loader's message mostly starts with the path again */
        const char *why = dlerror();
        size_t n = strlen(path);
        if (strncmp(why, path, n) == 0 && strncmp(why + n, ": ", 2) == 0)
            why += n + 2;
        return fw_fail(err, FW_ERUN, "cannot load the SUMO back end %s: %s", path, why);
    }
    fw_sumo_backend_entry entry;
    /* the ISO C way to turn dlsym's object pointer into a function pointer */
    *(void **)&entry = dlsym(h, FW_SUMO_BACKEND_ENTRY);
    const fw_sumo_backend *be = entry ? entry() : NULL;
    if (!be) {
        dlclose(h);
        return fw_fail(err, FW_ERUN, "%s is not a fairway SUMO back end (no %s)", path,
                       FW_SUMO_BACKEND_ENTRY);
    }
    g_table[k] = be;
    return FW_OK;
}

fw_status fw_sumo_backend_load(bool libtraci, const fw_sumo_backend **be, fw_error *err)
{
    int k = libtraci ? 1 : 0;
    fw_status st = FW_OK;
    pthread_mutex_lock(&g_lock);
    if (!g_table[k])
        st = open_module(k, err);
    *be = g_table[k];
    pthread_mutex_unlock(&g_lock);
    return st;
}
