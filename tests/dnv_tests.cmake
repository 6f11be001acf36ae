# DNV maritime-schema traffic situations (src/scenario/scn_dnv.h, issue 26).
fw_script_test(dnv_baseline 0 "the five DNV baselines: no collision" dnv_baseline.sh)
fw_script_test(dnv_waypoints 0 "a DNV target follows its waypoints" dnv_waypoints.sh)
fw_script_test(dnv_bad 0 "ok deep" dnv_bad.sh)
set_tests_properties(dnv_baseline dnv_waypoints dnv_bad PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
fw_script_test(dnv_write 0 "situations written, valid, and read back to the same run" dnv_write.sh)
set_tests_properties(dnv_write PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 180)
# A situation's environment (current, visibility; waves said not modelled) is run.
fw_script_test(dnv_env 0 "ok: a situation's environment is run" dnv_env.sh)
set_tests_properties(dnv_env PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
