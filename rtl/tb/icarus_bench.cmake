# icarus_bench.cmake: how the rtl/ tests' CMake drivers compile a bench with Icarus
# (include() it). icarus_compile(TOP VVP TESTBENCH ARGS...): iverilog -g2005 -Wall with
# `timescale's warning off (the device's files carry none, docs/rtl.md), the bench's own
# folder on the include path (its rtl/tb/*.vh, docs/testing/verilog_bench_library.md),
# ARGS (parameters, sources) before the bench; any error or warning fails the test.
function(icarus_compile top vvp testbench)
  get_filename_component(tb_dir ${testbench} DIRECTORY)
  execute_process(
    COMMAND ${IVERILOG} -g2005 -Wall -Wno-timescale -o ${vvp} -s ${top} -I${tb_dir} ${ARGN} ${testbench}
    RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT status EQUAL 0 OR log MATCHES "[Ww]arning")
    message(FATAL_ERROR "iverilog failed or warned (status ${status}):\n${log}")
  endif()
endfunction()
