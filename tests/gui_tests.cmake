# Watching a run in sumo-gui, and remote mode (issue 16): under Xvfb, the screenshot shows the own
# ship centred and to scale (gui_screenshot.sh); skipped (77) only when Xvfb cannot
# run, a failure then on CI (FAIRWAY_REQUIRE_XVFB=1, .ci/run).
fw_script_test(gui_screenshot 0 "ok: the own ship in the sumo-gui screenshot" gui_screenshot.sh)
set_tests_properties(gui_screenshot PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 180
                     ENVIRONMENT "${fw_lsan}")
# cli_test.sh turns 77 into its own failure: the script is run directly for the skip
set_property(TEST gui_screenshot PROPERTY SKIP_REGULAR_EXPRESSION "SKIP: ")
# without a display, gui mode is refused at once (the TIMEOUT: not after the 10 s
# connect timeout), exit 2, nothing run
add_test(NAME cli_run_gui_no_display
         COMMAND env -u DISPLAY FAIRWAY_DATA=${CMAKE_SOURCE_DIR}
                 bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_test.sh 2
                 "--sumo gui: no display \\(\\$DISPLAY is not set\\): run under xvfb-run"
                 $<TARGET_FILE:fairway> run ${CMAKE_SOURCE_DIR}/scenarios/paper/1-head-on.yaml
                 --sumo gui --out ${CMAKE_CURRENT_BINARY_DIR}/gui-none)
set_tests_properties(cli_run_gui_no_display PROPERTIES TIMEOUT 5)
fw_cli_test(cli_run_gui_option_alone 2 "--gui-delay: only with --sumo gui"
            run ${CMAKE_SOURCE_DIR}/scenarios/paper/1-head-on.yaml --gui-delay 10)
fw_cli_test(cli_run_gui_bad_size 2 "--gui-size '12': expected WxH"
            run ${CMAKE_SOURCE_DIR}/scenarios/paper/1-head-on.yaml --sumo gui --gui-size 12)
set_tests_properties(cli_run_gui_bad_size PROPERTIES ENVIRONMENT "DISPLAY=:99")

# Remote mode: the command file, a run through it equal to the embedded run, a
# sumo on another network refused (remote_mode.sh).
fw_script_test(remote_mode 0 "ok: remote mode" remote_mode.sh)
set_tests_properties(remote_mode PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
