/* fuzz_common.c - see fuzz_common.h. */
#include "fuzz_common.h"

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char g_dir[256];

/* A path that does not fit stops the fuzzer: it would name another file. */
#define FIT(buf, ...)                                                                       \
    do {                                                                                    \
        if ((size_t)snprintf(buf, sizeof buf, __VA_ARGS__) >= sizeof buf) {                \
            fprintf(stderr, "fuzz: path too long\n");                                       \
            abort();                                                                        \
        }                                                                                   \
    } while (0)

static void cleanup(void)
{
    char cmd[300];
    FIT(cmd, "rm -rf '%s'", g_dir);
    if (system(cmd) != 0)
        fprintf(stderr, "fuzz: could not remove %s\n", g_dir);
}

static void setup(void)
{
    setenv("FAIRWAY_DATA", FAIRWAY_DATA_DIR, 0);
    const char *tmp = getenv("TMPDIR");
    FIT(g_dir, "%s/fairway-fuzz.XXXXXX", tmp && tmp[0] ? tmp : "/tmp");
    if (!mkdtemp(g_dir)) {
        perror("fuzz: mkdtemp");
        abort();
    }
    static const char *const links[] = {"traffic", "paper", "imazu", "ships"};
    for (size_t i = 0; i < sizeof links / sizeof links[0]; i++) {
        char from[512], to[512];
        FIT(from, "%s/scenarios/%s", getenv("FAIRWAY_DATA"), links[i]);
        FIT(to, "%s/%s", g_dir, links[i]);
        if (symlink(from, to) != 0) {
            perror("fuzz: symlink");
            abort();
        }
    }
    atexit(cleanup);
}

const char *fuzz_write_input(const char *sub, const uint8_t *data, size_t size)
{
    static char path[512];
    if (!g_dir[0])
        setup();
    char dir[400];
    FIT(dir, "%s/%s", g_dir, sub);
    mkdir(dir, 0700);
    FIT(path, "%s/input.yaml", dir);
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0) {
        perror("fuzz: open");
        abort();
    }
    size_t done = 0;
    while (done < size) {
        ssize_t k = write(fd, data + done, size - done);
        if (k <= 0) {
            perror("fuzz: write");
            abort();
        }
        done += (size_t)k;
    }
    close(fd);
    return path;
}
