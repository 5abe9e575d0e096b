# Runs `GCSIM ARGS --jobs 1` and `GCSIM ARGS --jobs 3` and checks that the printed rows and the CSV
# are the same, apart from the host's wall times (the CSV column named wall_s, and the printed
# wall column found from the header line).
#   cmake -DGCSIM=path -DWORK=dir "-DARGS=sweep;APP;..." [-DWALL_FIELD=n] -P sweep_jobs_test.cmake
# WALL_FIELD: the printed wall column's position (0-based), for tables whose header has no wall_s.
file(MAKE_DIRECTORY ${WORK})

# Drops field `index` (0-based, separated by `sep`) from every line of text; returns the lines.
function(drop_field text sep index out)
  string(REPLACE "\n" ";" lines "${text}")
  set(result "")
  foreach(line IN LISTS lines)
    string(REPLACE "${sep}" ";" fields "${line}")
    list(LENGTH fields n)
    if(n GREATER index)
      list(REMOVE_AT fields ${index})
    endif()
    string(REPLACE ";" "${sep}" line "${fields}")
    list(APPEND result "${line}")
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

foreach(jobs 1 3)
  execute_process(COMMAND ${GCSIM} ${ARGS} --jobs ${jobs} --csv ${WORK}/jobs${jobs}.csv
                  OUTPUT_VARIABLE out_${jobs} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "--jobs ${jobs}: exit status ${rc}\n${out_${jobs}}")
  endif()
  file(READ ${WORK}/jobs${jobs}.csv csv_${jobs})
  string(REGEX MATCH "(^|\n)[^#\n][^\n]*" header "${csv_${jobs}}")  # the first row that is not a '#' comment
  string(STRIP "${header}" header)
  string(REPLACE "," ";" columns "${header}")
  list(FIND columns "wall_s" wall)
  if(wall LESS 0)
    message(FATAL_ERROR "no wall_s column in the CSV header: ${header}")
  endif()
  drop_field("${csv_${jobs}}" "," ${wall} csv_${jobs})
  # Printed rows: collapse runs of spaces so that columns are fields, then drop the wall column
  # at the position it has in the printed header.
  string(REGEX REPLACE " +" " " text "${out_${jobs}}")
  string(REGEX REPLACE "\n " "\n" text "${text}")
  string(REGEX REPLACE "^ " "" text "${text}")
  string(REGEX MATCH "(^|\n)nodes [^\n]*" printed_header "${text}")
  string(STRIP "${printed_header}" printed_header)
  string(REPLACE " " ";" printed_columns "${printed_header}")
  list(FIND printed_columns "wall_s" printed_wall)
  if(DEFINED WALL_FIELD)
    set(printed_wall ${WALL_FIELD})
  endif()
  if(printed_wall LESS 0)
    message(FATAL_ERROR "no wall_s column in the printed header: ${printed_header}")
  endif()
  drop_field("${text}" " " ${printed_wall} text_${jobs})
  string(REPLACE "jobs${jobs}.csv" "jobsN.csv" text_${jobs} "${text_${jobs}}")
endforeach()

if(NOT csv_1 STREQUAL csv_3)
  message(FATAL_ERROR "CSV rows differ between --jobs 1 and --jobs 3:\n${csv_1}\n---\n${csv_3}")
endif()
if(NOT text_1 STREQUAL text_3)
  message(FATAL_ERROR "printed rows differ between --jobs 1 and --jobs 3:\n${out_1}\n---\n${out_3}")
endif()
list(LENGTH csv_1 rows)
message(STATUS "${rows} CSV lines and the printed table are the same with --jobs 1 and --jobs 3")
