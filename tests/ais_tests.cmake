# AIS data (src/ais): the reader on a file with every kind of bad row, the
# tracks, their replay as a traffic source, and the `fairway ais` command.
fw_test(test_ais test_ais.c)
fw_test(test_ais_demand test_ais_demand.c)
target_link_libraries(test_ais_demand PRIVATE fairway_run)
set_tests_properties(test_ais_demand PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

# The command: help, bad input (exit 2, FILE:LINE), and the whole workflow of
# scenarios/ais/README.md (summary, tracks, demand run by SUMO, the replay).
fw_cli_test(cli_ais_help 0 "usage: fairway ais summary FILE" ais --help)
fw_cli_test(cli_ais_bad_sub 2 "ais: 'sumary': expected summary, tracks or demand" ais sumary x.csv)
fw_cli_test(cli_ais_no_origin 2 "--origin LAT,LON: the plane's centre is needed" ais tracks
            ${CMAKE_SOURCE_DIR}/scenarios/ais/aisdk-2026-03-01.csv)
fw_cli_test(cli_ais_bad_columns 2 "--columns: 'speed=SOG': expected FIELD=HEADER NAME" ais summary
            ${CMAKE_SOURCE_DIR}/scenarios/ais/aisdk-2026-03-01.csv --columns speed=SOG)
fw_cli_test(cli_ais_bad_header 2 "bad-rows.csv:1: header: no column 'BaseDateTime' \\(the time\\)" ais
            summary ${CMAKE_SOURCE_DIR}/tests/data/ais/bad-rows.csv --columns time=BaseDateTime)
fw_script_test(ais_workflow 0 "ok: AIS workflow" ais_workflow.sh)
fw_script_test(ais_run_counts 0 "ok: AIS counts in run.log and summary.json" ais_run_counts.sh)
# SUMO flows slower than 3.6 an hour (demand.h FW_SUMO_EXP_RATE_MIN): channel
# at density 0.1 is 0.6 ships an hour per stream, which SUMO's exp() period
# turned into a flood of ships and bad_alloc
fw_cli_test(cli_traffic_slow_flows 0 "median [0-9.]+ ms per step" traffic --network channel
            --density 0.1 --ships 0 --duration 60 --every 60 --log traffic-slow.log
            --routes traffic-slow.rou.xml)
foreach(t cli_ais_help cli_ais_bad_sub cli_ais_no_origin cli_ais_bad_columns cli_ais_bad_header
          ais_workflow ais_run_counts cli_traffic_slow_flows)
  set_tests_properties(${t} PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
endforeach()
