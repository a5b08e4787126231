# Finds SystemC 2.3.x and exposes it as the target SystemC::systemc.
# Accellera's CMake package is used when present; Debian ships only a pkg-config
# file, so we fall back to that and wrap it in an INTERFACE IMPORTED target whose
# include directory is a SYSTEM one (our -Werror must not fire on SystemC's headers).
if(TARGET SystemC::systemc)
  return()
endif()

find_package(SystemCLanguage CONFIG QUIET)
if(SystemCLanguage_FOUND AND TARGET SystemC::systemc)
  message(STATUS "SystemC: CMake package ${SystemCLanguage_VERSION}")
  return()
endif()

find_package(PkgConfig REQUIRED)
pkg_check_modules(SYSTEMC_PC REQUIRED IMPORTED_TARGET systemc)
add_library(SystemC::systemc INTERFACE IMPORTED)
target_link_libraries(SystemC::systemc INTERFACE PkgConfig::SYSTEMC_PC)
set_target_properties(SystemC::systemc PROPERTIES
  INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${SYSTEMC_PC_INCLUDE_DIRS}")
find_package(Threads REQUIRED)
target_link_libraries(SystemC::systemc INTERFACE Threads::Threads)
message(STATUS "SystemC: pkg-config ${SYSTEMC_PC_VERSION}")
