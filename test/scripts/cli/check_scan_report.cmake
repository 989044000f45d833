# SPDX-License-Identifier: BSD-3-Clause
# A check of run_command.cmake (CHECKS) for one scan of build-model --from-scans, -DSCAN_REPORT=scan.json: the scan's
# report gives its coverage, the registration's components and the refinement's prior.
file(READ "${SCAN_REPORT}" scan_json)
string(JSON coverage ERROR_VARIABLE missing GET "${scan_json}" resampling coverage)
string(JSON components ERROR_VARIABLE missing GET "${scan_json}" settings components 0)
string(JSON prior ERROR_VARIABLE missing GET "${scan_json}" settings refinement_prior_weight)
if(NOT coverage GREATER 0.5 OR NOT components EQUAL 8 OR NOT prior EQUAL 0.2)
  fail("${SCAN_REPORT}: coverage ${coverage} (> 0.5), components ${components} (8), refinement prior ${prior} (0.2)")
endif()
