# cmake -DARGS="program|arg|..." -DCHECK="check_scan_colours|mesh|folder" -P check_colours.cmake
# Runs ARGS (a register or resample that must succeed: exit 0), then CHECK (check_scan_colours on a mesh it wrote).
foreach(step ARGS CHECK)
  string(REPLACE "|" ";" command "${${step}}")
  execute_process(COMMAND ${command} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${step} exited ${code}: ${command}")
  endif()
endforeach()
