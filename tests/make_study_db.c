/* make_study_db KIND FILE [SEED]: writes a synthetic study database for the
 * command-line tests.  KIND: hand, random, failed (see study_db.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "study_db.h"

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: make_study_db hand|random|failed FILE [SEED]\n");
        return 2;
    }
    const char *kind = argv[1], *file = argv[2];
    unsigned long long seed = argc > 3 ? strtoull(argv[3], NULL, 10) : 1;
    int rc = strcmp(kind, "hand") == 0     ? sdb_hand(file)
             : strcmp(kind, "random") == 0 ? sdb_random(file, seed)
             : strcmp(kind, "failed") == 0 ? sdb_only_failed(file)
                                           : (fprintf(stderr, "unknown kind '%s'\n", kind), 2);
    return rc ? 1 : 0;
}
