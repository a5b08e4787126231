# silicon_flow (ctest fixture): scripts/flows/synthesis/silicon.sh --no-gatesim maps the device onto the
# OSU 0.18 um cells and runs OpenSTA once; the silicon_* tests read its folder.
# TOP: the top module (default specular_device; specular_device_sync for the variant).
if(NOT TOP)
  set(TOP specular_device)
endif()
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND bash ${SILICON} --top ${TOP} --no-gatesim ${OUT} ${ROM_DIR}
                RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
message(STATUS "${log}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "scripts/flows/synthesis/silicon.sh failed (status ${status})")
endif()
