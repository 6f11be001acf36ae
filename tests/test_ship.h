/* test_ship.h - a ship file loaded for a test, or the test program stops:
 * every later check needs it. */
#ifndef FW_TEST_SHIP_H
#define FW_TEST_SHIP_H

#include <stdio.h>
#include <stdlib.h>

#include "ship/ship.h"

static inline fw_ship test_load_ship(const char *name)
{
    fw_ship s;
    fw_error err = {0};
    if (fw_ship_load(name, &s, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        exit(1);
    }
    return s;
}

#endif
