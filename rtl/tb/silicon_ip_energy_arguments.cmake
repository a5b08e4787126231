# silicon_ip_energy_arguments: scripts/flows/energy/energy_ip.sh refuses bad arguments with exit 2 and
# a message naming the bad value and the allowed range, before any replay; --help exits 0.
include(${CMAKE_CURRENT_LIST_DIR}/silicon_test_support.cmake)  # expect_refusal
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH}/empty)
expect_refusal("usage" ${ENERGY_IP})
expect_refusal("unknown option '--frobnicate'" ${ENERGY_IP} --frobnicate ${SCRATCH}/x)
expect_refusal("--period '0.5' is not a period in ns from 1 to 1000" ${ENERGY_IP} --period 0.5 ${SCRATCH}/x)
expect_refusal("--operations '0' is not a count from 1 to 5000" ${ENERGY_IP} --operations 0 ${SCRATCH}/x)
expect_refusal("--operations '5001' is not a count from 1 to 5000" ${ENERGY_IP} --operations 5001 ${SCRATCH}/x)
expect_refusal("--accesses '0' is not a count from 1 to 5000" ${ENERGY_IP} --accesses 0 ${SCRATCH}/x)
expect_refusal("--accesses 'many' is not a count" ${ENERGY_IP} --accesses many ${SCRATCH}/x)
expect_refusal("mapped.v' not found: run scripts/flows/synthesis/silicon.sh --top specular_ip_axi first"
               ${ENERGY_IP} --netlist-dir ${SCRATCH}/empty ${SCRATCH}/x)
execute_process(COMMAND bash ${ENERGY_IP} --help RESULT_VARIABLE status OUTPUT_VARIABLE out)
if(NOT status EQUAL 0 OR NOT out MATCHES "OUT_DIR")
  message(FATAL_ERROR "${ENERGY_IP} --help: status ${status}")
endif()
message(STATUS "energy_ip.sh: every bad argument refused with exit 2 and its value named")
