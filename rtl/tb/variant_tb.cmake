# rtl_variant_tb_NAME: the generic self-checking testbench of the design variants
# (rtl/tb/specular_variant_tb.v) replays COUNT vectors of specular_variant_vectors NAME
# (the C++ model's lobe and pins 24-26) through the RTL top specular_NAME in Icarus, starts
# streamed whenever ready; it must print PASS with the clocks per result and latency.
# CORRUPT=ON: one expected value (vector 20's out_r) is changed first, and the testbench
# must stop with a MISMATCH naming that vector and pin 24 (the testbench can fail).
if(NOT COUNT)
  set(COUNT 200)
endif()
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
execute_process(COMMAND ${VECTORS_TOOL} ${NAME} --count ${COUNT} --seed 1 --out ${SCRATCH}/vectors.txt
                RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "specular_variant_vectors ${NAME} failed: ${err}")
endif()
if(CORRUPT)
  file(STRINGS ${SCRATCH}/vectors.txt lines)
  list(GET lines 20 line)
  string(REGEX REPLACE "^([^ ]+ [^ ]+ [^ ]+ [^ ]+ [^ ]+ [^ ]+ )[^ ]+" "\\1ffffffff" bad "${line}")
  list(REMOVE_AT lines 20)
  list(INSERT lines 20 "${bad}")
  list(JOIN lines "\n" text)
  file(WRITE ${SCRATCH}/vectors.txt "${text}\n")
endif()
string(REPLACE "|" ";" SOURCES "${SOURCES}")
execute_process(COMMAND ${IVERILOG} -g2005 -o ${SCRATCH}/tb.vvp -s specular_variant_tb -I${INCLUDE_DIR}
                        -DVARIANT_TOP=specular_${NAME}
                        "-Pspecular_variant_tb.VECTORS=\"${SCRATCH}/vectors.txt\""
                        ${SOURCES} ${TB}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "iverilog failed:\n${out}")
endif()
execute_process(COMMAND ${VVP} -n ${SCRATCH}/tb.vvp WORKING_DIRECTORY ${ROM_DIR}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
message(STATUS "${out}")
if(CORRUPT)
  if(NOT out MATCHES "MISMATCH vector 20 [^\n]*pin 24 \\(out_r\\): got [0-9a-f]+, want ffffffff")
    message(FATAL_ERROR "the testbench did not catch the corrupted vector 20")
  endif()
elseif(NOT out MATCHES "PASS ${COUNT} vectors: clocks_per_result [0-9.]+ latency_clocks [0-9]+")
  message(FATAL_ERROR "the testbench of specular_${NAME} did not pass")
endif()
