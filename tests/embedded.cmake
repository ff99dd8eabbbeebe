# Compile benchmarks/embedded.cpp for a Cortex-M4 and print its code size.
execute_process(COMMAND ${CXX} -std=c++20 -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
                        -fno-exceptions -fno-rtti -Os -DEIGEN_NO_MALLOC -Wall -Wextra -Werror
                        -DKANE_EMBEDDED_SCALAR=${SCALAR} -I${KANE_INCLUDE} -isystem ${EIGEN_INCLUDE}
                        -c ${SOURCE} -o ${OBJECT}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "arm-none-eabi-g++ failed:\n${out}")
endif()
execute_process(COMMAND ${SIZE} ${OBJECT} OUTPUT_VARIABLE size)
message(STATUS "Cortex-M4, ${SCALAR}, -Os:\n${size}")
