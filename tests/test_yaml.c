/* YAML tree: line numbers and every kind of field error. */
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "test.h"
#include "yaml/yaml_edit.h"
#include "yaml/yaml_tree.h"

static const char *doc_text = "a: 1.5\n"
                              "b:\n"
                              "  c: 2\n"
                              "  d: [1, 2, 3]\n"
                              "e: hello\n"
                              "f: .nan\n"
                              "g: 12abc\n"
                              "h: '3'\n"
                              "i: 80.000001\n"
                              "j: 0300\n";

static void test_lines_and_values(void)
{
    fw_error err = {0};
    yt_doc *doc;
    CHECK(yt_load_string(doc_text, "t.yaml", &doc, &err) == FW_OK);
    const yt_node *b = yt_get(doc->root, "b");
    CHECK(b && b->kind == YT_MAP);
    CHECK(yt_key_line(doc->root, "e") == 5);
    CHECK(yt_key_line(b, "d") == 4);
    double v = 0;
    CHECK(yt_req_number(doc, doc->root, "", "a", 0, 10, &v, &err) == FW_OK);
    CHECK_NEAR(v, 1.5, 0);
    CHECK(yt_req_number(doc, b, "b", "c", 0, 10, &v, &err) == FW_OK);
    CHECK_NEAR(v, 2, 0);
    const yt_node *d;
    CHECK(yt_req_seq(doc, b, "b", "d", &d, &err) == FW_OK);
    CHECK(d && d->n == 3);
    yt_free(doc);
}

