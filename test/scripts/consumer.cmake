# PackageTest: a tiny external project builds against the installed morphreg package.
add_test(NAME PackageTest.ConsumerBuildsAgainstInstalledPackage
  COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${CMAKE_BINARY_DIR} -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/consumer
          -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/consumer -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer/run_consumer.cmake)
set_tests_properties(PackageTest.ConsumerBuildsAgainstInstalledPackage PROPERTIES TIMEOUT 600)
