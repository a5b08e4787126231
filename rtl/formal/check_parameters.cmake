# The widths rtl/formal/CMakeLists.txt proves the multipliers at are the ones
# specular_device passes them: Icarus elaborates the device (device_parameters_tb.v) at
# ROM5_WORD_BITS / REG9_FRAC and prints each multiplier's parameters; every line of
# EXPECTED ("multiplier6 LOG2_W=28,...;...") must be among them.
# Run by ctest: cmake -DIVERILOG=... -DVVP=... -DSOURCES=... -DROM5_WORD_BITS=...
#                     -DREG9_FRAC=... -DEXPECTED=... -DSCRATCH=... -P check_parameters.cmake
foreach(var IVERILOG VVP SOURCES ROM5_WORD_BITS REG9_FRAC EXPECTED SCRATCH)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_parameters.cmake: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
execute_process(COMMAND ${IVERILOG} -g2005 -DROM5_WORD_BITS=${ROM5_WORD_BITS} -DREG9_FRAC=${REG9_FRAC}
                        -s device_parameters_tb -o ${SCRATCH}/params.vvp ${SOURCES}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "iverilog failed (${status}):\n${out}")
endif()
# The ROM images are not needed to read parameters: run where none is (vvp warns).
execute_process(COMMAND ${VVP} -n ${SCRATCH}/params.vvp WORKING_DIRECTORY ${SCRATCH}
                RESULT_VARIABLE status OUTPUT_VARIABLE printed ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "vvp failed (${status}):\n${printed}${errors}")
endif()
foreach(line ${EXPECTED})
  string(FIND "${printed}" "${line}\n" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the formal tests prove '${line}', but specular_device "
                        "(ROM5_WORD_BITS=${ROM5_WORD_BITS}, REG9_FRAC=${REG9_FRAC}) passes:\n${printed}")
  endif()
  message(STATUS "matches the device: ${line}")
endforeach()
