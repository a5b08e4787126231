# rtl_synth_report: scripts/flows/synthesis/synth.sh runs Yosys on the device and its report must be
# complete: every section present, and every summary figure a number above zero.
file(REMOVE_RECURSE ${SCRATCH})
execute_process(COMMAND bash ${SYNTH} ${SCRATCH} ${ROM_DIR} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "scripts/flows/synthesis/synth.sh failed (status ${status})")
endif()
file(READ ${SCRATCH}/synth_report.md report)
foreach(section "## Cells per block (hierarchical)" "## Flip-flops" "## ROMs"
                "## Transistor estimate" "ROM share:" "## Longest combinational path"
                "## Summary" "| multiplier 39 |" "| control unit 16" "| ROM 5 (rom5.mantissa_rom) |"
                "| ROM 38 (rom38.k_rom) |" "| **device total** |")
  string(FIND "${report}" "${section}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "synth_report.md lacks '${section}'")
  endif()
endforeach()
foreach(key total_cells flip_flops async_flip_flops rom_bits logic_transistors
            rom_transistors total_transistors gate_levels)
  if(NOT report MATCHES "\n${key}: ([0-9]+)\n")
    message(FATAL_ERROR "synth_report.md: no figure '${key}'")
  endif()
  if(CMAKE_MATCH_1 EQUAL 0)
    message(FATAL_ERROR "synth_report.md: ${key} = 0")
  endif()
  message(STATUS "${key}: ${CMAKE_MATCH_1}")
endforeach()
# ROM 5 is 2^15 words x 22 bits at the default widths: counted, not mapped to gates.
if(NOT report MATCHES "\\| ROM 5 \\(rom5.mantissa_rom\\) \\| 32 768 \\| 22 \\| 720 896 \\|")
  message(FATAL_ERROR "synth_report.md: ROM 5 not counted as 32 768 x 22 bits")
endif()
