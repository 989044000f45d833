# CliTest: the command line runs its subcommands and reports bad arguments with a non-zero exit.
if(TARGET morphreg_cli)
  add_test(NAME CliTest.VersionPrints COMMAND morphreg_cli --version)
  set_tests_properties(CliTest.VersionPrints PROPERTIES PASS_REGULAR_EXPRESSION "morphreg [0-9]+\\.[0-9]+")
  add_test(NAME CliTest.SynthWritesHeadsAndScans
    COMMAND morphreg_cli synth --count 2 --scans 1 --range-mesh --quiet --out ${CMAKE_CURRENT_BINARY_DIR}/cli_synth)
  set_tests_properties(CliTest.SynthWritesHeadsAndScans PROPERTIES PASS_REGULAR_EXPRESSION "wrote 2 heads and 1 scans")
  add_test(NAME CliTest.DemoRuns COMMAND morphreg_cli demo --count 3 --quiet --out ${CMAKE_CURRENT_BINARY_DIR}/cli_demo)
  set_tests_properties(CliTest.DemoRuns PROPERTIES PASS_REGULAR_EXPRESSION "demo: 3 heads")
  add_test(NAME CliTest.BadArgumentFails COMMAND morphreg_cli synth --count 0)
  set_tests_properties(CliTest.BadArgumentFails PROPERTIES WILL_FAIL TRUE)
  add_test(NAME CliTest.BadScannerSettingIsNamed COMMAND morphreg_cli synth --count 1 --scans 1 --noise -1 --quiet
    --out ${CMAKE_CURRENT_BINARY_DIR}/cli_bad)
  set_tests_properties(CliTest.BadScannerSettingIsNamed PROPERTIES PASS_REGULAR_EXPRESSION "noise_sigma")
endif()
