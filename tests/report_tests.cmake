# Study report (src/study/stats.c, report*.c, `fairway report`): statistics
# against known answers, a hand-built database whose report is worked out by
# hand, and the command's outputs and errors.
fw_test(test_stats test_stats.c)
fw_test(test_report test_report.c study_db.c)

# Synthetic databases for the command-line tests (not a test itself).
add_executable(make_study_db make_study_db.c study_db.c)
target_link_libraries(make_study_db PRIVATE fairway_core)

# The command: help, errors as one line with exit 2, outputs (script tests).
fw_cli_test(cli_report_help 0 "usage: fairway report FILE" report --help)
fw_cli_test(cli_report_listed 0 "report +statistics, tables, plots" --help)
fw_cli_test(cli_report_none 2 "no study database given" report)
fw_cli_test(cli_report_missing 2 "^fairway: nosuch.db: no such file$" report nosuch.db)
fw_cli_test(cli_report_not_db 2 "test.h: not a fairway study database"
            report ${CMAKE_CURRENT_SOURCE_DIR}/test.h)
fw_cli_test(cli_report_bad_option 2 "unknown option '--frob'" report x.db --frob)
fw_cli_test(cli_report_bad_reference 2 "--reference: 'big' is not a number" report x.db --reference big)
fw_cli_test(cli_report_two_files 2 "one file at a time" report a.db b.db)
fw_script_test(cli_report_plots 0 "^ok: report with plots" report_plots.sh $<TARGET_FILE:make_study_db>)
fw_script_test(cli_report_bad 0 "^ok: refused, nothing written" report_bad.sh $<TARGET_FILE:make_study_db>)
set_tests_properties(cli_report_plots PROPERTIES TIMEOUT 120)
fw_script_test(cli_report_monitors 0 "^ok: the report says whether the traffic behaved" report_monitors.sh $<TARGET_FILE:make_study_db>)
# A damaged or tampered database is refused naming table, row, run and column (db_check.h).
fw_script_test(cli_report_tampered 0 "^ok: 42 tampered databases refused" report_tampered.sh $<TARGET_FILE:make_study_db>)
