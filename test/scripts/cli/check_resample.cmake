# SPDX-License-Identifier: BSD-3-Clause
# A check of run_command.cmake (CHECKS) for a successful `morphreg resample` with -DMIN_COVERAGE=c: the resampling's
# status is "ok", its coverage at least MIN_COVERAGE, and observed + filled vertices make up the model's.
string(JSON resampling ERROR_VARIABLE missing GET "${json}" resampling status)
string(JSON coverage ERROR_VARIABLE missing GET "${json}" resampling coverage)
string(JSON vertices ERROR_VARIABLE missing GET "${json}" resampling vertices)
string(JSON observed ERROR_VARIABLE missing GET "${json}" resampling observed)
string(JSON filled ERROR_VARIABLE missing GET "${json}" resampling filled)
math(EXPR total "${observed} + ${filled}")
if(NOT resampling STREQUAL "ok" OR coverage LESS MIN_COVERAGE OR NOT total EQUAL vertices)
  fail("${REPORT}: resampling '${resampling}', coverage ${coverage} (at least ${MIN_COVERAGE}), ${observed} observed + ${filled} filled of ${vertices} vertices")
endif()
