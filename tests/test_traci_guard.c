/* test_traci_guard.c - a SUMO peer that answers wrongly cannot crash or hang
 * fairway (traffic/traci_guard.h): a fake peer in a child process accepts
 * fairway's connection, reads its first request (libtraci's getVersion) and
 * then says nothing, answers with a length of 0, of 2^31, with a short
 * message of random bytes, or closes.  Each time fw_traffic_open in remote
 * mode returns an error that says what happened, at once or within the
 * reply timeout (1 s here) and a margin, and this process is still running (libtraci's
 * assertion on a zero length would have aborted it). */
#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/clock.h"
#include "test.h"
#include "traffic/traffic.h"

typedef enum { SILENT, ZERO, HUGE_LEN, RANDOM, CLOSE } behaviour;

/* The fake peer: listens before the fork (so the port is known and taken),
 * serves one connection as `b` says, then waits to be killed. */
static pid_t fake_peer(behaviour b, int *port)
{
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    struct sockaddr_in a = {.sin_family = AF_INET, .sin_addr.s_addr = htonl(INADDR_LOOPBACK)};
    socklen_t len = sizeof a;
    if (fd < 0 || bind(fd, (struct sockaddr *)&a, sizeof a) != 0 || listen(fd, 4) != 0 ||
        getsockname(fd, (struct sockaddr *)&a, &len) != 0)
        return -1;
    *port = ntohs(a.sin_port);
    pid_t pid = fork();
    if (pid != 0) {
        close(fd);
        return pid;
    }
    int c = accept(fd, NULL, NULL);
    unsigned char req[4096];
    if (c < 0 || recv(c, req, sizeof req, 0) <= 0)
        _exit(1);
    static const unsigned char zero[4] = {0, 0, 0, 0}, huge[4] = {0x80, 0, 0, 0};
    unsigned char rnd[9] = {0, 0, 0, 9};
    srand(7);
    for (int i = 4; i < 9; i++)
        rnd[i] = (unsigned char)rand();
    switch (b) {
    case ZERO:
        (void)!send(c, zero, sizeof zero, MSG_NOSIGNAL);
        break;
    case HUGE_LEN:
        (void)!send(c, huge, sizeof huge, MSG_NOSIGNAL);
        break;
    case RANDOM:
        (void)!send(c, rnd, sizeof rnd, MSG_NOSIGNAL);
        break;
    case CLOSE:
        close(c);
        break;
    case SILENT:
        break;
    }
    pause(); /* killed by the test */
    _exit(0);
}

static void expect(behaviour b, const char *what, const char *message)
{
    int port = 0;
    pid_t pid = fake_peer(b, &port);
    CHECK(pid > 0);
    if (pid <= 0)
        return;
    fw_traffic_def d = fw_default_traffic_def();
    d.mode.kind = FW_TRAFFIC_REMOTE;
    snprintf(d.mode.host, sizeof d.mode.host, "127.0.0.1");
    d.mode.port = port;
    d.connect_timeout = 2.0;
    d.reply_timeout = 1.0;
    fw_traffic *t = NULL;
    fw_error err = {0};
    double t0 = fw_clock_s();
    fw_status st = fw_traffic_open(&d, &t, &err);
    double took = fw_clock_s() - t0;
    CHECK(st == FW_ERUN && t == NULL);
    CHECK_CONTAINS(err.msg, message);
    /* the silent peer (and libtraci waiting for more after the random
     * bytes): the reply timeout; the others at once */
    CHECK(took < (b == SILENT || b == RANDOM ? 3.0 : 1.0));
    CHECK_CONTAINS(err.msg, "is not a SUMO fairway can use");
    printf("%-22s %.2f s: %s\n", what, took, err.msg);
    if (t)
        fw_traffic_close(t);
    kill(pid, SIGKILL);
    waitpid(pid, NULL, 0);
}

static void test_bad_peers(void)
{
    expect(SILENT, "accepts, says nothing", "no answer for 1 s (the reply timeout)");
    expect(ZERO, "a length of 0", "it sent a message of 0 bytes");
    expect(HUGE_LEN, "a length of 2^31", "it sent a message of 2147483648 bytes");
    expect(CLOSE, "closes", "it closed the connection before answering");
    /* a message of a valid length whose bytes mean nothing: libtraci's own
     * bounds-checked reading throws; whatever it says, an error, no abort */
    expect(RANDOM, "random bytes", "");
}

int main(void)
{
    /* what fw_traffic does in remote mode: a peer gone is an error, not SIGPIPE */
    signal(SIGPIPE, SIG_IGN);
    TEST_RUN(test_bad_peers);
    return TEST_EXIT();
}
