# Monte Carlo sweeps (src/study, `fairway sweep`): the run list and common random
# numbers, the database, parallel and MPI sweeps agreeing, SIGKILL and resume.
fw_test(test_study test_study.c)
target_link_libraries(test_study PRIVATE fairway_study)

fw_script_test(sweep_parallel 0 "jobs 1 and 2 agree" sweep_parallel.sh)
fw_script_test(sweep_kill 0 "same results: 10 runs" sweep_kill.sh)
fw_script_test(sweep_fail 0 "failed runs recorded, skipped, then retried" sweep_fail.sh)
set(fw_sweep_tests test_study sweep_parallel sweep_kill sweep_fail)
find_program(FW_MPIRUN mpirun)
if(FW_MPIRUN AND MPI_C_FOUND)
  fw_script_test(sweep_mpi 0 "same results: 10 runs" sweep_mpi.sh)
  # Open MPI's own allocations would be reported as leaks
  set_tests_properties(sweep_mpi PROPERTIES LABELS no_sanitize TIMEOUT 300)
  # splitting's (cell, batch) estimates over the ranks, and resumed
  fw_script_test(sweep_mpi_split 0 "ok: splitting over MPI" sweep_mpi_split.sh)
  set_tests_properties(sweep_mpi_split PROPERTIES LABELS no_sanitize TIMEOUT 300)
  # a full disk under mpirun stops the sweep and says so (issue 28 item 7; root: a tmpfs)
  fw_script_test(sweep_full_mpi 0 "ok: a full disk stops an MPI sweep and says so" sweep_full_mpi.sh)
  set_tests_properties(sweep_full_mpi PROPERTIES LABELS no_sanitize TIMEOUT 300
                       SKIP_REGULAR_EXPRESSION "skipped: cannot mount")
endif()

fw_cli_test(cli_sweep_help 0 "usage: fairway sweep" sweep --help)
fw_cli_test(cli_sweep_no_db 2 "--db FILE is required" sweep ${CMAKE_SOURCE_DIR}/tests/data/study/small.yaml)
fw_cli_test(cli_sweep_jobs 2 "--jobs 0: give 1 to 1024" sweep x.yaml --db x.db --jobs 0)
fw_cli_test(cli_sweep_gui 2 "a sweep runs without windows" sweep x.yaml --db x.db --sumo gui)
fw_cli_test(cli_sweep_dry 0 "^study small .*10 runs" sweep ${CMAKE_SOURCE_DIR}/tests/data/study/small.yaml --dry-run)
# the shipped splitting study with an exact answer reads (bench/split_watch.sh runs it)
fw_cli_test(cli_sweep_dry_headon_watch 0 "^study headon-watch .*200 runs" sweep
            ${CMAKE_SOURCE_DIR}/scenarios/studies/headon-watch.yaml --dry-run)
foreach(bad "domain:4: domains_m\\[1\\]: 'abc' is not a number"
            "key:5: replicas: unknown field"
            "missing:1: replications: required field is missing"
            "nan:4: domains_m\\[1\\]: '.nan' is not a number"
            "twice:4: domains_m\\[1\\]: 300 is listed twice"
            "duration:5: duration_s: 10.5 s is not a whole number of steps"
            "scenario:2: scenario: .*nowhere.yaml: cannot open"
            "behaviour:5: behaviours\\[1\\]: 'polite' is not a behaviour"
            "audit:6: audit.speed_change: give a fraction in \\(0, 1\\]"
            "shape:5: fore_aft_ratios\\[1\\]: 0.1 is outside \\[0.2, 10\\]"
            "units:5: domains_l: give domains_m or domains_l, not both"
            "aisbehaviour:6: behaviours: .*replays recorded ships, which do not react"
            "aisspread:4: replications: 4 over recorded traffic would be 4 copies of one run"
            "timespread:6: start.time_s: only over recorded traffic"
            "particles:5: estimate.particles: 1 is out of range \\[2, 100000\\]"
            "event:5: estimate.event: unknown field"
            "estmethod:5: estimate.method: 'importance': the one method is splitting"
            "estbatches:7: estimate.batches: 1 is out of range \\[2, 10000\\]"
            "norandom:6: estimate: .*base.yaml has no randomness after t = 0"
            "axheld:6: axes.traffic.density: not an axis: use densities:"
            "axvalue:6: axes.own_ship.speed_kn\\[1\\]: .*base.yaml:9: own_ship.speed_kn: -3 is out of range"
            "axkey:6: axes.avoidance.horizon\\[0\\]: .*avoidance.horizon: unknown field"
            "axform:6: axes.own_ship.speed_kn\\[1\\]: 12 is listed twice"
            "axvis:6: axes.environment.visibility_nm\\[1\\]: .*base.yaml:3: environment.visibility_nm: 0: a visibility is more than 0"
            "axmode:6: axes.sensing.mode\\[1\\]: .*sensing.mode: 'lidar' is not a sensing mode")
  string(REGEX MATCH "^[a-z]+" name "${bad}")
  string(REGEX REPLACE "^[a-z]+" "" pattern "${bad}")
  fw_script_test(cli_sweep_bad_${name} 0 "ok: no database" sweep_bad.sh
                 ${CMAKE_SOURCE_DIR}/tests/data/study/bad-${name}.yaml "bad-${name}.yaml${pattern}")
  list(APPEND fw_sweep_tests cli_sweep_bad_${name})
