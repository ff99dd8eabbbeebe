# Build TARGET in BUILD_DIR; pass if the build fails and its output matches
# every regular expression of REGEX (separated by " && ").
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${TARGET}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(result EQUAL 0)
  message(FATAL_ERROR "${TARGET} compiled, but it must not")
endif()
string(REPLACE " && " ";" regexes "${REGEX}")
foreach(regex IN LISTS regexes)
  if(NOT out MATCHES "${regex}")
    message(FATAL_ERROR "${TARGET} failed, but its diagnostic does not match\n  ${regex}\n${out}")
  endif()
endforeach()
