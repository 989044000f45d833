# SPDX-License-Identifier: BSD-3-Clause
# The glTF tests write their files with test/support/glb_writer.h, which compresses with the draco library.
target_link_libraries(${target} PRIVATE draco::draco)
