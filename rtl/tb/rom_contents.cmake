# rtl_rom_contents_*: Icarus reads ROM 5 and ROM 38 of rtl/ through their ports
# (rom_read_tb.v) and specular_romgen --check compares every read with the C++ tables,
# failing when a word differs or was never read.
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
include(${CMAKE_CURRENT_LIST_DIR}/icarus_bench.cmake)
list(POP_BACK SOURCES testbench)  # rom_read_tb.v, last
icarus_compile(rom_read_tb ${SCRATCH}/rom_read.vvp ${testbench}
               "-Prom_read_tb.ROM5_IMAGE=\"${ROM_DIR}/rom5.hex\""
               "-Prom_read_tb.ROM38_IMAGE=\"${ROM_DIR}/rom38.hex\""
               "-Prom_read_tb.DUMP=\"${SCRATCH}/rom_dump.txt\"" ${PARAMS} ${SOURCES})
execute_process(COMMAND ${VVP} -n ${SCRATCH}/rom_read.vvp RESULT_VARIABLE status
                OUTPUT_VARIABLE out ERROR_VARIABLE out)
message(STATUS "${out}")
if(NOT status EQUAL 0 OR NOT out MATCHES "rom_read_tb: dumped" OR out MATCHES "WARNING|ERROR|FATAL")
  message(FATAL_ERROR "rom_read_tb failed (status ${status})")
endif()
execute_process(COMMAND ${ROMGEN} --check ${SCRATCH}/rom_dump.txt ${WIDTHS}
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the RTL's ROM reads differ from the C++ tables (status ${status})")
endif()
