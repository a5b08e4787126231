# SpecularUnitFirmware: the IP's firmware side alone (issue 35): plain C99, no SystemC,
# no C++ library, the same for every target architecture (its version file is
# architecture-independent), so a cross-compiling firmware build takes it:
#
#   find_package(SpecularUnitFirmware CONFIG REQUIRED)
#   target_link_libraries(fw PRIVATE SpecularUnit::firmware_driver)  # compiles the driver in
#   target_link_libraries(fw PRIVATE SpecularUnit::firmware)         # the headers only
#
# find_package(SpecularUnit) gives the same two targets to a host project.
include("${CMAKE_CURRENT_LIST_DIR}/SpecularUnitFirmwareTargets.cmake")
