# SPDX-License-Identifier: BSD-3-Clause
# A check of run_command.cmake (CHECKS) for `morphreg register --truth` with -DMAX_TRUTH_RMS=mm: the report holds the
# similarity, coefficients per region (in prior standard deviations, and as lengths in coefficients_mm), residual
# statistics, the iteration history (one entry per iteration), the termination reason, timings and the error against
# the truth, within MAX_TRUTH_RMS.
foreach(entry "scale;similarity;scale" "rms;residuals_mm;per_vertex;rms" "median;residuals_mm;scan_to_model;median"
        "total;iterations;total" "reason;termination;reason" "seconds;timings_s;fit" "model_regions;model;regions"
        "truth_rms;truth_vertex_error_mm;covered_by_scan;rms" "coefficients_unit;coefficients_unit")
  list(POP_FRONT entry name)
  string(JSON ${name} ERROR_VARIABLE missing GET "${json}" ${entry})
  if(missing)
    fail("${REPORT}: ${entry} missing")
  endif()
endforeach()
string(JSON matrix_length ERROR_VARIABLE missing LENGTH "${json}" similarity matrix_row_major)
string(JSON regions ERROR_VARIABLE missing LENGTH "${json}" coefficients)
string(JSON regions_mm ERROR_VARIABLE missing LENGTH "${json}" coefficients_mm)
string(JSON history ERROR_VARIABLE missing LENGTH "${json}" iterations history)
foreach(pair "matrix_length;16" "regions;${model_regions}" "regions_mm;${model_regions}" "history;${total}")
  list(GET pair 0 name)
  list(GET pair 1 expected)
  if(NOT "${${name}}" EQUAL "${expected}")
    fail("${REPORT}: ${name} is ${${name}}, expected ${expected}")
  endif()
endforeach()
if(total LESS 1 OR NOT reason MATCHES "converged|max_iterations" OR seconds LESS_EQUAL 0 OR rms LESS_EQUAL 0
   OR median LESS_EQUAL 0)
  fail("${REPORT}: implausible run (iterations ${total}, ${reason}, ${seconds} s, RMS ${rms})")
endif()
if(NOT coefficients_unit STREQUAL "prior standard deviations")
  fail("${REPORT}: coefficients_unit is '${coefficients_unit}', expected prior standard deviations")
endif()
if(truth_rms GREATER "${MAX_TRUTH_RMS}")
  fail("${REPORT}: vertex RMS against the truth ${truth_rms} mm > ${MAX_TRUTH_RMS} mm")
endif()
