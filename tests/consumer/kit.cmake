# Included by the consumer projects: unit tests written with the test kit, as a user's test
# program is built (iecoop::testing_main, iecoop_discover_tests); run_ctest.cmake runs them
# with CTest and reads its JUnit report.
enable_testing()
add_test(NAME consumer COMMAND iecoop_consumer)
add_executable(iecoop_consumer_kit ${CMAKE_CURRENT_LIST_DIR}/kit_test.cpp)
target_link_libraries(iecoop_consumer_kit PRIVATE iecoop::testing_main)
iecoop_discover_tests(iecoop_consumer_kit)
