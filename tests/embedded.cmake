# Compile benchmarks/embedded/embedded.cpp for a Cortex-M4; print its code size and each C function's stack.
execute_process(COMMAND ${CXX} -std=c++20 -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
                        -fno-exceptions -fno-rtti -Os -fstack-usage -DEIGEN_NO_MALLOC -Wall -Wextra -Werror
                        -DKANE_EMBEDDED_SCALAR=${SCALAR} -I${KANE_INCLUDE} -isystem ${EIGEN_INCLUDE}
                        -c ${SOURCE} -o ${OBJECT}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "arm-none-eabi-g++ failed:\n${out}")
endif()
execute_process(COMMAND ${SIZE} ${OBJECT} OUTPUT_VARIABLE size)
message(STATUS "Cortex-M4, ${SCALAR}, -Os:\n${size}")
get_filename_component(dir ${OBJECT} DIRECTORY)
get_filename_component(stem ${OBJECT} NAME_WE)
file(STRINGS ${dir}/${stem}.su stack REGEX "(arm|disc|pendulum)_step")
string(REPLACE ";" "\n" stack "${stack}")
message(STATUS "stack in bytes (-fstack-usage):\n${stack}")
