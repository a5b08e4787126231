# silicon_ip_report: what scripts/flows/synthesis/silicon.sh writes for the whole IP (specular_ip_axi,
# docs/silicon/ip_tests.md "The whole IP (specular_ip_axi)") is sane: the report with its shares of the area, cell
# counts above zero, the register block and the device in the mapped netlist by instance
# name (regs, device: the hierarchy kept), T_sta a number above zero with its worst path
# named, and OpenSTA's log without an error (a netlist line it could not read).
file(READ ${OUT}/silicon_report.md report)
include(${CMAKE_CURRENT_LIST_DIR}/silicon_test_support.cmake)
expect_sections("${report}" silicon_report.md
                "## Area per block" "## Shares of the area" "| register block |" "| AXI4-Lite top |"
                "| synchronous device (ROM macros apart) |" "| ROM macros |" "## Static timing (OpenSTA)"
                "worst path of the top: from " "| ROM5_MACRO | 32 768 x 22 |")
file(READ ${OUT}/silicon_summary.json summary)
foreach(key cells flip_flops area_logic_um2 area_macros_um2 area_total_um2 t_sta_ns)
  string(JSON value GET "${summary}" ${key})
  if(NOT value MATCHES "^[0-9]+(\\.[0-9]+)?$" OR NOT value GREATER 0)
    message(FATAL_ERROR "silicon_summary.json: ${key} = '${value}', want a number > 0")
  endif()
  message(STATUS "${key}: ${value}")
endforeach()
string(JSON worst GET "${summary}" worst_path startpoint)
if(worst STREQUAL "")
  message(FATAL_ERROR "silicon_summary.json: no worst path named")
endif()
string(JSON share_count LENGTH "${summary}" shares)
if(NOT share_count EQUAL 3)
  message(FATAL_ERROR "silicon_summary.json: ${share_count} shares, want 3 (AXI top, register block, device)")
endif()
math(EXPR last "${share_count} - 1")
foreach(k RANGE ${last})
  string(JSON name GET "${summary}" shares ${k} name)
  string(JSON cells GET "${summary}" shares ${k} cells)
  if(NOT cells GREATER 0)
    message(FATAL_ERROR "share '${name}': ${cells} cells, want > 0")
  endif()
  message(STATUS "share ${name}: ${cells} cells")
endforeach()
# The hierarchy kept: the register block and the device are instances of the top.
file(STRINGS ${OUT}/mapped.v instances REGEX "specular_(reg_block|device_sync) +(regs|device) \\($")
list(LENGTH instances found)
if(NOT found EQUAL 2)
  message(FATAL_ERROR "mapped.v: want the instances regs (specular_reg_block) and device "
          "(specular_device_sync), found: ${instances}")
endif()
file(READ ${OUT}/sta.log sta_log)
if(sta_log MATCHES "(^|\n)Error")
  message(FATAL_ERROR "OpenSTA's log has an error:\n${sta_log}")
endif()
message(STATUS "specular_ip_axi: report, shares, regs and device instances, T_sta all there")
