# SPDX-License-Identifier: BSD-3-Clause
# The photo reader's tests write JPEG files with libjpeg (the library reads them through it).
target_link_libraries(${target} PRIVATE JPEG::JPEG)
