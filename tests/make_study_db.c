/* make_study_db KIND FILE [SEED]: writes a synthetic study database for the
 * command-line tests.  KIND: hand, random, failed (see study_db.h).
 * make_study_db exec FILE SQL: runs SQL on an existing database (the tests
 * tamper with one this way, without needing the sqlite3 shell). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "study_db.h"

static int exec_sql(const char *file, const char *sql)
{
    sqlite3 *db = NULL;
    int rc = sqlite3_open_v2(file, &db, SQLITE_OPEN_READWRITE, NULL) == SQLITE_OK
                 ? sdb_exec(db, "%s", sql)
                 : (fprintf(stderr, "%s: %s\n", file, sqlite3_errmsg(db)), -1);
    sqlite3_close(db);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: make_study_db hand|random|failed FILE [SEED]\n"
                        "       make_study_db exec FILE SQL\n");
        return 2;
    }
    const char *kind = argv[1], *file = argv[2];
    unsigned long long seed = argc > 3 ? strtoull(argv[3], NULL, 10) : 1;
    if (strcmp(kind, "exec") == 0)
        return argc == 4 && exec_sql(file, argv[3]) == 0 ? 0 : 1;
    int rc = strcmp(kind, "hand") == 0     ? sdb_hand(file)
             : strcmp(kind, "random") == 0 ? sdb_random(file, seed)
             : strcmp(kind, "failed") == 0 ? sdb_only_failed(file)
                                           : (fprintf(stderr, "unknown kind '%s'\n", kind), 2);
    return rc ? 1 : 0;
}
