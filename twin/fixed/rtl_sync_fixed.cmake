# Specialised verilations of the synchronous variant (docs/rtl/sync.md, "Specialised
# verilation"): specular_device_sync with its configuration — pins 19 (h), 20 (a), 34
# (carry), adder 8's saturation and the ROM 38 bank — fixed as Verilog parameters
# (FIXED_CONFIG = 1), so Verilator folds them into the datapath instead of re-evaluating
# the datapath from those inputs at every eval(). One model per configuration: the
# general model (Vspecular_device_sync_fast/_cc) stays for every other one.
#
#   specular_rtl_sync_fixed(CONSTANTS <patent|minimax-half|minimax>
#                           NORMALISATION <patent|energy|none|device-energy>
#                           SATURATION <clamp|literal>)
#
# verilates two more models into specular_rtl_models, untraced, default widths:
# Vspecular_device_sync_fixed_<tag> (the synchronous variant) and
# Vspecular_device_fixed_<tag> (the drawn twin, specular_device.v, same parameters), and
# lists them in the table that RtlSyncCycleModel / RtlCycleModel, the TLM rtl-sync / rtl
# targets and RtlSyncDevice / RtlDevice (without --vcd) consult: a run whose Config
# matches uses them. The parameters' values come from the library's own sources (constants.cpp,
# rom38_banks.h), compiled into a probe and run when CMake configures.
# The cache list SPECULAR_RTL_SYNC_FIXED (default "patent/patent/clamp", the default
# device) calls it once per entry "constants/normalisation/saturation"; each entry adds
# about a minute of build (docs/rtl.md).

set(SPECULAR_RTL_SYNC_FIXED_DIR ${CMAKE_CURRENT_LIST_DIR})

function(specular_rtl_sync_fixed)
  cmake_parse_arguments(F "" "CONSTANTS;NORMALISATION;SATURATION" "" ${ARGN})
  foreach(key CONSTANTS NORMALISATION SATURATION)
    if(NOT F_${key})
      message(FATAL_ERROR "specular_rtl_sync_fixed: ${key} missing")
    endif()
  endforeach()
  string(MAKE_C_IDENTIFIER "${F_CONSTANTS}_${F_NORMALISATION}_${F_SATURATION}" tag)
  set(probe_dir ${CMAKE_BINARY_DIR}/rtl_sync_fixed/${tag})
  file(WRITE ${probe_dir}/probe_config.h
       "#define PROBE_CONSTANTS \"${F_CONSTANTS}\"\n"
       "#define PROBE_NORMALISATION \"${F_NORMALISATION}\"\n"
       "#define PROBE_SATURATION \"${F_SATURATION}\"\n")
  try_run(probe_run probe_compiled ${probe_dir}/probe
          SOURCES ${SPECULAR_RTL_SYNC_FIXED_DIR}/fixed_params_probe.cpp
          CMAKE_FLAGS "-DINCLUDE_DIRECTORIES=${PROJECT_SOURCE_DIR}/modules/include;${probe_dir}"
          CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON
          COMPILE_OUTPUT_VARIABLE probe_log
          RUN_OUTPUT_VARIABLE probe_out)
  if(NOT probe_compiled OR NOT probe_run EQUAL 0)
    message(FATAL_ERROR "specular_rtl_sync_fixed(${F_CONSTANTS} ${F_NORMALISATION} "
            "${F_SATURATION}): ${probe_out}${probe_log}")
  endif()
  unset(probe_run CACHE)
  unset(probe_compiled CACHE)
  string(STRIP "${probe_out}" probe_out)
  string(REPLACE "\n" ";" params "${probe_out}")
  # Relative to twin/, as the sources are (twin/CMakeLists.txt: no absolute path in the archive).
  file(RELATIVE_PATH rom_words ${CMAKE_CURRENT_SOURCE_DIR} ${SPECULAR_RTL_SYNC_FIXED_DIR}/rom_words_fixed.vlt)
  verilate(specular_rtl_models ${RTL_COVERAGE} PREFIX Vspecular_device_sync_fixed_${tag}
    TOP_MODULE specular_device_sync
    SOURCES ${rom_words} ${RTL_SYNC_SOURCES}
    VERILATOR_ARGS ${RTL_VERILATOR_ARGS} ${params}
    OPT_FAST ${RTL_OPT})
  # The drawn twin (specular_device) with the same parameters: RtlCycleModel, the TLM
  # rtl target and RtlDevice (without a VCD) use it for this configuration.
  verilate(specular_rtl_models ${RTL_COVERAGE} PREFIX Vspecular_device_fixed_${tag}
    TOP_MODULE specular_device
    SOURCES ${rom_words} ${RTL_TOP} ${RTL_SOURCES}
    VERILATOR_ARGS ${RTL_VERILATOR_ARGS} ${params}
    OPT_FAST ${RTL_OPT})
  set_property(GLOBAL APPEND PROPERTY SPECULAR_RTL_SYNC_FIXED_MODELS
               "${tag}|${F_CONSTANTS}|${F_NORMALISATION}|${F_SATURATION}")
  message(STATUS "Specialised RTL models (both twins) ${tag}: ${params}")
endfunction()

# The table of the models built (twin/src/rtl_sync_fixed_table.cpp.in): call after the
# last specular_rtl_sync_fixed(); `out` receives the generated source.
function(specular_rtl_sync_fixed_table out)
  get_property(models GLOBAL PROPERTY SPECULAR_RTL_SYNC_FIXED_MODELS)
  set(FIXED_INCLUDES "")
  set(FIXED_ENTRIES "")
  foreach(model IN LISTS models)
    string(REPLACE "|" ";" fields "${model}")
    list(GET fields 0 tag)
    list(GET fields 1 constants)
    list(GET fields 2 normalisation)
    list(GET fields 3 saturation)
    string(APPEND FIXED_INCLUDES
           "#include \"Vspecular_device_sync_fixed_${tag}.h\"\n"
           "#include \"Vspecular_device_sync_fixed_${tag}___024root.h\"\n"
           "#include \"Vspecular_device_fixed_${tag}.h\"\n"
           "#include \"Vspecular_device_fixed_${tag}___024root.h\"\n")
    string(APPEND FIXED_ENTRIES
           "    entry<Vspecular_device_sync_fixed_${tag}, Vspecular_device_fixed_${tag}>(\"${constants}\", \"${normalisation}\", \"${saturation}\"),\n")
  endforeach()
  set(generated ${CMAKE_CURRENT_BINARY_DIR}/rtl_sync_fixed_table.cpp)
  configure_file(${SPECULAR_RTL_SYNC_FIXED_DIR}/rtl_sync_fixed_table.cpp.in ${generated} @ONLY)
  set(${out} ${generated} PARENT_SCOPE)
endfunction()
