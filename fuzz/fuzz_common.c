/* fuzz_common.c - see fuzz_common.h. */
#include "fuzz_common.h"

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char g_dir[256];

static void cleanup(void)
{
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", g_dir);
    if (system(cmd) != 0)
        fprintf(stderr, "fuzz: could not remove %s\n", g_dir);
}

static void setup(void)
{
    setenv("FAIRWAY_DATA", FAIRWAY_DATA_DIR, 0);
    const char *tmp = getenv("TMPDIR");
    snprintf(g_dir, sizeof g_dir, "%s/fairway-fuzz.XXXXXX", tmp && tmp[0] ? tmp : "/tmp");
    if (!mkdtemp(g_dir)) {
        perror("fuzz: mkdtemp");
        abort();
    }
    static const char *const links[] = {"traffic", "paper", "imazu", "ships"};
    for (size_t i = 0; i < sizeof links / sizeof links[0]; i++) {
        char from[512], to[512];
        snprintf(from, sizeof from, "%s/scenarios/%s", getenv("FAIRWAY_DATA"), links[i]);
        snprintf(to, sizeof to, "%s/%s", g_dir, links[i]);
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
    snprintf(dir, sizeof dir, "%s/%s", g_dir, sub);
    mkdir(dir, 0700);
    snprintf(path, sizeof path, "%s/input.yaml", dir);
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
