# Scenario runs (src/run, src/scenario, `fairway run`): the paper's five cases
# and the 22 Imazu cases end to end through libsumo, determinism, bad files.
fw_test(test_run test_run.c)
target_link_libraries(test_run PRIVATE fairway_run)
set_tests_properties(test_run PROPERTIES TIMEOUT 180
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

# A run stepped by hand (open, step, close) against fw_run_scenario: the same
# bytes, kinematic and SUMO; closed half way; without a directory.
fw_test(test_run_step test_run_step.c)
target_link_libraries(test_run_step PRIVATE fairway_run)
set_tests_properties(test_run_step PROPERTIES TIMEOUT 120
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

# A DNV situation written from recorded tracks and read back: each target's
# course and speed as recorded (run/dnv_situation.h "turns")
fw_test(test_dnv_motion test_dnv_motion.c)
target_link_libraries(test_dnv_motion PRIVATE fairway_run)
set_tests_properties(test_dnv_motion PROPERTIES TIMEOUT 60
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

# The command: a run with a table row, --json, help, and bad input that leaves
# no output directory behind (run_bad.sh checks the directory).
fw_cli_test(cli_run_paper 0 "paper-3-crossing +[0-9]+ +no +no" run
            ${CMAKE_SOURCE_DIR}/scenarios/paper/3-crossing.yaml --out ${CMAKE_CURRENT_BINARY_DIR}/cli-runs)
fw_cli_test(cli_run_json 0 "\"scenario\": \"imazu-02\", \"status\": \"ok\"" run
            ${CMAKE_SOURCE_DIR}/scenarios/imazu/imazu-02.yaml --out ${CMAKE_CURRENT_BINARY_DIR}/cli-runs --json)
fw_cli_test(cli_run_help 0 "usage: fairway run" run --help)
fw_cli_test(cli_run_none 2 "no scenario given" run)
fw_cli_test(cli_run_bad_mode 2 "expected embedded, gui or remote:HOST:PORT" run x.yaml --sumo tcp)
fw_script_test(cli_run_bad_file 0 "ok: no output" run_bad.sh)
foreach(t cli_run_paper cli_run_json cli_run_help cli_run_none cli_run_bad_mode cli_run_bad_file)
  set_tests_properties(${t} PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 60)
endforeach()

# The environment's fields over time (gusts, the spring-neap tide) and the
# scenario's environment: section (the Dover network's charted stream).
fw_test(test_fields test_fields.c)
target_link_libraries(test_fields PRIVATE fairway_run)
set_tests_properties(test_fields PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

# The world and its traffic sources; a paper case with and without SUMO.
fw_test(test_world test_world.c)
target_link_libraries(test_world PRIVATE fairway_run)
set_tests_properties(test_world PROPERTIES TIMEOUT 120
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

# Hardening (issue 14): an interrupted run cleans up and says what it kept; an
# unresolvable remote host is refused before anything runs
fw_script_test(cli_run_interrupt 0 "ok: interrupted runs cleaned up" run_interrupt.sh)
fw_cli_test(cli_run_bad_host 2 "--sumo remote:no-such-host.invalid:8813: cannot resolve host 'no-such-host.invalid'"
            run ${CMAKE_SOURCE_DIR}/scenarios/paper/1-head-on.yaml --sumo remote:no-such-host.invalid:8813
            --out ${CMAKE_CURRENT_BINARY_DIR}/cli-runs-bad-host)
fw_cli_test(cli_sweep_bad_host 2 "cannot resolve host 'no-such-host.invalid'"
            sweep ${CMAKE_SOURCE_DIR}/tests/data/study/small.yaml --db ${CMAKE_CURRENT_BINARY_DIR}/bad-host.db
            --sumo remote:no-such-host.invalid:8813)
# --profile: where a run's time went, adding up, results unchanged
fw_script_test(cli_run_profile 0 "ok: --profile says where the time went, results unchanged"
               run_profile.sh)
foreach(t cli_run_interrupt cli_run_bad_host cli_sweep_bad_host cli_run_profile)
  set_tests_properties(${t} PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}" TIMEOUT 120)
endforeach()

# Latitude and longitude: the plane against the ellipsoid, a scenario in
# degrees against its twin in metres (loaded, then run: tracks within 0.1 m).
fw_test(test_geo test_geo.c)
target_link_libraries(test_geo PRIVATE fairway_run)
fw_script_test(geo_twin_run 0 "twin runs agree" geo_twin_run.sh)
fw_script_test(geo_targets 0 "geo targets ok" geo_targets.sh)
set_tests_properties(geo_targets PROPERTIES ENVIRONMENT "${fw_lsan}")
# the runs reach SUMO, whose own allocations the LeakSanitizer suppressions cover
set_tests_properties(geo_twin_run PROPERTIES ENVIRONMENT "${fw_lsan}")
fw_script_test(geojson_export 0 "geojson export ok" geojson_export.sh)
set_tests_properties(geojson_export PROPERTIES ENVIRONMENT "${fw_lsan}")
# every SUMO run's sumo/run.sumocfg, and the FCD replayed in SUMO (headless)
fw_script_test(sumo_replay 0 "sumo replay ok" sumo_replay.sh)
set_tests_properties(sumo_replay PROPERTIES ENVIRONMENT "${fw_lsan}")
# run plots: the network's lanes, which ships are named
fw_script_test(plot_run 0 "plot run ok" plot_run.sh)
set_tests_properties(plot_run PROPERTIES ENVIRONMENT "${fw_lsan}")

# Vessels that come and go (world.h handles, roles, take and give back); its
# "sumo" case (a SUMO ship taken and given back) is with the traffic tests.
# the watch under splitting: redrawn detections, the unseen approach
fw_test(test_watch_redraw test_watch_redraw.c)
target_link_libraries(test_watch_redraw PRIVATE fairway_run)
fw_test(test_vessels test_vessels.c)
fw_test(test_steer test_steer.c)
# its look along the swing: the shortcuts against every ship over every sample
fw_test(test_steer_look test_steer_look.c)
target_link_libraries(test_vessels PRIVATE fairway_run)
set_tests_properties(test_vessels PROPERTIES TIMEOUT 60
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
# a SUMO ship given back and taken again in one step starts where it was given back
fw_test(test_retake_sumo test_retake_sumo.c)
target_link_libraries(test_retake_sumo PRIVATE fairway_run)
set_tests_properties(test_retake_sumo PROPERTIES TIMEOUT 90
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

# The reacting background ships decide on what their sensing tells them
# (world/reactions.h "Sensing"): AIS reports (delayed, noisy), radar tracks
fw_test(test_react_sense test_react_sense.c)
target_link_libraries(test_react_sense PRIVATE fairway_run)
set_tests_properties(test_react_sense PROPERTIES TIMEOUT 60
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
# a give-way background ship judges every ship it gives way to (reactions.c)
fw_test(test_react_judge test_react_judge.c)
target_link_libraries(test_react_judge PRIVATE fairway_run)
set_tests_properties(test_react_judge PROPERTIES TIMEOUT 60
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

# Snapshot and restore of a running run (src/run/branch.h): a run of each
# source kind branched at three steps ends byte-identical to the unbranched one
fw_test(test_branch test_branch.c)
target_link_libraries(test_branch PRIVATE fairway_run)
set_tests_properties(test_branch PROPERTIES TIMEOUT 120
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

# The encounter book's COLREGs reading in restricted visibility (run/book.h: rule 19)
fw_test(test_book test_book.c)
target_link_libraries(test_book PRIVATE fairway_run)

# The own ship follows a route (issue 27 item 5): a 30 deg bend within 100 m
# of its line, the return to the route after avoiding, bad routes refused.
fw_test(test_route test_route.c)
target_link_libraries(test_route PRIVATE fairway_run)
set_tests_properties(test_route PROPERTIES TIMEOUT 120
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
fw_cli_test(cli_route_bad_speed 2 "bad-speed.yaml:12: own_ship.route.1..speed_kn: -4 is out of range"
            run ${CMAKE_SOURCE_DIR}/tests/data/route/bad-speed.yaml --out ${CMAKE_CURRENT_BINARY_DIR}/cli-runs-route)
set_tests_properties(cli_route_bad_speed PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}" TIMEOUT 60)
# A route given as a network's edges (networks/bend): within 100 m of the
# lanes' line; edges, speeds, streams, waypoints off the network and networks
# without nodes or edges refused (FILE:LINE: FIELD, exit 2, nothing run).
fw_script_test(net_route 0 "ok: the own ship follows a network's edges" net_route.sh)
set_tests_properties(net_route PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
fw_script_test(channel_overtaken 0 "ok: the own ship overtaken close keeps within its channel" channel_overtaken.sh)
set_tests_properties(channel_overtaken PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
fw_script_test(channel_steady 0 "ok: the own ship in a channel steadies parallel to it and holds its course"
               channel_steady.sh)
set_tests_properties(channel_steady PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 180)
fw_script_test(channel_overtaking 0 "ok: the own ship overtaking close in a channel keeps clear"
               channel_overtaking.sh)
set_tests_properties(channel_overtaking PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
