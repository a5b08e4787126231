# rtl_ip_axi_icarus*: the whole IP (specular_ip_axi) under its AXI4-Lite testbench
# (rtl/tb/specular_ip_axi_tb.v). specular_tb writes the operations with Core's bits
# (--random COUNT --seed SEED --format csv), Icarus replays them over the bus with the
# AXI4-Lite rules checked on every edge; STALL=1: the master stalls every channel at random.
# cmake -DSPECULAR_TB=... -DIVERILOG=... -DVVP=... -DROM_DIR=... -DSOURCES=a.v|b.v
#       -DTESTBENCH=... -DSTALL=0|1 -DCOUNT=N -DSEED=S -DSCRATCH=... -P run_ip_axi.cmake
string(REPLACE "|" ";" SOURCES "${SOURCES}")
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
execute_process(COMMAND ${SPECULAR_TB} --random ${COUNT} --seed ${SEED} --format csv
                        --output ${SCRATCH}/vectors.csv
                RESULT_VARIABLE status ERROR_VARIABLE summary OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "specular_tb --random failed (status ${status}): ${summary}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/icarus_bench.cmake)
icarus_compile(specular_ip_axi_tb ${SCRATCH}/tb.vvp ${TESTBENCH}
               "-Pspecular_ip_axi_tb.ROM5_IMAGE=\"${ROM_DIR}/rom5.hex\""
               "-Pspecular_ip_axi_tb.ROM38_IMAGE=\"${ROM_DIR}/rom38.hex\""
               "-Pspecular_ip_axi_tb.VECTORS=\"${SCRATCH}/vectors.csv\""
               -Pspecular_ip_axi_tb.STALL=${STALL} -Pspecular_ip_axi_tb.SEED=${SEED}
               ${SOURCES})
execute_process(COMMAND ${VVP} -n ${SCRATCH}/tb.vvp RESULT_VARIABLE status
                OUTPUT_VARIABLE out ERROR_VARIABLE out)
message(STATUS "${out}")
if(NOT status EQUAL 0 OR NOT out MATCHES "specular_ip_axi_tb: PASS")
  message(FATAL_ERROR "specular_ip_axi_tb failed (status ${status})")
endif()
