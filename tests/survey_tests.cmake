# Traffic-level encounters (src/survey): known answers on hand-built traffic,
# the grid against all pairs, input order (no SUMO); the survey: section of
# scenario files; a scenario run with a survey through libsumo (its own
# process: one simulation per process); a bad survey field on the command line.
fw_test(test_survey test_survey.c)
set_tests_properties(test_survey PROPERTIES TIMEOUT 120)

fw_test(test_survey_run test_survey_run.c)
target_link_libraries(test_survey_run PRIVATE fairway_run)
set_tests_properties(test_survey_run PROPERTIES TIMEOUT 60
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
add_test(NAME test_survey_run_sumo COMMAND test_survey_run run)
set_tests_properties(test_survey_run_sumo PROPERTIES TIMEOUT 180
                     ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")

fw_cli_test(cli_run_bad_survey 2 "survey_bad.yaml:19: survey.tcpa_s" run
            ${CMAKE_CURRENT_SOURCE_DIR}/data/survey_bad.yaml --out ${CMAKE_CURRENT_BINARY_DIR}/cli-runs)
set_tests_properties(cli_run_bad_survey PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 60)
