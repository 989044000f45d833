# SPDX-License-Identifier: BSD-3-Clause
# A check of run_command.cmake (CHECKS) for a batch with failing scans, -DSUMMARY=summary.csv: each failure is named
# with its file and problem, and the other scans are ok with their RMS and iterations.
file(READ "${SUMMARY}" summary)
foreach(pattern "no_such_scan,failed,,,[0-9.]+,,[^,]*no_such_scan.pcd,[^\n]*no_such_scan.pcd: no such file\n"
        "scan_0,ok,[0-9.]+,[0-9]+," "scan_1,ok,[0-9.]+,[0-9]+,"
        "scan_flat,failed,,,[0-9.]+,,[^\n]*the 200 points lie in a plane")
  if(NOT summary MATCHES "${pattern}")
    fail("${SUMMARY} does not match '${pattern}'")
  endif()
endforeach()
