# silicon_gatesim_pass_fail: the gate-level simulation is sensitive to timing. With the
# SDF delays of the mapped device, scripts/flows/gatelevel/gatesim.sh replays the vectors at 1.1 T_sim
# (every vector must match, exit 0) and at T_sim / 2 (a register or pin must capture too
# early: exit 1 with a MISMATCH naming it). T_SIM is the figure the bisection measured
# (docs/silicon.md), not read from this run.
# TOP: the top module (default specular_device).
if(NOT TOP)
  set(TOP specular_device)
endif()
include(${CMAKE_CURRENT_LIST_DIR}/silicon_test_support.cmake)
foreach(case pass fail)
  gatesim_period(${case} ${T_SIM_CENTI} period)
  file(REMOVE_RECURSE ${SCRATCH}/${case})
  execute_process(COMMAND bash ${GATESIM} --top ${TOP} --netlist-dir ${NETLIST_DIR} --specular-tb ${SPECULAR_TB}
                          ${period} ${SCRATCH}/${case} ${ROM_DIR}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message(STATUS "T = ${period} ns: status ${status}\n${out}")
  if(case STREQUAL "pass" AND NOT (status EQUAL 0 AND out MATCHES "PASS"))
    message(FATAL_ERROR "gatesim.sh fails at 1.1 T_sim = ${period} ns")
  endif()
  if(case STREQUAL "fail" AND NOT (status EQUAL 1 AND out MATCHES "MISMATCH vector [0-9]+ [^\n]*(register [19]|pin 2[456])[^\n]*got [0-9a-fx]+, want [0-9a-f]+"))
    message(FATAL_ERROR "gatesim.sh does not name a register or pin captured too early at T_sim / 2 = ${period} ns")
  endif()
endforeach()
