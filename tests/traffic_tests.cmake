# The traffic layer (src/traffic): one process per case, since libsumo holds
# one simulation per process.  Remote cases start their own headless sumo.
fw_test(test_traffic test_traffic.c)
target_link_libraries(test_traffic PRIVATE fairway_traffic)
set_tests_properties(test_traffic PROPERTIES TIMEOUT 30)
foreach(case embedded remote badnet noport dies)
  add_test(NAME test_traffic_${case} COMMAND test_traffic ${case})
  set_tests_properties(test_traffic_${case} PROPERTIES TIMEOUT 90
                       ENVIRONMENT "FAIRWAY_DATA=${CMAKE_SOURCE_DIR}")
endforeach()
