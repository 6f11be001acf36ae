/* traci_guard.h - a relay between libtraci and a SUMO peer that checks what
 * the peer sends, so that no byte from the wire can crash or hang fairway.
 *
 * libtraci trusts its peer: a message length of 0 trips an assertion in its
 * socket code (SIGABRT), a length of 2^31 makes it allocate gigabytes, and a
 * peer that accepts and says nothing is waited for for ever.  So libtraci
 * never talks to the peer itself: it connects to this relay on the loopback
 * interface, and a thread of the relay passes libtraci's requests on
 * unchanged and the peer's answers back only after checking each message's
 * length prefix (TraCI: a 4-byte big-endian length that counts itself, then
 * the message): a length of at most 4 bytes or above FW_TRACI_MAX_MESSAGE is
 * refused before anything is allocated for it, and an answer that does not
 * begin within the reply timeout of a request is given up.  Either way the
 * relay records why, closes both connections (libtraci then sees the
 * connection closed and throws, which the back end turns into an error) and
 * says so once on stderr.  fw_traci_guard_reason gives the reason for the
 * caller's message.
 *
 * What it does not check: the content of a message of a valid length
 * (libtraci reads it through bounds-checked storage, which throws).
 */
#ifndef FW_TRACI_GUARD_H
#define FW_TRACI_GUARD_H

#include "core/error.h"

/* The largest TraCI message accepted from a peer: a context subscription of
 * thousands of ships is a few MB. */
#define FW_TRACI_MAX_MESSAGE (64u << 20)

typedef struct fw_traci_guard fw_traci_guard;

typedef struct fw_traci_guard_def {
    const char *host;       /* the peer */
    int port;
    double connect_timeout; /* s, for the relay's connection to the peer */
    double reply_timeout;   /* s, from a request to the start of its answer; 0: none
                               (a sumo-gui the user may pause) */
} fw_traci_guard_def;

/* Connects to the peer and listens on a loopback port (*local_port) for
 * libtraci's one connection.  FW_ERUN when the peer cannot be reached within
 * the connect timeout (connection refused: at once), with the reason. */
fw_status fw_traci_guard_start(const fw_traci_guard_def *def, fw_traci_guard **out,
                               int *local_port, fw_error *err);

/* Why the relay closed the connection ("" while it has not). */
const char *fw_traci_guard_reason(const fw_traci_guard *g);

/* Closes both connections and joins the thread. NULL: nothing. */
void fw_traci_guard_stop(fw_traci_guard *g);

#endif
