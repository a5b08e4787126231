# rtl_icarus_*: specular_tb writes the vectors (--format csv; the pin model's hex codes)
# for one policy combination, Icarus compiles the device with specular_device_tb.v and
# replays them. Stimulus: groups of operations with n, R, G, B unchanged (back-to-back
# starts at 2 T), edge cases of cos and n, then random operations (a reload, 3 T, each).
# CORRUPT=ON: one expected value is changed first, and the testbench must stop with a
# MISMATCH on that vector (the testbench can fail). EXPECT_MISMATCH=ON: the first
# vector must already mismatch (vectors of one width set, testbench of another).
# WIDTHS: specular_tb's --width options of the width set, PARAMS: the device's
# parameters of the same set (NAME=VALUE), both '|'-separated and empty for the
# default set; ROM_DIR holds that set's images.
# TB_TOP names the testbench module (default specular_device_tb; the synchronous
# variant's is specular_device_sync_tb, with its own timing).
if(NOT TB_TOP)
  set(TB_TOP specular_device_tb)
endif()
string(REPLACE "|" ";" SOURCES "${SOURCES}")
string(REPLACE "|" ";" WIDTHS "${WIDTHS}")
string(REPLACE "|" ";" PARAMS "${PARAMS}")
list(TRANSFORM PARAMS PREPEND -P${TB_TOP}.)
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})

set(stimulus "cos,n,r,g,b\n")
set(groups "1,255,255,255" "2,0,128,255" "3,1,2,3" "10,255,0,17" "64,200,100,50"
           "500,255,255,255" "999,7,77,177" "1000,255,254,253")
set(cosines 0 1 0.5 1.52587890625e-05 0.9999847412109375 0.70710678 0.25 0.999 0.05 0.9)
foreach(group IN LISTS groups)
  string(REPLACE "," ";" fields "${group}")
  list(GET fields 0 n)
  list(REMOVE_AT fields 0)
  string(REPLACE ";" "," rgb "${fields}")
  foreach(cos IN LISTS cosines)
    string(APPEND stimulus "${cos},${n},${rgb}\n")
  endforeach()
endforeach()
# One more group: every cos code 2^k for k = 1..15 (cos = 2^(k-16) at the default 16
# fraction bits). ROM 5's zero test and leading-one search see a single set bit at each
# position of its bus; with none of them here, a zero test blind to one bus bit survived
# the mutants (docs/testing/coverage.md, "Coverage and mutants: how strong the suite is"). Appended, so the vectors before
# it (and the CORRUPT vector 37) are unchanged.
set(powers_of_two 0.000030517578125 0.00006103515625 0.0001220703125 0.000244140625
                 0.00048828125 0.0009765625 0.001953125 0.00390625 0.0078125 0.015625
                 0.03125 0.0625 0.125 0.25 0.5)
foreach(cos IN LISTS powers_of_two)
  string(APPEND stimulus "${cos},5,9,99,199\n")
endforeach()
# And one where register 9 after pass 1, 1 + n*k for cos = 2^-k under the patent's
# constants (a = 1; ROM 5 is exact at a power of two), is itself a power of two 2^m, for
# every m that some n <= 1000 and k <= 16 reach: ROM 5 then reads a single set bit at
# each position 23-32 and 34 of its bus in pass 2 (n*k = 2^m - 1).
foreach(operands "0.5,1" "0.5,3" "0.5,7" "0.5,15" "0.5,31" "0.5,63" "0.5,127" "0.5,255" "0.5,511"
                 "0.125,341" "0.03125,819")
  string(APPEND stimulus "${operands},9,99,199\n")
endforeach()
file(WRITE ${SCRATCH}/stimulus.csv "${stimulus}")

# A different random draw per combination.
string(LENGTH "${SATURATION}" seed)
math(EXPR seed "${seed} * 16 + ${CONSTANTS_VALUE} * 4 + ${NORMALISATION_VALUE}")
set(policy_options --constants ${CONSTANTS} --policy ${NORMALISATION} --saturation ${SATURATION}
                   ${WIDTHS})
execute_process(COMMAND ${SPECULAR_TB} ${policy_options}
                        --input ${SCRATCH}/stimulus.csv --format csv --output ${SCRATCH}/groups.csv
                RESULT_VARIABLE status ERROR_VARIABLE summary)
