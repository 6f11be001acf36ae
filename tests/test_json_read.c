/* test_json_read.c - the JSON reader (core/json_read.h): values read through
 * their paths, every problem named "FILE: $.path: problem" with FW_EINPUT,
 * text that is not JSON named by line and column, and inputs built to exhaust
 * memory or the stack (deep nesting, a 50 MB file of nested arrays) refused
 * with a message.  DNV's baseline situations (scenarios/dnv/) parse. */
#include <stdlib.h>
#include <unistd.h>

#include "core/json_read.h"
#include "test.h"

static fw_jdoc *parse(const char *text, fw_error *err)
{
    fw_jdoc *d = NULL;
    fw_jdoc_parse("t.json", text, strlen(text), &d, err);
    return d;
}

static void reads_values_by_path(void)
{
    fw_error err = {0};
    fw_jdoc *d = parse("{\"ownShip\": {\"waypoints\": [{\"position\": {\"lat\": 58.5, \"lon\": 10}}],"
                       " \"name\": \"BASTO VI\", \"ok\": true}}", &err);
    CHECK(d != NULL);
    if (!d)
        return;
    fw_jnode root = fw_jdoc_root(d), own, wps, pos;
    CHECK(fw_jmember(&root, "ownShip", true, &own, &err) == FW_OK);
    CHECK(fw_jmember(&own, "waypoints", true, &wps, &err) == FW_OK);
    size_t n = 0;
    CHECK(fw_jarray(&wps, 1, &n, &err) == FW_OK && n == 1);
    fw_jnode w0 = fw_jelement(&wps, 0);
    CHECK(fw_jmember(&w0, "position", true, &pos, &err) == FW_OK);
    CHECK(strcmp(pos.path, "$.ownShip.waypoints[0].position") == 0);
    double lat = 0, lon = 0;
    CHECK(fw_jmember_number(&pos, "lat", true, -90, 90, &lat, NULL, &err) == FW_OK);
    CHECK(fw_jmember_number(&pos, "lon", true, -180, 180, &lon, NULL, &err) == FW_OK);
    CHECK_NEAR(lat, 58.5, 0);
    CHECK_NEAR(lon, 10, 0); /* an integer is a number */
    const char *name = NULL;
    CHECK(fw_jmember_string(&own, "name", true, &name, &err) == FW_OK && strcmp(name, "BASTO VI") == 0);
    bool present = true;
    double sog = 7;
    CHECK(fw_jmember_number(&pos, "sog", false, 0, 100, &sog, &present, &err) == FW_OK);
    CHECK(!present && sog == 7);
    size_t nk = 0;
    const char *key = NULL;
    CHECK(fw_jkeys(&own, &nk, &err) == FW_OK && nk == 3);
    fw_jnode k2 = fw_jkey_at(&own, 2, &key);
    CHECK(strcmp(key, "ok") == 0 && fw_jnode_type(&k2) == FW_J_BOOL);
    static const char *const known[] = {"waypoints", "name", NULL};
    CHECK(fw_jonly_keys(&own, known, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.json: $.ownShip.ok: unknown key");
    fw_jdoc_free(d);
}

static void names_each_problem(void)
{
    fw_error err = {0};
    fw_jdoc *d = parse("{\"targetShips\": [{}, {\"waypoints\": [{\"position\": {\"lat\": 95, \"lon\": \"x\"}}]}],"
                       " \"odd key\": 1}", &err);
    CHECK(d != NULL);
    if (!d)
        return;
    fw_jnode root = fw_jdoc_root(d), ts, pos, m;
    size_t n = 0;
    CHECK(fw_jmember(&root, "targetShips", true, &ts, &err) == FW_OK && fw_jarray(&ts, 1, &n, &err) == FW_OK);
    fw_jnode t1 = fw_jelement(&ts, 1), t0 = fw_jelement(&ts, 0), wps;
    CHECK(fw_jmember(&t0, "waypoints", true, &wps, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.json: $.targetShips[0].waypoints: missing");
    CHECK(fw_jmember(&t1, "waypoints", true, &wps, &err) == FW_OK);
    fw_jnode w0 = fw_jelement(&wps, 0);
    CHECK(fw_jmember(&w0, "position", true, &pos, &err) == FW_OK);
    double v = 0;
    CHECK(fw_jmember_number(&pos, "lat", true, -90, 90, &v, NULL, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.json: $.targetShips[1].waypoints[0].position.lat: 95 is not in [-90, 90]");
    CHECK(err.status == FW_EINPUT);
    CHECK(fw_jmember_number(&pos, "lon", true, -180, 180, &v, NULL, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "$.targetShips[1].waypoints[0].position.lon: must be a number, not a string");
    CHECK(fw_jarray(&pos, 0, &n, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "position: must be an array, not an object");
    CHECK(fw_jmember(&root, "odd key", true, &m, &err) == FW_OK);
    CHECK(fw_jnumber(&m, 2, 3, &v, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.json: $['odd key']: 1 is not in [2, 3]");
    CHECK(fw_jmember(&ts, "x", false, &m, &err) == FW_EINPUT); /* an array has no members */
    CHECK_CONTAINS(err.msg, "$.targetShips: must be an object, not an array");
    fw_jdoc_free(d);
}

static void refuses_text_that_is_not_json(void)
{
    static const char *const bad[] = {"", "{", "{\"a\": 1,}", "{\"a\": 1, \"a\": 2}", "[1e999]",
                                      "{\"a\": NaN}", "\"\\u0000\"", "{\"a\": 1}\n}"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fw_error err = {0};
        fw_jdoc *d = parse(bad[i], &err);
        CHECK_MSG(d == NULL && err.status == FW_EINPUT, "'%s' accepted", bad[i]);
        CHECK_CONTAINS(err.msg, "t.json:");
        /* a bare string is JSON but no document of fairway's: not JSON here */
        CHECK_MSG(strstr(err.msg, "invalid JSON") || strstr(err.msg, "not JSON"), "%s", err.msg);
        fw_jdoc_free(d);
    }
    /* a file of another kind is named, never quoted (issue 28: a situation
     * given /etc/shadow printed "near 'root'") */
    static const char *const foreign[] = {"root:*:20228:0:99999:7:::\n", "\n  secret {\n",
                                          "# Timestamp,MMSI\n"};
    for (size_t i = 0; i < sizeof foreign / sizeof foreign[0]; i++) {
        fw_error e = {0};
        CHECK(parse(foreign[i], &e) == NULL && e.status == FW_EINPUT);
        CHECK_CONTAINS(e.msg, "not JSON: it does not begin with '{' or '['");
        CHECK_MSG(!strstr(e.msg, "root") && !strstr(e.msg, "secret") && !strstr(e.msg, "Timestamp"),
                  "quoted: %s", e.msg);
    }
    fw_error e2 = {0};
    CHECK(parse("\n  secret {\n", &e2) == NULL);
    CHECK_CONTAINS(e2.msg, "t.json:2: $: not JSON");
    fw_error err = {0};
    CHECK(parse("{\n  \"a\": [1,\n 2 x]}", &err) == NULL);
    CHECK_CONTAINS(err.msg, "t.json:3: $: invalid JSON:");
}

/* Nesting is bounded by the parser (no stack overflow); a file bigger than
 * FW_JSON_MAX_BYTES is refused before it is parsed (no memory exhaustion). */
static void refuses_inputs_built_to_exhaust(void)
{
    size_t n = 100000;
    char *deep = malloc(2 * n + 1);
    memset(deep, '[', n);
    memset(deep + n, ']', n);
    deep[2 * n] = '\0';
    fw_error err = {0};
    CHECK(parse(deep, &err) == NULL && err.status == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "depth");
    free(deep);

    char path[] = "/tmp/fairway-json-XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    if (fd < 0)
        return;
    FILE *f = fdopen(fd, "w");
    static char block[1 << 16];
    for (size_t i = 0; i < sizeof block; i += 2)
        block[i] = '[', block[i + 1] = i % 64 == 62 ? ']' : '[';
    for (int i = 0; i < 800; i++) /* 52 MB */
        fwrite(block, 1, sizeof block, f);
    fclose(f);
    fw_jdoc *d = NULL;
    CHECK(fw_jdoc_load(path, &d, &err) == FW_EINPUT && d == NULL);
    CHECK_CONTAINS(err.msg, path);
    CHECK_CONTAINS(err.msg, "$: more than 8388608 bytes");
    unlink(path);
    CHECK(fw_jdoc_load("/nonexistent/x.json", &d, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "/nonexistent/x.json: cannot open");
}

static void reads_dnv_baseline_situations(void)
{
    const char *data = getenv("FAIRWAY_DATA");
    for (int i = 1; i <= 5; i++) {
        char path[512];
        snprintf(path, sizeof path, "%s/scenarios/dnv/traffic_situation_%02d.json", data ? data : ".", i);
        fw_jdoc *d = NULL;
        fw_error err = {0};
        CHECK_MSG(fw_jdoc_load(path, &d, &err) == FW_OK, "%s", err.msg);
        if (!d)
            continue;
        fw_jnode root = fw_jdoc_root(d), own, wps;
        const char *version = NULL;
        CHECK(fw_jmember_string(&root, "schemaVersion", true, &version, &err) == FW_OK);
        CHECK(version && strcmp(version, "0.2.0") == 0);
        size_t n = 0;
        CHECK(fw_jmember(&root, "ownShip", true, &own, &err) == FW_OK);
        CHECK(fw_jmember(&own, "waypoints", true, &wps, &err) == FW_OK && fw_jarray(&wps, 2, &n, &err) == FW_OK);
        fw_jdoc_free(d);
    }
}

int main(void)
{
    TEST_RUN(reads_values_by_path);
    TEST_RUN(names_each_problem);
    TEST_RUN(refuses_text_that_is_not_json);
    TEST_RUN(refuses_inputs_built_to_exhaust);
    TEST_RUN(reads_dnv_baseline_situations);
    return TEST_EXIT();
}
