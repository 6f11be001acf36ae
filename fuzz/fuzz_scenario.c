/* libFuzzer target: scenario files (fw_scenario_load, with their ship). */
#include <stdint.h>
#include <stdlib.h>

#include "fuzz_common.h"
#include "scenario/scenario.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fw_scenario *s;
    if (!s && !(s = malloc(sizeof *s)))
        abort();
    fw_error err = {0};
    fw_scenario_load(fuzz_write_input("scenario-in", data, size), s, &err);
    return 0;
}
