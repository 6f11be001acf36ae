/* fairway ship NAME: load and check a ship file, print what it holds. */
#include <stdio.h>

#include "cli/args.h"
#include "cli/commands.h"
#include "core/units.h"
#include "ship/ship.h"

static void help(void)
{
    printf("usage: fairway ship NAME|FILE\n"
           "\n"
           "Loads a ship file (scenarios/ships/NAME.yaml under the data root, or a path),\n"
           "checks every field and prints the main particulars.  Errors name the file,\n"
           "line and field and exit with code 2.\n");
}

int fw_cmd_ship(int argc, char **argv)
{
    if (argc < 1 || fw_is_help(argv[0])) {
        help();
        return argc < 1 ? 2 : 0;
    }
    fw_error err = {0};
    if (argc > 1)
        return fw_report((fw_fail(&err, FW_EINPUT, "ship: one ship at a time (unexpected '%s')",
                                  argv[1]), &err));
    fw_ship ship;
    if (fw_ship_load(argv[0], &ship, &err))
        return fw_report(&err);
    printf("ship %s (%s)\n", ship.name, ship.file);
    printf("  L %.1f m, Loa %.1f m, B %.1f m, d %.2f m, Cb %.3f\n", ship.L, ship.Loa, ship.B,
           ship.d, ship.Cb);
    printf("  displacement %.0f m^3 (%.0f t)\n", ship.volume, fw_ship_mass(&ship) / 1000.0);
    printf("  rudder: max %.0f deg, rate %.2f deg/s, area %.1f m^2\n",
           fw_rad_to_deg(ship.rudder_max), fw_rad_to_deg(ship.rudder_rate), ship.A_R);
    printf("  Nomoto knowledge base: %s\n", ship.nomoto.present ? "yes" : "no");
    return 0;
}
