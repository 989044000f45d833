# SPDX-License-Identifier: BSD-3-Clause
# The photo reader's tests write JPEG files with libjpeg (the library reads them through it); the glTF tests
# write their files with test/support/glb_writer.h, which compresses with the draco library.
target_link_libraries(${target} PRIVATE JPEG::JPEG draco::draco)
