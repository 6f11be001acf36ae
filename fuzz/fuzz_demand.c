/* libFuzzer target: network demand files (fw_demand_load), and the route
 * file written from a demand that loaded. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fuzz_common.h"
#include "traffic/demand.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fw_demand d;
    fw_error err = {0};
    const char *path = fuzz_write_input("demand-in", data, size);
    if (fw_demand_load(path, &d, &err) == FW_OK) {
        char rou[600];
        snprintf(rou, sizeof rou, "%.580s.rou.xml", path);
        fw_demand_def def = fw_default_demand_def();
        def.fill = 3;
        def.end = 600;
        fw_demand_write(&d, &def, rou, &err);
        if (fw_demand_rate(&d) < 0)
            __builtin_trap();
    }
    return 0;
}