if(status EQUAL 2 AND summary MATCHES "saturation literal with normalisation")
  # A combination the device refuses (K*A beyond multiplier 39's format): nothing to
  # replay; the test reports itself skipped (SKIP_REGULAR_EXPRESSION).
  message(STATUS "rtl_icarus: combination refused by the model: ${summary}")
  return()
endif()
if(NOT status MATCHES "^[01]$")  # 1: a value outside the reference's tolerance (literal)
  message(FATAL_ERROR "specular_tb --input failed (status ${status}): ${summary}")
endif()
execute_process(COMMAND ${SPECULAR_TB} ${policy_options}
                        --random 300 --seed ${seed} --format csv --output ${SCRATCH}/random.csv
                RESULT_VARIABLE status ERROR_VARIABLE summary)
if(NOT status MATCHES "^[01]$")
  message(FATAL_ERROR "specular_tb --random failed (status ${status}): ${summary}")
endif()

file(STRINGS ${SCRATCH}/groups.csv groups_lines)
file(STRINGS ${SCRATCH}/random.csv random_lines)
list(REMOVE_AT random_lines 0)  # its header
set(lines ${groups_lines} ${random_lines})
set(corrupt_vector 37)
if(CORRUPT)
  # Vector 37 (line 38): flip the last hex digit of pin 26's expected code.
  math(EXPR line_index "${corrupt_vector} + 1")
  list(GET lines ${line_index} line)
  string(REGEX MATCH "([0-9a-f]),[01]$" tail "${line}")
  if(CMAKE_MATCH_1 STREQUAL "0")
    set(digit 1)
  else()
    set(digit 0)
  endif()
  string(REGEX REPLACE "[0-9a-f](,[01])$" "${digit}\\1" line "${line}")
  list(REMOVE_AT lines ${line_index})
  list(INSERT lines ${line_index} "${line}")
endif()
string(REPLACE ";" "\n" vectors "${lines}")
file(WRITE ${SCRATCH}/vectors.csv "${vectors}\n")

if(SATURATION STREQUAL "literal")
  set(literal 1)
else()
  set(literal 0)
endif()
include(${CMAKE_CURRENT_LIST_DIR}/icarus_bench.cmake)
icarus_compile(${TB_TOP} ${SCRATCH}/device_tb.vvp ${TESTBENCH}
               "-P${TB_TOP}.ROM5_IMAGE=\"${ROM_DIR}/rom5.hex\""
               "-P${TB_TOP}.ROM38_IMAGE=\"${ROM_DIR}/rom38.hex\""
               "-P${TB_TOP}.VECTORS=\"${SCRATCH}/vectors.csv\""
               "-P${TB_TOP}.PINS_IMAGE=\"${ROM_DIR}/pins.hex\""
               -P${TB_TOP}.LITERAL=${literal}
               -P${TB_TOP}.CONSTANTS=${CONSTANTS_VALUE}
               -P${TB_TOP}.NORMALISATION=${NORMALISATION_VALUE}
               ${PARAMS} ${SOURCES})
execute_process(COMMAND ${VVP} -n ${SCRATCH}/device_tb.vvp RESULT_VARIABLE status
                OUTPUT_VARIABLE out ERROR_VARIABLE out)
message(STATUS "${out}")
if(EXPECT_MISMATCH)
  if(status EQUAL 0 OR NOT out MATCHES "MISMATCH vector 0 ")
    message(FATAL_ERROR "the testbench should have stopped on vector 0 (status ${status})")
  endif()
  message(STATUS "the testbench stopped on vector 0, as it must (status ${status})")
elseif(CORRUPT)
  if(status EQUAL 0 OR NOT out MATCHES "MISMATCH vector ${corrupt_vector} [^\n]*pin 26")
    message(FATAL_ERROR "the corrupted expected value of vector ${corrupt_vector} was not caught "
            "(status ${status})")
  endif()
  message(STATUS "the testbench stopped on the corrupted vector ${corrupt_vector} (status ${status})")
elseif(NOT status EQUAL 0 OR NOT out MATCHES "${TB_TOP}: PASS" OR out MATCHES "WARNING")
  message(FATAL_ERROR "${TB_TOP} failed (status ${status})")
endif()
