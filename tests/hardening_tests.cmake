# Hardening (issue 14): every bad input the audit found gets a clear message and
# exit 2 before any computation; editing ship files with any line breaks; paths.
# (Sweep and report cases are in study_tests.cmake, run cases in run_tests.cmake.)
fw_script_test(edit_line_breaks 0 "ok: line breaks kept, values intact" edit_line_breaks.sh)
fw_script_test(identify_out 0 "ok: --out refused before computing" identify_out.sh)
fw_script_test(dir_inputs 0 "ok: directories refused, speeds checked" dir_inputs.sh)
fw_cli_test(cli_ship_extra_arg 2 "ship: one ship at a time \\(unexpected 'extra-arg'\\)" ship c3 extra-arg)
fw_cli_test(cli_identify_empty_item 2 "--speeds: empty item in '10,,12'" identify --ship c3 --speeds 10,,12)
fw_cli_test(cli_identify_trailing_comma 2 "--rudders: empty item in '10,'" identify --ship c3 --rudders 10,)
fw_cli_test(cli_manoeuvre_csv_dir 2 "--csv ${CMAKE_CURRENT_BINARY_DIR}: is a directory, expected a file name"
            manoeuvre turning --ship c3 --speed 20 --rudder 35 --csv ${CMAKE_CURRENT_BINARY_DIR})
fw_cli_test(cli_traffic_tiny_step 2 "--step 1e-09: must be 0.1 to 60 s" traffic --step 1e-9)
fw_cli_test(cli_traffic_routes_dir 2 "--routes ${CMAKE_CURRENT_BINARY_DIR}: is a directory"
            traffic --routes ${CMAKE_CURRENT_BINARY_DIR})
fw_cli_test(cli_traffic_bad_host 2 "cannot resolve host 'no-such-host.invalid'"
            traffic --sumo remote:no-such-host.invalid:8813)
fw_cli_test(cli_helm_on_own_ship 2 "--target 1: at the own ship's position \\(100, 200\\) m"
            helm --ship c3 --own 100,200,0,12 --target 100,200,180,10)
fw_cli_test(cli_helm_huge_position 2 "--target: position \\(1e\\+300, 0\\) m is beyond 10000 km"
            helm --ship c3 --own 0,0,0,12 --target 1e300,0,180,10)
fw_cli_test(cli_sweep_db_dir 2 "--db ${CMAKE_CURRENT_BINARY_DIR}: is a directory, expected a database file"
            sweep ${CMAKE_SOURCE_DIR}/tests/data/study/small.yaml --db ${CMAKE_CURRENT_BINARY_DIR})
# issue 28: empty names, line breaks, fw_ ids, numbers quoted as written
fw_script_test(names_numbers 0 "ok: names and numbers refused as written" names_numbers.sh)
# runs reach SUMO, whose own allocations the LeakSanitizer suppressions cover
foreach(t edit_line_breaks identify_out dir_inputs names_numbers)
  set_tests_properties(${t} PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
endforeach()
# Hardening, round two (issue 28, Files): nothing written through a planted
# symlink, streams printed, only fairway's own files replaced in an output
fw_script_test(files_planted 0 "ok: nothing written through a planted link, streams printed"
               files_planted.sh)
fw_script_test(files_outdirs 0 "ok: only fairway's own files replaced" files_outdirs.sh)
foreach(t files_planted files_outdirs)
  set_tests_properties(${t} PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
endforeach()
fw_script_test(foreign_quote 0 "ok: no line of a foreign file printed" foreign_quote.sh)
set_tests_properties(foreign_quote PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
# the remote SUMO's connect and reply timeouts: FAIRWAY_SUMO_TIMEOUT (issue 28 item 2)
fw_script_test(sumo_timeout 0 "ok: the SUMO timeout is a setting" sumo_timeout.sh)
set_tests_properties(sumo_timeout PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
# a file's temporary left by a SIGKILL (.NAME.fairway-tmp.PID.XXXXXX) removed by
# the next writer into the same directory, nothing else (issue 28 item 7)
fw_script_test(tmp_leftovers 0 "ok: leftover temporaries removed, nothing else touched"
               tmp_leftovers.sh)
set_tests_properties(tmp_leftovers PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR}")
# fairway traffic writes outside an output only the files its help names (issue 28, Files)
fw_script_test(traffic_files 0 "ok: traffic writes only what its help names" traffic_files.sh)
set_tests_properties(traffic_files PROPERTIES ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR};${fw_lsan}")
