# SPDX-License-Identifier: BSD-3-Clause
# A check of run_command.cmake (CHECKS) for `morphreg register --truth` with -DMAX_TRUTH_RMS=mm: the report holds the
# similarity, coefficients per region (in prior standard deviations, and as lengths in coefficients_mm), residual
# statistics, the iteration history (one entry per iteration), the termination reason, timings, the coverage of each
# model region (a share in [0, 1]; the simulated laser scan of a whole head covers more than half of most regions,
# though hardly the chin's underside) and the error against the truth, within MAX_TRUTH_RMS.
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
string(JSON covered_regions ERROR_VARIABLE missing LENGTH "${json}" checks measures region_coverage)
foreach(pair "matrix_length;16" "regions;${model_regions}" "regions_mm;${model_regions}" "history;${total}"
        "covered_regions;${model_regions}")
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
math(EXPR last_region "${covered_regions} - 1")
set(mostly_covered 0)
foreach(index RANGE ${last_region})
  string(JSON region MEMBER "${json}" checks measures region_coverage ${index})
  string(JSON share GET "${json}" checks measures region_coverage ${region})
  if(share LESS 0 OR share GREATER 1)
    fail("${REPORT}: region ${region}'s coverage ${share} is no share")
  elseif(share GREATER_EQUAL 0.5)
    math(EXPR mostly_covered "${mostly_covered} + 1")
  endif()
endforeach()
math(EXPR half_regions "${covered_regions} / 2")
if(mostly_covered LESS_EQUAL half_regions)
  fail("${REPORT}: only ${mostly_covered} of ${covered_regions} regions are half covered by a scan of the whole head")
endif()
if(NOT coefficients_unit STREQUAL "prior standard deviations")
  fail("${REPORT}: coefficients_unit is '${coefficients_unit}', expected prior standard deviations")
endif()
if(truth_rms GREATER "${MAX_TRUTH_RMS}")
  fail("${REPORT}: vertex RMS against the truth ${truth_rms} mm > ${MAX_TRUTH_RMS} mm")
endif()
