/* commands.h - the subcommands of the fairway executable.
 *
 * Each takes the arguments after its name and returns the process exit code:
 * 0 ok, 1 a run failed, 2 bad input.  Each prints its own help for --help.
 */
#ifndef FW_COMMANDS_H
#define FW_COMMANDS_H

int fw_cmd_ship(int argc, char **argv);
int fw_cmd_helm(int argc, char **argv);
int fw_cmd_identify(int argc, char **argv);
int fw_cmd_manoeuvre(int argc, char **argv);
int fw_cmd_calibrate(int argc, char **argv);
int fw_cmd_traffic(int argc, char **argv);
int fw_cmd_run(int argc, char **argv);
int fw_cmd_sweep(int argc, char **argv);
int fw_cmd_report(int argc, char **argv);
int fw_cmd_worst(int argc, char **argv);
int fw_cmd_ais(int argc, char **argv);
int fw_cmd_situation(int argc, char **argv);

#endif
