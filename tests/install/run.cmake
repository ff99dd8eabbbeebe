# Install kane into WORK_DIR/prefix, then configure, build and run a consumer. Boost is not a
# dependency: both configure with find_package(Boost) disabled.
file(REMOVE_RECURSE ${WORK_DIR})
function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE r OUTPUT_VARIABLE o ERROR_VARIABLE o)
  if(NOT r EQUAL 0)
    message(FATAL_ERROR "failed: ${ARGV}\n${o}")
  endif()
endfunction()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/kane -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX}
    -DKANE_BUILD_TESTS=OFF -DKANE_BUILD_EXAMPLES=OFF -DCMAKE_INSTALL_PREFIX=${WORK_DIR}/prefix
    -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON)
run(${CMAKE_COMMAND} --install ${WORK_DIR}/kane)
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/consumer -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run(${WORK_DIR}/consumer/consumer)
