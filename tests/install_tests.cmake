# The install (issue 16): `cmake --install` into a temporary prefix; the
# installed fairway, moved and run from an unrelated directory, finds its data
# under the prefix and nowhere else (install_layout.sh says how that is shown).
fw_script_test(install_layout 0 "ok: installed fairway uses its prefix" install_layout.sh
               ${CMAKE_COMMAND} ${CMAKE_BINARY_DIR})
set_tests_properties(install_layout PROPERTIES ENVIRONMENT "${fw_lsan}" TIMEOUT 120)