static void test_errors(void)
{
    fw_error err = {0};
    yt_doc *doc;
    CHECK(yt_load_string(doc_text, "t.yaml", &doc, &err) == FW_OK);
    double v;
    CHECK(yt_req_number(doc, doc->root, "", "f", -1e9, 1e9, &v, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.yaml:6: f:");
    CHECK(yt_req_number(doc, doc->root, "", "g", -1e9, 1e9, &v, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.yaml:7: g: '12abc' is not a number");
    CHECK(yt_req_number(doc, doc->root, "", "h", -1e9, 1e9, &v, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "expected a number");
    CHECK(yt_req_number(doc, doc->root, "", "a", 2, 3, &v, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.yaml:1: a: 1.5 is out of range");
    /* the number as the file has it: %g said "80 is out of range [-80, 80]" */
    CHECK(yt_req_number(doc, doc->root, "", "i", -80, 80, &v, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.yaml:9: i: 80.000001 is out of range [-80, 80]");
    long k;
    CHECK(yt_req_int(doc, doc->root, "", "j", 0, 100, &k, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.yaml:10: j: 0300 is out of range [0, 100]");
    CHECK(yt_req_number(doc, doc->root, "", "zz", 0, 1, &v, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "zz: required field is missing");
    const yt_node *b = yt_get(doc->root, "b");
    CHECK(yt_req_number(doc, b, "b", "d", 0, 1, &v, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.yaml:4: b.d: expected a number");
    static const char *const allowed[] = {"a", "b", "e", "f", "g", "i", "j", NULL};
    CHECK(yt_check_keys(doc, doc->root, "", allowed, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.yaml:8: h: unknown field");
    yt_free(doc);

    CHECK(yt_load_string("a: 1\na: 2\n", "dup.yaml", &doc, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "dup.yaml:2: a: duplicate key");
    CHECK(yt_load_string("a: [1, 2\nb: 3\n", "syn.yaml", &doc, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "syn.yaml:");
    CHECK(yt_load_string("- 1\n- 2\n", "list.yaml", &doc, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "top level must be a mapping");
    CHECK(yt_load_string("", "empty.yaml", &doc, &err) == FW_EINPUT);
    CHECK(yt_load_file("/nonexistent/x.yaml", &doc, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "cannot open");
}

/* 50,000 levels of '[' or of mappings: a located error, not a stack overflow. */
static void test_deep_nesting(void)
{
    enum { N = 50000 };
    char *t = malloc(4 * N + 16); /* "{a: " per level */
    CHECK(t != NULL);
    if (!t)
        return;
    size_t k = (size_t)sprintf(t, "a: ");
    for (int i = 0; i < N; i++)
        t[k++] = '[';
    t[k] = '\0';
    fw_error err = {0};
    yt_doc *doc = NULL;
    CHECK(yt_load_string(t, "deep.yaml", &doc, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "deep.yaml:1: nested deeper than 64 levels");
    k = (size_t)sprintf(t, "a: ");
    for (int i = 0; i < N; i++)
        k += (size_t)sprintf(t + k, "{a: ");
    CHECK(yt_load_string(t, "deepmap.yaml", &doc, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "deepmap.yaml:1: nested deeper than 64 levels");
    /* what fairway's files need stays accepted */
    CHECK(yt_load_string("a: [[[[1]]]]\nb: {c: {d: {e: 1}}}\n", "ok.yaml", &doc, &err) == FW_OK);
    yt_free(doc);
    free(t);
}

/* A ship-like file with the given line break after every line. */
static char *sample(const char *brk)
{
    static const char *const lines[] = {"# header", "hull:", "  N_r: -0.05  # old",
                                        "  N_vvv: 0.1", "nomoto:", "  a: 1", "", "tail: 3"};
    char *t = malloc(512);
    size_t k = 0;
    for (size_t i = 0; t && i < sizeof lines / sizeof lines[0]; i++)
        k += (size_t)sprintf(t + k, "%s%s", lines[i], brk);
    return t;
}

/* LF, CRLF, bare CR and NEL: the editor's lines are libyaml's lines. */
static void test_edit_line_breaks(void)
{
    static const char *const brks[] = {"\n", "\r\n", "\r", "\xc2\x85"};
    for (int b = 0; b < 4; b++) {
        char *t = sample(brks[b]);
        fw_error err = {0};
        fw_yaml_edit *ed = NULL;
        CHECK(fw_yaml_edit_open_text(t, strlen(t), "s.yaml", &ed, &err) == FW_OK);
        CHECK_MSG(fw_yaml_edit_scalar(ed, "hull", "N_r", "-0.08", "was -0.05", &err) == FW_OK,
                  "%d: %s", b, err.msg);
        CHECK(fw_yaml_edit_block(ed, "nomoto", "nomoto:\n  b: 2\n", &err) == FW_OK);
        CHECK(fw_yaml_edit_comment_block(ed, "cal", "# note\n", &err) == FW_OK);
        const char *out = fw_yaml_edit_text(ed, NULL);
        yt_doc *doc = NULL;
        CHECK(yt_load_string(out, "o.yaml", &doc, &err) == FW_OK);
        if (doc) {
            const yt_node *hull = yt_get(doc->root, "hull");
            CHECK(strcmp(yt_get(hull, "N_r")->str, "-0.08") == 0);
            CHECK(strcmp(yt_get(hull, "N_vvv")->str, "0.1") == 0);
            CHECK(strcmp(yt_get(yt_get(doc->root, "nomoto"), "b")->str, "2") == 0);
            CHECK(strcmp(yt_get(doc->root, "tail")->str, "3") == 0);
            yt_free(doc);
        }
        /* the file's own line break is kept, none is added */
        char want[64];
        snprintf(want, sizeof want, "  N_r: -0.08  # was -0.05%s  N_vvv", brks[b]);
        CHECK_MSG(strstr(out, want) != NULL, "%d: %s", b, out);
        if (b != 0)
            CHECK(strchr(out, '\n') == NULL || b == 1);
        fw_yaml_edit_free(ed);
        free(t);
    }
}

/* An edit the line editor cannot make exactly is refused, the file untouched. */
static void test_edit_refused(void)
{
    char dir[] = "/tmp/fw-yaml-edit.XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char path[64];
    snprintf(path, sizeof path, "%s/s.yaml", dir);
    const char *text = "hull: {N_r: -0.05, N_v: 1}\nx:\n  y:\n    -0.1\n";
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    fw_error err = {0};
    CHECK(fw_yaml_set_scalar(path, "hull", "N_r", "-0.08", NULL, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "cannot edit");
    CHECK(fw_yaml_set_scalar(path, "x", "y", "1", NULL, &err) == FW_EINPUT);
    CHECK(fw_yaml_set_scalar(path, "hull", "nope", "1", NULL, &err) == FW_EINPUT);
    char buf[256] = "";
    f = fopen(path, "r");
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    CHECK(strcmp(buf, text) == 0);
    /* a check that fails leaves the target as it was and no temporary file */
    char out[64];
    snprintf(out, sizeof out, "%s/out.yaml", dir);
    fw_yaml_edit *ed = NULL;
    CHECK(fw_yaml_edit_open(path, &ed, &err) == FW_OK);
    CHECK(fw_yaml_edit_save(ed, dir, NULL, NULL, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "is a directory");
    CHECK(fw_yaml_edit_save(ed, out, NULL, NULL, &err) == FW_OK);
    struct stat sb;
    CHECK(stat(out, &sb) == 0 && (size_t)sb.st_size == strlen(text));
    fw_yaml_edit_free(ed);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "test $(ls -A %s | wc -l) -eq 2 && rm -rf %s", dir, dir);
    CHECK(system(cmd) == 0);
}

int main(void)
{
    TEST_RUN(test_lines_and_values);
    TEST_RUN(test_errors);
    TEST_RUN(test_deep_nesting);
    TEST_RUN(test_edit_line_breaks);
    TEST_RUN(test_edit_refused);
    return TEST_EXIT();
}
