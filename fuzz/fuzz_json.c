/* libFuzzer target: the JSON reader (core/json_read.h) and the DNV traffic
 * situation loader on it (scenario/scn_dnv.h).  Each input is parsed and,
 * when it is JSON, walked whole through the reader's accessors: every member
 * and element, every value read as the type it has and as a type it has not
 * (the message path built each time); then loaded as a situation, as
 * `fairway run situation.json` does (own ship c3-mmg). */
#include <stdint.h>
#include <stdlib.h>

#include "core/json_read.h"
#include "fuzz_common.h"
#include "scenario/scn_dnv.h"

static void walk(const fw_jnode *n, int depth)
{
    fw_error err = {0};
    double d;
    const char *s;
    bool b;
    size_t len = 0;
    fw_jnumber(n, -1e300, 1e300, &d, &err);
    fw_jstring(n, &s, &err);
    fw_jbool(n, &b, &err);
    if (fw_jarray(n, 0, &len, &err) == FW_OK) {
        for (size_t i = 0; i < len; i++) {
            fw_jnode e = fw_jelement(n, i);
            walk(&e, depth + 1);
        }
    }
    if (fw_jkeys(n, &len, &err) == FW_OK) {
        for (size_t i = 0; i < len && i < 64; i++) {
            const char *key;
            fw_jnode m = fw_jkey_at(n, i, &key), again;
            fw_jmember(n, key, true, &again, &err);
            walk(&m, depth + 1);
        }
        static const char *const none[] = {NULL};
        fw_jonly_keys(n, none, &err);
        fw_jmember_number(n, "lat", false, -90, 90, &d, NULL, &err);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fw_scenario *s;
    if (!s && !(s = malloc(sizeof *s)))
        abort();
    fw_jdoc *doc = NULL;
    fw_error err = {0};
    bool parsed = fw_jdoc_parse("fuzz.json", (const char *)data, size, &doc, &err) == FW_OK;
    if (parsed) {
        fw_jnode root = fw_jdoc_root(doc);
        walk(&root, 0);
    }
    fw_jdoc_free(doc);
    if (parsed) { /* JSON: the situation loader reads it as a file */
        fw_error lerr = {0};
        fw_scn_dnv_load(fuzz_write_input("situation-in", data, size), NULL, s, &lerr);
    }
    return 0;
}
