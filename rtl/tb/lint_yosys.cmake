# rtl_lint_yosys: Yosys reads the device, checks the hierarchy and every net
# (`check -assert` fails on undriven nets, multiple drivers and logic loops), and no
# warning remains beyond the one docs/rtl/checks.md explains: "Complex async reset" for
# d_flip_flop, a flip-flop with both asynchronous R and S, as Fig. 2 draws it.
# Run from the ROM folder: rom5/rom38 read their images with $readmemh.
# TOP (default specular_device) and EXPLAINED (how many of those warnings to expect,
# default 1): the synchronous variant, specular_device_sync, has no such flip-flop and
# must give no warning at all.
if(NOT TOP)
  set(TOP specular_device)
endif()
if(NOT DEFINED EXPLAINED)
  set(EXPLAINED 1)
endif()
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
string(REPLACE ";" " " sources "${SOURCES}")
execute_process(
  COMMAND ${YOSYS} -l ${SCRATCH}/yosys.log -p
          "read_verilog ${sources}; hierarchy -check -top ${TOP}; proc; check -assert"
  WORKING_DIRECTORY ${ROM_DIR}
  RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
file(READ ${SCRATCH}/yosys.log log)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "yosys failed (status ${status}):\n${log}")
endif()
string(REGEX MATCHALL "Warning: [^\n]*" warnings "${log}")
set(unexplained "")
set(explained 0)
foreach(warning IN LISTS warnings)
  if(warning MATCHES "^Warning: Complex async reset for dff `\\\\q'\\.$")
    math(EXPR explained "${explained} + 1")
  else()
    list(APPEND unexplained "${warning}")
  endif()
endforeach()
if(unexplained)
  string(REPLACE ";" "\n" unexplained "${unexplained}")
  message(FATAL_ERROR "yosys warnings not explained in docs/rtl/checks.md:\n${unexplained}")
endif()
if(NOT explained EQUAL EXPLAINED)
  message(FATAL_ERROR "expected ${EXPLAINED} 'Complex async reset' warning(s) of d_flip_flop, saw ${explained}")
endif()
message(STATUS "yosys (${TOP}): hierarchy, proc, check -assert pass; ${explained} warning(s), explained (docs/rtl/checks.md)")
