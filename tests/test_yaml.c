/* YAML tree: line numbers and every kind of field error. */
#include "test.h"
#include "yaml/yaml_tree.h"

static const char *doc_text = "a: 1.5\n"
                              "b:\n"
                              "  c: 2\n"
                              "  d: [1, 2, 3]\n"
                              "e: hello\n"
                              "f: .nan\n"
                              "g: 12abc\n"
                              "h: '3'\n";

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
    CHECK(yt_req_number(doc, doc->root, "", "zz", 0, 1, &v, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "zz: required field is missing");
    const yt_node *b = yt_get(doc->root, "b");
    CHECK(yt_req_number(doc, b, "b", "d", 0, 1, &v, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "t.yaml:4: b.d: expected a number");
    static const char *const allowed[] = {"a", "b", "e", "f", "g", NULL};
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

int main(void)
{
    TEST_RUN(test_lines_and_values);
    TEST_RUN(test_errors);
    return TEST_EXIT();
}
