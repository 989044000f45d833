# SPDX-License-Identifier: BSD-3-Clause
# A check of run_command.cmake (CHECKS) with -DPYTHON=python3 -DPNG=file.png -DWIDTH=w -DHEIGHT=h and optionally
# -DPIXEL_CHECKS="--drawn x0 y0 x1 y1 share ..." (separated by spaces): the PNG's pixels, by check_png_pixels.py (its
# size, not blank, drawing where expected).
separate_arguments(pixel_checks UNIX_COMMAND "${PIXEL_CHECKS}")
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_png_pixels.py ${PNG} ${WIDTH} ${HEIGHT}
                        ${pixel_checks}
                RESULT_VARIABLE pixels_code OUTPUT_VARIABLE pixels_out ERROR_VARIABLE pixels_error)
message(STATUS "${pixels_out}")
if(NOT pixels_code EQUAL 0)
  fail("${pixels_error}")
endif()
