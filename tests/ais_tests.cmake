# AIS data (src/ais): the reader on a file with every kind of bad row, the
# tracks, their replay as a traffic source, and the `fairway ais` command.
fw_test(test_ais test_ais.c)
