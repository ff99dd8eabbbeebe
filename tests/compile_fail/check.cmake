# Build TARGET in BUILD_DIR, or compile SOURCE with CXX and FLAGS; with ACCEPT, pass if it
# compiles; else pass if the compile fails, its first error line matches every regular expression of REGEX
# (separated by " && ") and the whole diagnostic is at most MAX_BYTES (default 10 KB).
# Only the first error line counts: later lines quote the source, which would match
# anything it names.
if(NOT DEFINED MAX_BYTES)
  set(MAX_BYTES 10240)
endif()
if(DEFINED CXX)
  separate_arguments(flags UNIX_COMMAND "${FLAGS}")
  execute_process(COMMAND ${CXX} ${flags} -fsyntax-only ${SOURCE} RESULT_VARIABLE result OUTPUT_VARIABLE out
                  ERROR_VARIABLE out)
  set(what "${SOURCE} (${CASE})")
else()
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${TARGET} RESULT_VARIABLE result
                  OUTPUT_VARIABLE out ERROR_VARIABLE out)
  set(what ${TARGET})
endif()
if(out MATCHES "invalid-pch|precompiled header .* (was not|cannot be) used")
  message(FATAL_ERROR "${what}: the precompiled header was not used\n${out}")
endif()
if(ACCEPT)  # the accepted twin: it must compile
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${what} did not compile, but it must\n${out}")
  endif()
  return()
endif()
if(result EQUAL 0)
  message(FATAL_ERROR "${what} compiled, but it must not")
endif()
string(LENGTH "${out}" bytes)
if(bytes GREATER MAX_BYTES)
  message(FATAL_ERROR "${what}: a diagnostic of ${bytes} bytes, over ${MAX_BYTES}\n${out}")
endif()
string(REGEX MATCH "[^\n]*error: [^\n]*" first "${out}")
string(REPLACE " && " ";" regexes "${REGEX}")
foreach(regex IN LISTS regexes)
  if(NOT first MATCHES "${regex}")
    message(FATAL_ERROR "${what} failed, but its first error line does not match\n  ${regex}\n${first}\n\n${out}")
  endif()
endforeach()
message(STATUS "${what}: diagnostic of ${bytes} bytes")
