# silicon_ip_gatesim_pass_fail: the whole IP's gate-level replay (scripts/flows/gatelevel/gatesim.sh --top
# specular_ip_axi, rtl/tb/specular_ip_axi_gate_tb.v: operations, register reads and writes
# over AXI) is sensitive to timing. With the SDF delays of the mapped IP every access
# passes at 1.1 T_sim (exit 0, PASS) and at T_sim / 2 one fails (exit 1, a MISMATCH
# naming the access: a read with got and expected, a write's response, or done_irq).
# T_SIM_CENTI is the figure the bisection measured (docs/rtl_ip.md), not read from this run.
include(${CMAKE_CURRENT_LIST_DIR}/silicon_test_support.cmake)
foreach(case pass fail)
  gatesim_period(${case} ${T_SIM_CENTI} period)
  file(REMOVE_RECURSE ${SCRATCH}/${case})
  execute_process(COMMAND bash ${GATESIM} --top specular_ip_axi --netlist-dir ${NETLIST_DIR}
                          --specular-tb ${SPECULAR_TB} --quiet ${period} ${SCRATCH}/${case} ${ROM_DIR}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message(STATUS "T = ${period} ns: status ${status}\n${out}")
  if(case STREQUAL "pass" AND NOT (status EQUAL 0 AND out MATCHES "specular_ip_axi_gate_tb: PASS"))
    message(FATAL_ERROR "gatesim.sh fails at 1.1 T_sim = ${period} ns")
  endif()
  if(case STREQUAL "fail" AND NOT (status EQUAL 1 AND out MATCHES
     "MISMATCH (read 0x[0-9a-f]+ \\([A-Z_0-9]+\\): 0x[0-9a-fxzXZ]+ response [01xzXZ]+, expected 0x[0-9a-f]+|write 0x[0-9a-f]+|vector [0-9]+: done_irq)"))
    message(FATAL_ERROR "gatesim.sh does not name an access that failed at T_sim / 2 = ${period} ns")
  endif()
endforeach()
