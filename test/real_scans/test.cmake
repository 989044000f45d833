# The glTF versions of the real scans are written with test/support/glb_writer.h, which compresses with draco.
target_link_libraries(${target} PRIVATE draco::draco)
