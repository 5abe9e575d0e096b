# The lines matching MATCH must be the same, in the same order, in every file of FILES (joined
# by @@): a program's result does not depend on how many ranks computed it.
#   cmake "-DFILES=a.txt@@b.txt" "-DMATCH=^jacobi " -P same_lines.cmake
string(REPLACE "@@" ";" FILES "${FILES}")
list(GET FILES 0 first)
file(STRINGS ${first} reference REGEX "${MATCH}")
if(NOT reference)
  message(FATAL_ERROR "${first} has no line matching '${MATCH}'")
endif()
foreach(f ${FILES})
  file(STRINGS ${f} lines REGEX "${MATCH}")
  if(NOT lines STREQUAL reference)
    string(REPLACE ";" "\n" a "${reference}")
    string(REPLACE ";" "\n" b "${lines}")
    message(FATAL_ERROR "${first} printed\n${a}\nbut ${f} printed\n${b}")
  endif()
endforeach()
list(LENGTH reference n)
message(STATUS "${n} lines the same in ${FILES}")
