# rtl_clone_<top>: rtl/ as an integrator reads it from a clone, with no build folder and
# no ROM folder: from an empty scratch folder, Yosys elaborates TOP with the sources of
# rtl/sources.cmake (`hierarchy -check -top; proc; memory -nomap`: the ROMs stay memories,
# a 32 K-word ROM mapped to gates never finishes) and must open every $readmemh image (the
# committed ones beside the Verilog); `verilator --lint-only -Wall` reads the same top.
# -DYOSYS=... -DVERILATOR=... -DTOP=... -DSCRATCH=... [-DRTL_DIR=rtl]
if(NOT RTL_DIR)
  get_filename_component(RTL_DIR ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
endif()
include(${RTL_DIR}/sources.cmake)
set(sources ${SPECULAR_RTL_ALL_SOURCES} ${SPECULAR_RTL_IP_SOURCES} ${SPECULAR_RTL_SOC_SOURCES})
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
string(REPLACE ";" " " yosys_sources "${sources}")
execute_process(
  COMMAND ${YOSYS} -q -l ${SCRATCH}/yosys.log -p
          "read_verilog -I ${SPECULAR_RTL_INCLUDE_DIR} ${yosys_sources}; hierarchy -check -top ${TOP}; proc; memory -nomap"
  WORKING_DIRECTORY ${SCRATCH}
  RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
file(READ ${SCRATCH}/yosys.log log)
string(REGEX MATCHALL "[^\n]*(Can not open file|ERROR:|Warning:[^\n]*readmem)[^\n]*" problems "${log}")
if(NOT status EQUAL 0 OR problems)
  string(REPLACE ";" "\n" problems "${problems}")
  message(FATAL_ERROR "yosys on rtl/ from ${SCRATCH} (no ROM folder), top ${TOP}: status ${status}\n"
          "${problems}\n(whole log: ${SCRATCH}/yosys.log)")
endif()
execute_process(
  COMMAND ${VERILATOR} --lint-only -Wall --top-module ${TOP} -I${SPECULAR_RTL_INCLUDE_DIR} ${sources}
  WORKING_DIRECTORY ${SCRATCH}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT status EQUAL 0 OR out MATCHES "%Warning|%Error")
  message(FATAL_ERROR "verilator --lint-only -Wall on rtl/ (top ${TOP}): status ${status}\n${out}")
endif()
message(STATUS "${TOP} read from rtl/ with no build folder: Yosys and Verilator -Wall clean")
