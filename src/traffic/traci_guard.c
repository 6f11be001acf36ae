/* traci_guard.c - the checking relay between libtraci and a SUMO peer (see
 * traci_guard.h). */
#include "traffic/traci_guard.h"

#include <errno.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "core/clock.h"

struct fw_traci_guard {
    fw_traci_guard_def def;
    char host[256];
    int listen_fd, lib_fd, peer_fd;
    int stop[2];             /* a byte written to stop[1] ends the thread */
    pthread_t thread;
    bool running;
    pthread_mutex_t lock;
    char reason[256];        /* under lock */
    /* the relay's reading of the peer's stream */
    unsigned char hdr[4];
    int hdr_n;               /* bytes of the current length prefix read */
    uint32_t remaining;      /* bytes of the current message still to pass on */
    bool awaiting;           /* a request went out and its answer is not complete */
    double deadline;         /* s (fw_clock_s), while awaiting */
};

static void set_reason(fw_traci_guard *g, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

static void set_reason(fw_traci_guard *g, const char *fmt, ...)
{
    va_list ap;
    pthread_mutex_lock(&g->lock);
    if (!g->reason[0]) {
        va_start(ap, fmt);
        vsnprintf(g->reason, sizeof g->reason, fmt, ap);
        va_end(ap);
        fprintf(stderr, "fairway: SUMO at %s:%d: %s; the connection is closed\n", g->host,
                g->def.port, g->reason);
    }
    pthread_mutex_unlock(&g->lock);
}

const char *fw_traci_guard_reason(const fw_traci_guard *g)
{
    /* the thread writes it once, before it closes the connection whose
     * failure makes a caller ask */
    fw_traci_guard *m = (fw_traci_guard *)g;
    pthread_mutex_lock(&m->lock);
    const char *r = g->reason;
    pthread_mutex_unlock(&m->lock);
    return r;
}

/* Non-blocking, and without Nagle's delay: TraCI is small requests and
 * answers, each waited for. */
static int nonblocking(int fd)
{
    int fl = fcntl(fd, F_GETFL), one = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    return fl < 0 ? -1 : fcntl(fd, F_SETFL, fl | O_NONBLOCK);
}

/* Milliseconds until t (fw_clock_s), at least 0. */
static int ms_until(double t)
{
    double ms = (t - fw_clock_s()) * 1000.0;
    return ms <= 0.0 ? 0 : ms > 1e9 ? 1000000000 : (int)ms + 1;
}

/* Writes all of buf to fd (non-blocking), waiting for room at most until
 * `until` (0: no limit).  false on an error or the time running out. */
static bool write_all(int fd, const unsigned char *buf, size_t n, double until)
{
    while (n > 0) {
        ssize_t k = send(fd, buf, n, MSG_NOSIGNAL);
        if (k > 0) {
            buf += k;
            n -= (size_t)k;
            continue;
        }
        if (k < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
            return false;
        struct pollfd p = {.fd = fd, .events = POLLOUT};
        if (poll(&p, 1, until > 0.0 ? ms_until(until) : -1) == 0)
            return false;
    }
    return true;
}

/* Passes what the peer sent on to libtraci, checking each message's length
 * prefix before any of the message goes on; what was read goes on in one
 * write (two small writes would wait for each other's acknowledgement:
 * Nagle's algorithm, tens of milliseconds a message).  false (reason set) on
 * a length no TraCI message has or when libtraci cannot take it. */
static bool from_peer(fw_traci_guard *g, const unsigned char *b, size_t n)
{
    unsigned char out[65536 + 4];
    size_t m = 0;
    while (n > 0) {
        if (g->remaining == 0) {
            g->hdr[g->hdr_n++] = *b++;
            n--;
            if (g->hdr_n < 4)
                continue;
            g->hdr_n = 0;
            uint32_t len = (uint32_t)g->hdr[0] << 24 | (uint32_t)g->hdr[1] << 16 |
                           (uint32_t)g->hdr[2] << 8 | g->hdr[3];
            if (len <= 4 || len > FW_TRACI_MAX_MESSAGE) {
                set_reason(g, "it sent a message of %u bytes (a TraCI message is 5 bytes to "
                              "%u MB): not a SUMO, or a broken one", len,
                           FW_TRACI_MAX_MESSAGE >> 20);
                return false;
            }
            g->remaining = len - 4;
            memcpy(out + m, g->hdr, 4);
            m += 4;
            continue;
        }
        size_t k = n < g->remaining ? n : g->remaining;
        memcpy(out + m, b, k);
        m += k;
        b += k;
        n -= k;
        g->remaining -= (uint32_t)k;
        if (g->remaining == 0)
            g->awaiting = false; /* the answer is complete */
    }
    return write_all(g->lib_fd, out, m, 0.0);
}

/* One readable end: read and pass on.  false ends the relay. */
static bool pass(fw_traci_guard *g, bool peer)
{
    unsigned char buf[65536];
    ssize_t k = recv(peer ? g->peer_fd : g->lib_fd, buf, sizeof buf, 0);
    if (k < 0)
        return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
    double timeout = g->def.reply_timeout;
    if (k == 0) {
        if (peer && (g->awaiting || g->remaining || g->hdr_n))
            set_reason(g, "it closed the connection before answering");
        return false; /* libtraci closed: the run is over */
    }
    if (!peer) {
        if (!write_all(g->peer_fd, buf, (size_t)k, timeout > 0.0 ? fw_clock_s() + timeout : 0.0)) {
            set_reason(g, "it does not take fairway's requests");
            return false;
        }
        g->awaiting = true;
        g->deadline = fw_clock_s() + timeout;
        return true;
    }
    g->deadline = fw_clock_s() + timeout; /* progress */
    return from_peer(g, buf, (size_t)k);
}

static void relay(fw_traci_guard *g)
{
    for (;;) {
        struct pollfd p[3] = {{.fd = g->lib_fd, .events = POLLIN},
                              {.fd = g->peer_fd, .events = POLLIN},
                              {.fd = g->stop[0], .events = POLLIN}};
        bool timed = g->awaiting && g->def.reply_timeout > 0.0;
        int r = poll(p, 3, timed ? ms_until(g->deadline) : -1);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0 || p[2].revents)
            return;
        if (r == 0) {
            set_reason(g, "no answer for %g s (the reply timeout)", g->def.reply_timeout);
            return;
        }
        if ((p[0].revents & (POLLIN | POLLHUP | POLLERR)) && !pass(g, false))
            return;
        if ((p[1].revents & (POLLIN | POLLHUP | POLLERR)) && !pass(g, true))
            return;
    }
}

static void *thread_main(void *arg)
{
    fw_traci_guard *g = arg;
    struct pollfd p[2] = {{.fd = g->listen_fd, .events = POLLIN},
                          {.fd = g->stop[0], .events = POLLIN}};
    while (poll(p, 2, -1) < 0 && errno == EINTR)
        ;
    if (!p[1].revents && (p[0].revents & POLLIN)) {
        g->lib_fd = accept(g->listen_fd, NULL, NULL);
        if (g->lib_fd >= 0 && nonblocking(g->lib_fd) == 0)
            relay(g);
    }
    /* both ends closed: libtraci sees the connection gone and throws */
    if (g->lib_fd >= 0)
        shutdown(g->lib_fd, SHUT_RDWR);
    shutdown(g->peer_fd, SHUT_RDWR);
    return NULL;
}

/* A non-blocking connect to host:port within timeout s. */
static fw_status connect_peer(fw_traci_guard *g, fw_error *err)
{
    struct addrinfo hints = {.ai_family = AF_UNSPEC, .ai_socktype = SOCK_STREAM}, *ai = NULL;
    char port[16];
    snprintf(port, sizeof port, "%d", g->def.port);
    int rc = getaddrinfo(g->host, port, &hints, &ai);
    if (rc)
        return fw_fail(err, FW_ERUN, "%s: %s", g->host, gai_strerror(rc));
    int e = 0;
    double until = fw_clock_s() + g->def.connect_timeout;
    for (struct addrinfo *a = ai; a && g->peer_fd < 0; a = a->ai_next) {
        int fd = socket(a->ai_family, a->ai_socktype, a->ai_protocol);
        if (fd < 0 || nonblocking(fd)) {
            e = errno;
            if (fd >= 0)
                close(fd);
            continue;
        }
        if (connect(fd, a->ai_addr, a->ai_addrlen) != 0 && errno == EINPROGRESS) {
            struct pollfd p = {.fd = fd, .events = POLLOUT};
            socklen_t len = sizeof e;
            e = poll(&p, 1, ms_until(until)) == 1 &&
                        getsockopt(fd, SOL_SOCKET, SO_ERROR, &e, &len) == 0
                    ? e
                    : ETIMEDOUT;
        } else {
            e = errno == EINPROGRESS ? 0 : errno;
        }
        if (e == 0)
            g->peer_fd = fd;
        else
            close(fd);
    }
    freeaddrinfo(ai);
    if (g->peer_fd < 0)
        return fw_fail(err, FW_ERUN, "%s:%d: %s", g->host, g->def.port,
                       e == ETIMEDOUT ? "no answer within the connect timeout" : strerror(e));
    return FW_OK;
}

/* The loopback port libtraci connects to. */
static fw_status listen_local(fw_traci_guard *g, int *port, fw_error *err)
{
    struct sockaddr_in a = {.sin_family = AF_INET, .sin_addr.s_addr = htonl(INADDR_LOOPBACK)};
    socklen_t len = sizeof a;
    g->listen_fd = socket(AF_INET, SOCK_STREAM, 0);
    if (g->listen_fd < 0 || bind(g->listen_fd, (struct sockaddr *)&a, sizeof a) != 0 ||
        listen(g->listen_fd, 1) != 0 ||
        getsockname(g->listen_fd, (struct sockaddr *)&a, &len) != 0)
        return fw_fail(err, FW_ERUN, "cannot listen on the loopback interface: %s",
                       strerror(errno));
    *port = ntohs(a.sin_port);
    return FW_OK;
}

fw_status fw_traci_guard_start(const fw_traci_guard_def *def, fw_traci_guard **out,
                               int *local_port, fw_error *err)
{
    *out = NULL;
    fw_traci_guard *g = calloc(1, sizeof *g);
    if (!g)
        return fw_fail(err, FW_ERUN, "out of memory");
    g->def = *def;
    snprintf(g->host, sizeof g->host, "%s", def->host ? def->host : "localhost");
    g->listen_fd = g->lib_fd = g->peer_fd = g->stop[0] = g->stop[1] = -1;
    pthread_mutex_init(&g->lock, NULL);
    fw_status st;
    if (pipe(g->stop) != 0) {
        st = fw_fail(err, FW_ERUN, "cannot make a pipe: %s", strerror(errno));
    } else if (!(st = connect_peer(g, err)) && !(st = listen_local(g, local_port, err))) {
        if (pthread_create(&g->thread, NULL, thread_main, g) != 0)
            st = fw_fail(err, FW_ERUN, "cannot start the relay's thread");
        else
            g->running = true;
    }
    if (st) {
        fw_traci_guard_stop(g);
        return st;
    }
    *out = g;
    return FW_OK;
}

void fw_traci_guard_stop(fw_traci_guard *g)
{
    if (!g)
        return;
    if (g->running) {
        ssize_t k = write(g->stop[1], "x", 1);
        (void)k; /* a full pipe already says stop */
        pthread_join(g->thread, NULL);
    }
    int fds[] = {g->listen_fd, g->lib_fd, g->peer_fd, g->stop[0], g->stop[1]};
    for (size_t i = 0; i < sizeof fds / sizeof fds[0]; i++)
        if (fds[i] >= 0)
            close(fds[i]);
    pthread_mutex_destroy(&g->lock);
    free(g);
}
