/* libFuzzer target: study files (fw_study_load, with the scenario they name,
 * found beside the shipped ones: ../traffic/NAME.yaml). */
#include <stdint.h>
#include <stdlib.h>

#include "fuzz_common.h"
#include "study/study.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fw_study *s;
    if (!s && !(s = malloc(sizeof *s)))
        abort();
    fw_error err = {0};
    if (fw_study_load(fuzz_write_input("studies", data, size), s, &err) == FW_OK) {
        /* the run list of a loaded study is always well formed */
        int n = fw_study_run_count(s);
        if (n <= 0)
            abort();
        fw_study_run r = fw_study_run_at(s, n - 1);
        if (r.domain_index >= s->n_domains || r.density_index >= s->n_densities)
            abort();
    }
    return 0;
}
