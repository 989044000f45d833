# CliTest: the command line runs its subcommands and reports bad arguments with a non-zero exit.
if(TARGET morphreg_cli)
  add_test(NAME CliTest.VersionPrints COMMAND morphreg_cli --version)
  set_tests_properties(CliTest.VersionPrints PROPERTIES PASS_REGULAR_EXPRESSION "morphreg [0-9]+\\.[0-9]+")
  add_test(NAME CliTest.SynthWritesHeadsAndScans
    COMMAND morphreg_cli synth --count 2 --scans 1 --range-mesh --quiet --out ${CMAKE_CURRENT_BINARY_DIR}/cli_synth)
  set_tests_properties(CliTest.SynthWritesHeadsAndScans PROPERTIES PASS_REGULAR_EXPRESSION "wrote 2 heads and 1 scans"
    FIXTURES_SETUP cli_synth)
  add_test(NAME CliTest.DemoRuns COMMAND morphreg_cli demo --count 3 --quiet --out ${CMAKE_CURRENT_BINARY_DIR}/cli_demo)
  set_tests_properties(CliTest.DemoRuns PROPERTIES PASS_REGULAR_EXPRESSION "demo: 3 heads")
  add_test(NAME CliTest.BadArgumentFails COMMAND morphreg_cli synth --count 0)
  set_tests_properties(CliTest.BadArgumentFails PROPERTIES WILL_FAIL TRUE)
  add_test(NAME CliTest.BadScannerSettingIsNamed COMMAND morphreg_cli synth --count 1 --scans 1 --noise -1 --quiet
    --out ${CMAKE_CURRENT_BINARY_DIR}/cli_bad)
  set_tests_properties(CliTest.BadScannerSettingIsNamed PROPERTIES PASS_REGULAR_EXPRESSION "noise_sigma")
endif()

# render: a screenshot under a virtual X server of the heads that CliTest.SynthWritesHeadsAndScans wrote.
find_program(XVFB_RUN xvfb-run)
if(TARGET morphreg_cli AND XVFB_RUN)
  add_test(NAME CliTest.RenderWritesPng
    COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" $<TARGET_FILE:morphreg_cli> render
            --mesh ${CMAKE_CURRENT_BINARY_DIR}/cli_synth/head_000.ply --cloud ${CMAKE_CURRENT_BINARY_DIR}/cli_synth/scan_0.pcd
            --width 320 --height 240 --view oblique --out ${CMAKE_CURRENT_BINARY_DIR}/cli_render.png)
  set_tests_properties(CliTest.RenderWritesPng PROPERTIES
    DEPENDS CliTest.SynthWritesHeadsAndScans FIXTURES_REQUIRED cli_synth RESOURCE_LOCK xvfb
    PASS_REGULAR_EXPRESSION "wrote .*cli_render.png \\(320x240\\)")
  add_test(NAME CliTest.RenderMissingFileFails
    COMMAND $<TARGET_FILE:morphreg_cli> render --mesh ${CMAKE_CURRENT_BINARY_DIR}/no_such_mesh.ply)
  set_tests_properties(CliTest.RenderMissingFileFails PROPERTIES PASS_REGULAR_EXPRESSION "no_such_mesh.ply")
endif()
