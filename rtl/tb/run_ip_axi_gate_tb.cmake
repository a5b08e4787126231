# rtl_ip_axi_gate_tb: the gate-level AXI testbench of the whole IP
# (rtl/tb/specular_ip_axi_gate_tb.v, scripts/flows/synthesis/silicon.sh --top specular_ip_axi) run on the
# RTL, every MODE: the gate-level replay's own operations (scripts/flows/gatelevel/gatesim_vectors.py:
# specular_tb's expected values, Core's bits, of GROUPS edge-case groups of 10 and RANDOM
# random operations, policy patent/patent/clamp), register reads and writes, idle clocks;
# each must PASS and report the
# clocks each access takes on the bus (28 per operation, 38 with MODE 3's five more reads,
# 2 per read, 3 per write, counted by hand from the AXI top's handshakes: docs/rtl_ip.md,
# "TLM axi target").
# cmake -DSPECULAR_TB=... -DVECTORS_TOOL=gatesim_vectors.py -DIVERILOG=... -DVVP=... -DROM_DIR=...
#       -DSOURCES=a.v|b.v -DTESTBENCH=... -DGROUPS=G -DRANDOM=R -DSCRATCH=... -P run_ip_axi_gate_tb.cmake
string(REPLACE "|" ";" SOURCES "${SOURCES}")
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
execute_process(COMMAND /usr/bin/python3 ${VECTORS_TOOL} ${SPECULAR_TB} ${SCRATCH} patent/patent/clamp
                        ${GROUPS} ${RANDOM}
                RESULT_VARIABLE status OUTPUT_VARIABLE summary ERROR_VARIABLE summary)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "gatesim_vectors.py failed (status ${status}): ${summary}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/icarus_bench.cmake)
foreach(mode_clocks "3:operation 38" "0:operation 28" "1:read 2" "2:write 3" "4:idle 1")
  string(REPLACE ":" ";" mode_clocks "${mode_clocks}")
  list(GET mode_clocks 0 mode)
  list(GET mode_clocks 1 clocks)
  icarus_compile(specular_ip_axi_gate_tb ${SCRATCH}/tb${mode}.vvp ${TESTBENCH}
                 "-Pspecular_ip_axi_gate_tb.ROM5_IMAGE=\"${ROM_DIR}/rom5.hex\""
                 "-Pspecular_ip_axi_gate_tb.ROM38_IMAGE=\"${ROM_DIR}/rom38.hex\""
                 "-Pspecular_ip_axi_gate_tb.VECTORS=\"${SCRATCH}/vectors_patent_patent_clamp.csv\""
                 -Pspecular_ip_axi_gate_tb.MODE=${mode} -Pspecular_ip_axi_gate_tb.ACCESSES=30
                 ${SOURCES})
  execute_process(COMMAND ${VVP} -n ${SCRATCH}/tb${mode}.vvp RESULT_VARIABLE status
                  OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message(STATUS "MODE ${mode}: ${out}")
  string(REPLACE " " ";" clocks "${clocks}")
  list(GET clocks 0 kind)
  list(GET clocks 1 want)
  if(NOT status EQUAL 0 OR NOT out MATCHES "specular_ip_axi_gate_tb: PASS \\(MODE ${mode}:")
    message(FATAL_ERROR "specular_ip_axi_gate_tb MODE ${mode} failed (status ${status})")
  endif()
  if(NOT out MATCHES "clocks_per_${kind} ${want}\\.00\n")
    message(FATAL_ERROR "MODE ${mode}: want clocks_per_${kind} ${want}.00")
  endif()
endforeach()
