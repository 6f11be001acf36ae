# Command-line behaviour: help, exit codes, one-line errors.
fw_cli_test(cli_help 0 "usage: fairway COMMAND" --help)
fw_cli_test(cli_unknown_command 2 "unknown command" frobnicate)
fw_cli_test(cli_ship_c3 0 "ship c3" ship c3)
fw_cli_test(cli_ship_unknown 2 "unknown ship 'nosuch'" ship nosuch)