endforeach()
fw_script_test(cli_sweep_not_db 0 "ok: refused" sweep_not_db.sh)
# a study with splitting end to end, and its closest path replayed (fairway worst --splits)
fw_script_test(split_worst 0 "ok: splitting's closest path replayed" split_worst.sh)
list(APPEND fw_sweep_tests split_worst)
# splitting over the own ship's watch (world/watch.h) as the only randomness
fw_script_test(watch_split 0 "ok: splitting over the own ship's watch" watch_split.sh)
list(APPEND fw_sweep_tests watch_split)
# a study with an axis over a scenario key, swept and reported
fw_script_test(sweep_axes 0 "ok: axes swept, recorded, reported" sweep_axes.sh)
list(APPEND fw_sweep_tests sweep_axes)
# a study over recorded traffic: domains swept over an AIS replay
fw_script_test(sweep_ais 0 "ok: AIS study swept, paired, guarded" sweep_ais.sh)
list(APPEND fw_sweep_tests sweep_ais)
list(APPEND fw_sweep_tests cli_sweep_help cli_sweep_no_db cli_sweep_jobs cli_sweep_gui
     cli_sweep_dry cli_sweep_not_db)
foreach(t ${fw_sweep_tests})
  set_tests_properties(${t} PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
endforeach()
set_tests_properties(sweep_parallel sweep_kill sweep_fail PROPERTIES TIMEOUT 300)

# Hardening (issue 14): inputs of a resumed sweep, one writer, paths checked first
fw_script_test(sweep_inputs 0 "ok: every changed input refused by name" sweep_inputs.sh)
# Hardening (issue 28 item 7): nothing outlives a SIGKILL; leftovers removed by the next command
fw_script_test(kill_leftovers 0 "ok: nothing outlives a SIGKILL, leftovers removed" kill_leftovers.sh)
set_tests_properties(kill_leftovers PROPERTIES TIMEOUT 120)
fw_script_test(sweep_lock 0 "ok: second sweep refused at once" sweep_lock.sh)
fw_script_test(sweep_paths 0 "ok: bad paths refused, nothing created" sweep_paths.sh)
fw_script_test(report_readonly 0 "ok: read-only database reported" report_readonly.sh)
foreach(t sweep_inputs sweep_lock sweep_paths report_readonly kill_leftovers)
  set_tests_properties(${t} PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
endforeach()
fw_test(test_ams test_ams.c ams_walk.c)
fw_test(test_split_run test_split_run.c)
target_link_libraries(test_split_run PRIVATE fairway_study)
# a full disk stops a sweep with a message that says so (issue 28 item 7); a
# small tmpfs mounted as root, else skipped
fw_script_test(sweep_full 0 "ok: a full disk stops the sweep and says so" sweep_full.sh)
set_tests_properties(sweep_full PROPERTIES SKIP_REGULAR_EXPRESSION "skipped: cannot mount"
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
