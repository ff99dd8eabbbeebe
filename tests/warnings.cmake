# Check tests/warnings.cpp with a compiler (CXX) under the strict warnings (FLAGS): -fsyntax-only
# instantiates every template the explicit instantiations reach, without generating code.
separate_arguments(flags UNIX_COMMAND "${FLAGS}")
execute_process(COMMAND ${CXX} -std=c++20 ${flags} -fsyntax-only -I${KANE_INCLUDE} -isystem ${EIGEN_INCLUDE}
                        ${SOURCE}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${CXX} failed:\n${out}")
endif()
message(STATUS "${CXX}: no warning")
