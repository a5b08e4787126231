# ip_verilog_current: specular_ip_export --verilog writes the register block again and it
# must equal the committed rtl/ip/specular_reg_block.v byte for byte (edit the register
# map, then run `specular_ip_export --verilog rtl/ip/specular_reg_block.v`).
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
execute_process(COMMAND ${EXPORT} --verilog ${SCRATCH}/specular_reg_block.v RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "specular_ip_export --verilog failed (status ${status})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${SCRATCH}/specular_reg_block.v ${COMMITTED}
                RESULT_VARIABLE differs)
if(differs)
  message(FATAL_ERROR "${COMMITTED} differs from what specular_ip_export --verilog writes now "
          "(${SCRATCH}/specular_reg_block.v): regenerate it from the register map")
endif()
message(STATUS "rtl/ip/specular_reg_block.v is current")
