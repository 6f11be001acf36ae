/* backend_load.c - the SUMO back ends as modules opened on first use (see
 * backend.h).  RTLD_LOCAL: the two modules export the same entry name and
 * link different SUMO libraries; neither is seen by the other.  RTLD_NOW:
 * SUMO's libraries bind immediately anyway (they are linked BIND_NOW), and a
 * missing symbol is better found at the load than in the middle of a run. */
#define _GNU_SOURCE /* RTLD_DEEPBIND */
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "traffic/backend.h"

static const char *const kModule[2] = {"fairway-libsumo.so", "fairway-libtraci.so"};
static const fw_sumo_backend *g_table[2];
static pthread_mutex_t g_lock = PTHREAD_MUTEX_INITIALIZER;

enum { MAX_STUBS = 64 };
static void *g_stub[MAX_STUBS];
static int g_nstub;

static void close_stubs(void)
{
    while (g_nstub > 0)
        dlclose(g_stub[--g_nstub]);
}

/* The stand-ins for libsumocpp's GUI libraries (scripts/sumo_gui_stubs.py:
 * GDAL, FFmpeg, OpenSceneGraph, gl2ps and some 150 libraries behind them,
 * which only sumo-gui's code calls), opened before the libsumo module: the
 * loader then takes them for libsumocpp's dependencies of the same SONAME
 * and maps none of the real ones, which cost 0.1 s of linking per process.
 * None if FAIRWAY_SUMO_GUI_LIBS=load or none were built (stubs.txt absent). */
static void open_stubs(void)
{
    const char *env = getenv("FAIRWAY_SUMO_GUI_LIBS");
    if (env && strcmp(env, "load") == 0)
        return;
    char dir[4096], list[4096], line[512];
    fw_error e = {0};
    if (fw_path(dir, sizeof dir, &e, "%s/gui-stubs", fw_module_dir()) ||
        fw_path(list, sizeof list, &e, "%s/stubs.txt", dir))
        return;
    FILE *f = fopen(list, "r");
    if (!f)
        return;
    while (g_nstub < MAX_STUBS && fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = 0;
        char path[4608];
        if (!line[0] || snprintf(path, sizeof path, "%s/%s", dir, line) >= (int)sizeof path)
            continue;
        void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
        if (!h) {
            /* a partial set would still map the real ones behind it */
            close_stubs();
            break;
        }
        g_stub[g_nstub++] = h;
    }
    fclose(f);
}

/* RTLD_DEEPBIND for the libsumo module: libsumocpp's 55,000 symbol
 * references are looked up in its own libraries first, not after the 53 the
 * program has (MPI, PROJ, SUNDIALS and theirs), which halves its load (0.028-
 * 0.042 s to 0.014-0.022 s CPU, measured).  Only where nothing interposes on
 * the program's side: under the sanitizers (whose malloc the module must share)
 * or with an LD_PRELOAD (a profiler's or another allocator) the usual order. */
static int bind_flag(int k)
{
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    (void)k;
    return 0;
#else
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
    (void)k;
    return 0;
#endif
#endif
    const char *pre = getenv("LD_PRELOAD");
    return k == 0 && !(pre && pre[0]) ? RTLD_DEEPBIND : 0;
#endif
}

static fw_status open_module(int k, fw_error *err)
{
    char path[4096];
    fw_status st = fw_path(path, sizeof path, err, "%s/%s", fw_module_dir(), kModule[k]);
    if (st)
        return st;
    if (k == 0)
        open_stubs();
    const int flags = RTLD_NOW | RTLD_LOCAL | bind_flag(k);
    void *h = dlopen(path, flags);
    if (!h && g_nstub > 0) {
        /* libsumocpp changed since the build made the stand-ins (a symbol
         * they lack): the real libraries, slower to load, and a word why */
        fprintf(stderr, "fairway: the stand-ins for SUMO's GUI libraries do not fit "
                        "libsumocpp (%s); loading the real ones (a rebuild makes new stand-ins)\n",
                dlerror());
        close_stubs();
        h = dlopen(path, flags);
    }
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
