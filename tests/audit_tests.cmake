# The COLREGs audit (src/audit): scripted encounters that follow and break rules 8, 14, 16, 17.
fw_test(test_audit test_audit.c)
target_link_libraries(test_audit PRIVATE fairway_run)
