# The visualiser renders through X: run (and list) these tests under a virtual X server, one server at a time.
find_program(XVFB_RUN xvfb-run REQUIRED)
set_target_properties(${target} PROPERTIES CROSSCOMPILING_EMULATOR "${XVFB_RUN};-a;-s;-screen 0 1280x1024x24")
set(extra_test_properties RESOURCE_LOCK xvfb)
