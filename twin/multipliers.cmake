# Multipliers 13–15 verilated alone (issue 13, must-have 5): rtl/device/multiplier_rgb.v at the
# parameters specular_device passes it at the default widths (NORM_W = 1 + NORM_INT +
# NORM_FRAC = 31, RGB_BITS = 8, OUT_W = 1 + OUT_INT + OUT_FRAC = 32, SHIFT = NORM_FRAC −
# OUT_FRAC = 7), as plain C++, for tests/test_rtl_multipliers.cpp. Included at the end
# of twin/CMakeLists.txt.
# Added to specular_rtl_models rather than a library of its own: that library already
# compiles Verilator's runtime (verilated.cpp), and a second copy in the same executable
# would duplicate its symbols. Verilator's generated code builds there without -Werror.
set(RTL_MULTIPLIER_RGB_PARAMS -GNORM_W=31 -GRGB_BITS=8 -GOUT_W=32 -GSHIFT=7)
set(RTL_MULTIPLIER_RGB_DIR ${CMAKE_CURRENT_BINARY_DIR}/Vmultiplier_rgb)
verilate(specular_rtl_models ${RTL_COVERAGE} PREFIX Vmultiplier_rgb TOP_MODULE multiplier_rgb
  DIRECTORY ${RTL_MULTIPLIER_RGB_DIR}
  # Relative to twin/, where Verilator runs: the installed archive names no folder of
  # this machine (issue 35, twin/CMakeLists.txt).
  SOURCES ../rtl/device/multiplier_rgb.v ../rtl/primitives/multiply_round_saturate.v
  VERILATOR_ARGS ${RTL_VERILATOR_ARGS} ${RTL_MULTIPLIER_RGB_PARAMS}
  OPT_FAST ${RTL_OPT})

# What a test needs to drive Vmultiplier_rgb directly: the model's library, its headers
# and Verilator's as SYSTEM (our -Werror is for our code), the VM_* settings the runtime
# was built with.
add_library(specular_rtl_multiplier_rgb INTERFACE)
target_link_libraries(specular_rtl_multiplier_rgb INTERFACE specular_rtl_models)
target_include_directories(specular_rtl_multiplier_rgb SYSTEM INTERFACE ${RTL_MULTIPLIER_RGB_DIR}
                           ${VERILATOR_ROOT}/include ${VERILATOR_ROOT}/include/vltstd)
target_include_directories(specular_rtl_multiplier_rgb INTERFACE ${RTL_COVERAGE_INCLUDE})
target_compile_definitions(specular_rtl_multiplier_rgb INTERFACE VM_SC=0 VM_TRACE=1
                           VM_TRACE_VCD=1 VM_COVERAGE=$<BOOL:${SPECULAR_RTL_COVERAGE}> VM_TRACE_FST=0
                           $<$<BOOL:${SPECULAR_RTL_COVERAGE}>:SPECULAR_RTL_COVERAGE=1>)

# tests/ defines its executables after this folder (tests/CMakeLists.txt globs them):
# link the test at the end of the top-level directory, once it exists.
function(specular_link_multiplier_test)
  if(TARGET test_rtl_multipliers)
    target_link_libraries(test_rtl_multipliers PRIVATE specular_rtl_multiplier_rgb)
  endif()
endfunction()
cmake_language(DEFER DIRECTORY ${PROJECT_SOURCE_DIR} CALL specular_link_multiplier_test)
