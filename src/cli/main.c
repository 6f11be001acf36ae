/* fairway - ship traffic safety studies: MMG own ship, Nomoto avoidance, SUMO traffic. */
#include <stdio.h>
#include <string.h>

#include "cli/args.h"
#include "cli/commands.h"

typedef struct command {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} command;

static const command commands[] = {
    {"manoeuvre", fw_cmd_manoeuvre, "standard manoeuvres (turning circle, zig-zag) with IMO verdicts"},
    {"calibrate", fw_cmd_calibrate, "fit named MMG coefficients of a ship to its sea trial"},
    {"identify", fw_cmd_identify, "Nomoto indices and their regression from MMG turning tests"},
    {"helm", fw_cmd_helm, "one avoidance decision (Nomoto helm search) for an own ship and targets"},
    {"traffic", fw_cmd_traffic, "run SUMO background traffic around a straight-running own ship"},
    {"run", fw_cmd_run, "run scenarios: SUMO traffic, MMG own ship, avoidance, full records"},
    {"sweep", fw_cmd_sweep, "Monte Carlo study: every run of a study file into a SQLite database"},
    {"report", fw_cmd_report, "statistics, tables, plots and a summary of a study database"},
    {"worst", fw_cmd_worst, "a study's closest encounters as scenarios that replay them"},
    {"situation", fw_cmd_situation, "scenarios written as DNV traffic situations"},
    {"ais", fw_cmd_ais, "AIS files: summary, tracks in the plane, a network's demand from them"},
    {"ship", fw_cmd_ship, "check a ship file and print its particulars"},
};

static void usage(FILE *out)
{
    fprintf(out,
            "usage: fairway COMMAND [OPTIONS]\n"
            "\n"
            "Maritime traffic safety studies: the own ship stepped with the MMG model\n"
            "(integrated by SUNDIALS ARKODE), Nomoto-based collision avoidance, SUMO traffic.\n"
            "\n"
            "commands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(out, "  %-12s %s\n", commands[i].name, commands[i].summary);
    fprintf(out,
            "\n"
            "'fairway COMMAND --help' describes each command.\n"
            "Exit codes: 0 ok, 1 a run failed, 2 bad input.\n"
            "Units at the interface: knots, degrees, nautical miles; metres east/north.\n"
            "Data files (ships, scenarios, networks) are looked up under $FAIRWAY_DATA;\n"
            "without it, an installed fairway (PREFIX/bin/fairway) uses PREFIX/share/fairway,\n"
            "a fairway in its build tree the source tree it was built from.\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (fw_is_help(argv[1])) {
        usage(stdout);
        return 0;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("fairway 0.1.0\n");
        return 0;
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (strcmp(argv[1], commands[i].name) == 0)
            return commands[i].run(argc - 2, argv + 2);
    fprintf(stderr, "fairway: unknown command '%s' (see fairway --help)\n", argv[1]);
    return 2;
}
