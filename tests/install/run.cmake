# The README's install steps (install.sh): install kane into WORK_DIR/.local, then configure, build
# and run a consumer with find_package(kane).
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
file(CREATE_LINK ${SOURCE_DIR} ${WORK_DIR}/kane SYMBOLIC)
file(COPY ${SOURCE_DIR}/tests/install/consumer/ DESTINATION ${WORK_DIR}/app)
execute_process(COMMAND ${CMAKE_COMMAND} -E env HOME=${WORK_DIR} CXX=${CXX} CMAKE_GENERATOR=${GENERATOR}
                        sh ${SOURCE_DIR}/tests/install/install.sh
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE r OUTPUT_VARIABLE o ERROR_VARIABLE o)
if(NOT r EQUAL 0)
  message(FATAL_ERROR "the README's install steps failed:\n${o}")
endif()
