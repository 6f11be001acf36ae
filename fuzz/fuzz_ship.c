/* libFuzzer target: ship files (fw_ship_load), every field checked. */
#include <stdint.h>

#include "fuzz_common.h"
#include "ship/ship.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fw_ship ship;
    fw_error err = {0};
    fw_ship_load(fuzz_write_input("ships-in", data, size), &ship, &err);
    return 0;
}
