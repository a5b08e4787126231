# silicon_control_unit: the mapped control unit is Fig. 2 as drawn, one library cell per
# gate and flip-flop (written here from the figure, not read from the flow):
#   inverter 44 INVX1, AND 40 AND2X1, flip-flops 41-43 DFFSR, NANDs 45, 46 NAND3X1,
#   NAND 47 NAND2X1, and an INVX1 each for /Q42 and /Q43 (the DFFSR has no /Q).
file(READ ${OUT}/mapped.v netlist)
string(REGEX MATCH "\nmodule control_unit16\\(.*\nendmodule" cu "${netlist}")
string(FIND "${cu}" "\nendmodule" end)
string(SUBSTRING "${cu}" 0 ${end} cu)
if(cu STREQUAL "")
  message(FATAL_ERROR "mapped.v has no module control_unit16")
endif()
string(REGEX MATCHALL "\n  ([A-Z0-9]+) ([^ ]+) +\\(" instances "${cu}")
set(types "")
foreach(inst IN LISTS instances)
  string(REGEX REPLACE "\n  ([A-Z0-9]+) ([^ ]+) +\\(" "\\1 \\2" inst "${inst}")
  list(APPEND types "${inst}")
endforeach()
list(SORT types)
message(STATUS "control_unit16 cells: ${types}")
foreach(want "INVX1 \\inv44.cell" "AND2X1 \\and40.cell" "DFFSR \\dff41.cell" "DFFSR \\dff42.cell"
             "DFFSR \\dff43.cell" "NAND3X1 \\nand45.cell" "NAND3X1 \\nand46.cell" "NAND2X1 \\nand47.cell")
  list(FIND types "${want}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "control_unit16 lacks '${want}' (cells: ${types})")
  endif()
  list(REMOVE_AT types ${at})
endforeach()
# What is left: the two /Q inverters, nothing else.
list(LENGTH types left)
string(REGEX MATCHALL "INVX1" inverters "${types}")
list(LENGTH inverters left_inverters)
if(NOT left EQUAL 2 OR NOT left_inverters EQUAL 2)
  message(FATAL_ERROR "control_unit16 has cells beyond Fig. 2 and the two /Q inverters: ${types}")
endif()
# NAND 45 is driven by the clock (pin 28) on one input, as drawn.
string(REGEX MATCH "NAND3X1 \\\\nand45\\.cell[^;]*;" nand45 "${cu}")
if(NOT nand45 MATCHES "\\(clk\\)")
  message(FATAL_ERROR "NAND 45 is not driven by clk: ${nand45}")
endif()
