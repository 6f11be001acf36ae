# The traffic layer (src/traffic): one process per case, since libsumo holds
# one simulation per process.  Remote cases start their own headless sumo.
# Leaks inside SUMO's libraries are suppressed (see lsan_sumo.supp); harmless
# outside sanitizer builds.
set(fw_lsan "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/lsan_sumo.supp")
fw_test(test_traffic test_traffic.c)
target_link_libraries(test_traffic PRIVATE fairway_traffic)
set_tests_properties(test_traffic PROPERTIES TIMEOUT 30
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
# a SUMO ship's hull on its bow's track (traffic/hull_track.h)
fw_test(test_hull_track test_hull_track.c)
target_link_libraries(test_hull_track PRIVATE fairway_traffic)
# a SUMO peer that answers wrongly (traffic/traci_guard.h): errors, no abort, no hang
fw_test(test_traci_guard test_traci_guard.c)
target_link_libraries(test_traci_guard PRIVATE fairway_traffic)
set_tests_properties(test_traci_guard PROPERTIES TIMEOUT 60
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
# libsumo's remote control outlives neither a simulation nor a ship (a run after a run, fairway worst)
fw_test(test_sumo_reopen test_sumo_reopen.c)
target_link_libraries(test_sumo_reopen PRIVATE fairway_traffic)
set_tests_properties(test_sumo_reopen PROPERTIES TIMEOUT 60
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
# the start-up fill: there from t = 0 or never (a fill larger than the lanes hold)
fw_test(test_fill_room test_fill_room.c)
target_link_libraries(test_fill_room PRIVATE fairway_traffic)
set_tests_properties(test_fill_room PROPERTIES TIMEOUT 90
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
foreach(case embedded remote badnet noport dies)
  add_test(NAME test_traffic_${case} COMMAND test_traffic ${case})
  set_tests_properties(test_traffic_${case} PROPERTIES TIMEOUT 90
                       ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
endforeach()

# A SUMO ship taken by fairway and given back (embedded libsumo; test_vessels
# is built with the run tests).
add_test(NAME test_vessels_sumo COMMAND test_vessels sumo)
set_tests_properties(test_vessels_sumo PROPERTIES TIMEOUT 90
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

# The traffic command: a short embedded run, and one-line errors for bad input.
fw_cli_test(cli_traffic_run 0 "median [0-9.]+ ms per step" traffic --network channel --ships 20
            --duration 30 --every 10 --log traffic-cli.log --routes traffic-cli.rou.xml)
fw_cli_test(cli_traffic_help 0 "usage: fairway traffic" traffic --help)
fw_cli_test(cli_traffic_bad_network 2 "unknown network 'atlantis'" traffic --network atlantis)
fw_cli_test(cli_traffic_bad_mode 2 "expected embedded, gui or remote:HOST:PORT" traffic --sumo tcp)
fw_cli_test(cli_traffic_bad_ships 2 "--ships: 'many' is not an integer" traffic --ships many)
foreach(t cli_traffic_run cli_traffic_help cli_traffic_bad_network cli_traffic_bad_mode
          cli_traffic_bad_ships)
  set_tests_properties(${t} PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 60)
endforeach()

# Bad traffic input in a scenario: FILE:LINE: FIELD, exit 2, nothing run.
fw_script_test(traffic_bad_inputs 0 "bad traffic input refused" traffic_bad_inputs.sh)
set_tests_properties(traffic_bad_inputs PROPERTIES ENVIRONMENT "${fw_lsan}")

# SUMO is a loadable module (traffic/backend.h): the commands that do not
# simulate never map it, a simulating run maps it once.
fw_script_test(sumo_loading 0 "ok: SUMO loaded only to simulate, once" sumo_loading.sh)
set_tests_properties(sumo_loading PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)

# The libsumo range query spares reads and stays SUMO's range test exactly.
fw_script_test(range_read 0 "ok: range read exact, an understated bound caught" range_read.sh)
set_tests_properties(range_read PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 300)

# Networks built at run time are kept by their inputs' content (netcache.h).
fw_script_test(netcache 0 "ok: networks reused byte for byte" netcache.sh)
set_tests_properties(netcache PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 300)
# A network of the user's own: built on first use, again when edited.
fw_script_test(network_user 0 "ok: a network of the user's own built on first use" network_user.sh)
set_tests_properties(network_user PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 300)

# Recorded tracks as a traffic source (traffic/source_track.h), and a study's
# worst encounters exported as scenarios that replay them (fairway worst).
fw_test(test_track test_track.c)
fw_script_test(worst_replay 0 "ok: worst cases replayed within 10 m" worst_replay.sh)
set_tests_properties(worst_replay PROPERTIES TIMEOUT 300 ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

# ships on a bent channel (networks/bend) never move sideways like no ship can
fw_script_test(bend_traffic 0 "ok: no ship jumps on the bend" bend_traffic.sh)
set_tests_properties(bend_traffic PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
# the geometry of it: ships meeting along one waterway, ships of one stream, a crossing ship
fw_test(test_lanes test_lanes.c)
# ships meeting round the bend are meeting ships (rules 9 and 14), not crossing ones
fw_script_test(bend_meeting 0 "ok: ships meet round the bend head-on" bend_meeting.sh)
set_tests_properties(bend_meeting PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
# the start-up fill puts no two ships on a collision course, network-wide
fw_script_test(fill_pairs 0 "ok: no fill pair on a collision course" fill_pairs.sh)
set_tests_properties(fill_pairs PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)

# Background ships that alter course (traffic.give_way: course) in SUMO's Dover traffic.
fw_script_test(give_way_course 0 "background ships alter course and come back" give_way_course.sh)
set_tests_properties(give_way_course PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)

# In a wind the own ship keeps its planned line (its one leg steered as a route).
fw_script_test(wind_track 0 "the own ship keeps its line in a wind" wind_track.sh)
set_tests_properties(wind_track PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
fw_script_test(current_track 0 "the own ship keeps its line in a current" current_track.sh)
set_tests_properties(current_track PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
fw_script_test(standon_far 0 "no rule 17.b. action beyond 2 nm, no collision" standon_far.sh)
set_tests_properties(standon_far PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
