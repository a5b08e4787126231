# silicon_report: the report of scripts/flows/synthesis/silicon.sh is complete: every section, every
# headline figure of silicon_summary.json above zero, ROM 5 a macro of 32 768 x 22 bits
# (never gates), the logic area the sum of the blocks' areas.
file(READ ${OUT}/silicon_report.md report)
include(${CMAKE_CURRENT_LIST_DIR}/silicon_test_support.cmake)
expect_sections("${report}" silicon_report.md
                "## Area per block" "## ROM macros" "## Area total" "## Cells and flip-flops"
                "## Control unit 16: Fig. 2's gates" "## Static timing (OpenSTA)"
                "## Results per second" "## T_sta beside T_sim"
                "## Fig. 2's hazards in the gate-level simulation"
                "## What STA does not time, and what it assumes there" "## Summary"
                "| multiplier 6 |" "| multiplier 39 |" "| register 9 |" "| control unit 16"
                "| ROM5_MACRO | 32 768 x 22 |" "| ROM38_MACRO | 16 384 x 25 |"
                "| ROM38_BANK_MACRO | 1 024 x 25 |" "| pass 1 |" "| pass 2 from select 36 |"
                "| output to pins 24-26 |")
file(READ ${OUT}/silicon_summary.json summary)
foreach(key area_logic_um2 area_macros_um2 area_total_um2 area_total_one_rom38_bank_um2
            die_area_estimate_mm2 cells flip_flops t_sta_ns results_per_second_streamed_at_t_sta
            results_per_second_reload_at_t_sta results_per_second_per_mm2_streamed)
  string(JSON value GET "${summary}" ${key})
  if(NOT value GREATER 0)
    message(FATAL_ERROR "silicon_summary.json: ${key} = '${value}', want > 0")
  endif()
  message(STATUS "${key}: ${value}")
endforeach()
# Flip-flops: registers 1, 2, 9, 10-12 (17 + 10 + 37 + 3 x 8 = 88) and 41-43.
string(JSON flip_flops GET "${summary}" flip_flops)
if(NOT flip_flops EQUAL 91)
  message(FATAL_ERROR "silicon_summary.json: ${flip_flops} flip-flops, want 88 + 3 = 91")
endif()
# Results per second from T_sta: 1 / (2 T) streamed, 1 / (3 T) with a reload.
string(JSON t_sta GET "${summary}" t_sta_ns)
string(JSON streamed GET "${summary}" results_per_second_streamed_at_t_sta)
# (t_sta has two decimals: T_sta * 100 in 1/100 ns, 1e9 / (2 T) = 1e11 / (2 * 100 T))
string(REPLACE "." "" t_sta_centi "${t_sta}")
math(EXPR want "100000000000 / (2 * ${t_sta_centi})")
math(EXPR diff "${streamed} - ${want}")
if(diff GREATER 1 OR diff LESS -1)
  message(FATAL_ERROR "results/s streamed ${streamed}, want 1e9 / (2 x ${t_sta} ns) = ${want}")
endif()
# ROMs are macros: no memory left in the netlist, and the macros in it.
file(READ ${OUT}/mapped.v netlist)
foreach(macro "ROM5_MACRO " "ROM38_MACRO ")
  string(FIND "${netlist}" "${macro}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "mapped.v has no ${macro}instance")
  endif()
endforeach()
string(FIND "${netlist}" "$mem" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "mapped.v holds a memory that is not a ROM macro")
endif()
# Every file the issue names.
foreach(f mapped.v constraints.sdc device.sdf rom_macros.lib yosys.log sta.log)
  if(NOT EXISTS ${OUT}/${f})
    message(FATAL_ERROR "silicon.sh wrote no ${f}")
  endif()
endforeach()
