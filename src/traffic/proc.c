/* proc.c - a free TCP port for a sumo started here (gui mode, tests); the
 * child itself is started with core/spawn.h. */
#include <errno.h>
#include <netinet/in.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "traffic/traffic.h"

fw_status fw_traffic_free_port(int *port, fw_error *err)
{
    int s = socket(AF_INET, SOCK_STREAM, 0);
    if (s < 0)
        return fw_fail(err, FW_ERUN, "cannot open a socket: %s", strerror(errno));
    struct sockaddr_in a;
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = 0; /* the kernel picks an unused port */
    socklen_t len = sizeof a;
    if (bind(s, (struct sockaddr *)&a, sizeof a) != 0 ||
        getsockname(s, (struct sockaddr *)&a, &len) != 0) {
        int e = errno;
        close(s);
        return fw_fail(err, FW_ERUN, "cannot find a free port: %s", strerror(e));
    }
    *port = ntohs(a.sin_port);
    close(s);
    return FW_OK;
}
