# SPDX-License-Identifier: BSD-3-Clause
# A check of run_command.cmake (CHECKS) with -DPNG=file.png -DWIDTH=w -DHEIGHT=h: the file is a PNG of that size
# (signature and IHDR chunk) and not trivially small.
file(SIZE "${PNG}" bytes)
file(READ "${PNG}" header LIMIT 24 HEX)
string(SUBSTRING "${header}" 0 16 signature)
string(SUBSTRING "${header}" 32 8 width_hex)
string(SUBSTRING "${header}" 40 8 height_hex)
math(EXPR width "0x${width_hex}")
math(EXPR height "0x${height_hex}")
if(NOT signature STREQUAL "89504e470d0a1a0a" OR NOT width EQUAL WIDTH OR NOT height EQUAL HEIGHT OR bytes LESS 2000)
  fail("${PNG}: expected a ${WIDTH}x${HEIGHT} PNG, got signature ${signature}, ${width}x${height}, ${bytes} bytes")
endif()
