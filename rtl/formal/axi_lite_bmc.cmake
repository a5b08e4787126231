# rtl_formal_axi_lite*: the AXI4-Lite rules of specular_ip_axi (rtl/ip/specular_ip_axi_props.v,
# FORMAL: the slave's asserted, the master's assumed) proved by bounded model checking
# with yosys-smtbmc and z3 to DEPTH cycles from reset, the hierarchy kept. The device is
# its free-output stand-in (specular_device_sync_free.v): the adapter's handshakes never
# read its outputs. `--unroll`: z3 4.8.12 stalled in step 0 on the incremental model.
# EXPECT=proved, or refuted: the top is read with BREAK_B_HOLD, a fault (BVALID dropped
# without BREADY) the proof must find.
# cmake -DYOSYS=... -DSMTBMC=... -DIP_SOURCES=a.v|b.v -DPROPS=... -DFREE_DEVICE=...
#       -DFORMAL_TOP=... -DDEPTH=N -DEXPECT=proved|refuted -DSCRATCH=... -P axi_lite_bmc.cmake
string(REPLACE "|" ";" IP_SOURCES "${IP_SOURCES}")
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
set(sources "")
foreach(source IN LISTS IP_SOURCES)
  if(EXPECT STREQUAL "refuted" AND source MATCHES "specular_ip_axi\\.v$")
    file(READ ${source} text)
    string(REPLACE "end else if (s_axi_bvalid && s_axi_bready) begin"
                   "end else if (s_axi_bvalid) begin" text "${text}")
    file(WRITE ${SCRATCH}/specular_ip_axi_broken.v "${text}")
    set(source ${SCRATCH}/specular_ip_axi_broken.v)
  endif()
  string(APPEND sources " ${source}")
endforeach()
file(WRITE ${SCRATCH}/model.ys
"read_verilog -formal -DFORMAL ${PROPS}
read_verilog -formal ${FREE_DEVICE}
read_verilog${sources}
read_verilog -formal ${FORMAL_TOP}
prep -top specular_ip_axi_formal
write_smt2 ${SCRATCH}/model.smt2
")
execute_process(COMMAND ${YOSYS} -q -l ${SCRATCH}/yosys.log ${SCRATCH}/model.ys RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  file(READ ${SCRATCH}/yosys.log log)
  message(FATAL_ERROR "yosys failed (status ${status}):\n${log}")
endif()
execute_process(COMMAND ${SMTBMC} -s z3 --unroll --noprogress -t ${DEPTH} ${SCRATCH}/model.smt2
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
file(WRITE ${SCRATCH}/smtbmc.log "${out}")
if(EXPECT STREQUAL "proved")
  if(NOT status EQUAL 0 OR NOT out MATCHES "Status: PASSED")
    message(FATAL_ERROR "AXI4-Lite rules not proved to depth ${DEPTH} (status ${status}):\n${out}")
  endif()
  message(STATUS "AXI4-Lite rules proved to depth ${DEPTH}")
else()
  if(status EQUAL 0 OR NOT out MATCHES "Assert failed")
    message(FATAL_ERROR "the planted fault (BVALID dropped without BREADY) was not found:\n${out}")
  endif()
  message(STATUS "the planted fault was found, as it must be")
endif()
