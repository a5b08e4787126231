# silicon_sta: OpenSTA timed the pass loop and the control unit: the named paths exist,
# pass 1 and pass 2 run through ROM 5 (its macro), multiplier 6 and adder 8 into register 9,
# the output path ends at a pin 24-26, the control unit's path joins 41 to 42 or 42 to 43,
# and at T_sta no path has negative slack while at 0.9 T_sta... is left to the bisection
# (the worst slack at T_sta is between 0 and 0.01 ns).
file(READ ${OUT}/sta_summary.txt sta)
if(NOT sta MATCHES "worst_slack_ns (-?[0-9.]+)")
  message(FATAL_ERROR "sta_summary.txt has no worst slack")
endif()
if(CMAKE_MATCH_1 LESS 0 OR CMAKE_MATCH_1 GREATER 0.05)
  message(FATAL_ERROR "worst slack at T_sta is ${CMAKE_MATCH_1} ns, want 0 to 0.05 (bisection)")
endif()
foreach(path pass1 pass2_select pass2_loop)
  file(READ ${OUT}/path_${path}.txt text)
  foreach(through "ROM5_MACRO" "mul6/" "adder8/" "Endpoint: reg9/" "slack (MET)")
    string(FIND "${text}" "${through}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "path_${path}.txt does not pass '${through}'")
    endif()
  endforeach()
endforeach()
file(READ ${OUT}/path_output.txt text)
if(NOT text MATCHES "Endpoint: pin2[456]_" OR NOT text MATCHES "mul39/" OR NOT text MATCHES "Startpoint: reg9/")
  message(FATAL_ERROR "path_output.txt is not register 9 -> multiplier 39 -> pins 24-26")
endif()
file(READ ${OUT}/path_control_unit.txt text)
if(NOT text MATCHES "Startpoint: cu16/dff4[12]\\.cell" OR NOT text MATCHES "Endpoint: cu16/dff4[23]\\.cell")
  message(FATAL_ERROR "path_control_unit.txt is not a path between flip-flops 41-43")
endif()
# Clocks as drawn: register 9 is clocked through NANDs 45 and 47 (strobe 37), 42 and 43
# through inverter 44.
file(READ ${OUT}/path_pass2_select.txt text)
if(NOT text MATCHES "clocked by clk'")
  message(FATAL_ERROR "pass 2 does not start at flip-flop 43 on the inverted clock")
endif()
