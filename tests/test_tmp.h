/* test_tmp.h - a test program's scratch directory, removed when the program
 * ends whether its checks passed or not.
 *
 * test_tmpdir makes TMPDIR/fw_test_TAG.XXXXXX ($TMPDIR, or /tmp when it is
 * unset or the path would not fit buf) and removes it, with everything in it,
 * at exit and on SIGINT, SIGTERM, SIGHUP and SIGABRT (a failed assert) in the
 * process that made it (a forked child's exit leaves it to its parent).  A
 * SIGKILL (ctest's timeout) cannot be caught: that leaves it.  FW_TEST_KEEP=1
 * keeps it for a look after a failure, and prints where it is.
 */
#ifndef FW_TEST_TMP_H
#define FW_TEST_TMP_H

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/files.h"

static char test_tmp_root_[512];
static pid_t test_tmp_owner_;

static void test_tmp_remove_(void)
{
    if (!test_tmp_root_[0] || getpid() != test_tmp_owner_)
        return;
    const char *keep = getenv("FW_TEST_KEEP");
    if (keep && strcmp(keep, "1") == 0)
        fprintf(stderr, "scratch directory kept: %s\n", test_tmp_root_);
    else
        fw_remove_tree(test_tmp_root_);
    test_tmp_root_[0] = '\0';
}

static void test_tmp_signal_(int sig)
{
    test_tmp_remove_();
    signal(sig, SIG_DFL);
    raise(sig);
}

/* The scratch directory into buf (size n); 0, or -1 (said on stderr) when it
 * cannot be made.  One per program. */
static inline int test_tmpdir(const char *tag, char *buf, size_t n)
{
    const char *td = getenv("TMPDIR");
    if (!td || td[0] != '/' || (size_t)snprintf(buf, n, "%s/fw_test_%s.XXXXXX", td, tag) >= n)
        snprintf(buf, n, "/tmp/fw_test_%s.XXXXXX", tag);
    if (!mkdtemp(buf)) {
        perror(buf);
        return -1;
    }
    snprintf(test_tmp_root_, sizeof test_tmp_root_, "%s", buf);
    test_tmp_owner_ = getpid();
    atexit(test_tmp_remove_);
    const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGABRT};
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++)
        signal(sigs[i], test_tmp_signal_);
    return 0;
}

#endif
