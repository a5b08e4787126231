# SystemC for SpecularUnit, 2.3 or 3.0: finds it, exposes it as the target
# SystemC::systemc and says which one it is. Used twice:
#   - by the IP's build (CMakeLists.txt): Accellera's CMake package SystemCLanguage
#     (SystemC built from source: -DSystemCLanguage_DIR=<prefix>/lib/cmake/SystemCLanguage
#     or -DCMAKE_PREFIX_PATH=<prefix>), else pkg-config's systemc.pc (Debian's
#     libsystemc-dev ships only that). The build records the result in the package.
#   - installed beside the package, by SpecularUnitConfig.cmake, which first sets
#     SpecularUnit_SYSTEMC_* to that record: the recorded SystemC is looked for first, by
#     the same route at the same place, and whatever SystemC the consumer ends up with
#     must be that one, or the package is NOT FOUND with a message saying why
#     (docs/integration/package.md). The consumer chooses another SystemC with its own
#     SystemC::systemc target (found before SpecularUnit) or with SystemCLanguage_DIR.
#
# A SystemC is told apart by the symbol of its link-time check,
# sc_api_version_<major>_<minor>_<patch>_cxx<__cplusplus>L: every object compiled with
# SystemC's headers references the one of those headers' version and of the C++ standard
# it was compiled with, and a library defines only the one it was built as. It is read
# from the library file's text (ELF .so or .a alike), so no program is compiled or run.
#
# Results:
#   SPECULAR_SYSTEMC_FOUND_BY  "CMake package", "pkg-config", or "target" (SystemC::systemc
#                              existed already, made by the project that includes us)
#   SPECULAR_SYSTEMC_LOCATION  the SystemCLanguage_DIR, the folder of systemc.pc, or the
#                              library (target)
#   SPECULAR_SYSTEMC_LIBRARY   the library file ("" when unknown, e.g. not built yet)
#   SPECULAR_SYSTEMC_VERSION   e.g. 2.3.4: from the symbol, else sysc/kernel/sc_ver.h
#   SPECULAR_SYSTEMC_API       e.g. sc_api_version_2_3_4_cxx201703L ("" when unknown)
#   SPECULAR_SYSTEMC_CXX       the library's C++ standard, e.g. 17 ("" when unknown)

# The library files and include folders behind a target, through its link items.
# Accumulates into _specular_walk_libraries and _specular_walk_includes.
function(_specular_systemc_walk target depth)
  if(depth GREATER 4)
    return()
  endif()
  get_target_property(aliased ${target} ALIASED_TARGET)
  if(aliased)
    set(target ${aliased})
  endif()
  get_target_property(type ${target} TYPE)
  get_target_property(imported ${target} IMPORTED)
  if(imported AND NOT type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(location ${target} LOCATION)
    if(location)
      list(APPEND _specular_walk_libraries "${location}")
    endif()
  endif()
  foreach(property INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
    get_target_property(dirs ${target} ${property})
    if(dirs)
      list(APPEND _specular_walk_includes ${dirs})
    endif()
  endforeach()
  get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
  if(links)
    math(EXPR next "${depth} + 1")
    foreach(item IN LISTS links)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
      if(TARGET "${item}")
        _specular_systemc_walk("${item}" ${next})
      elseif(IS_ABSOLUTE "${item}")
        list(APPEND _specular_walk_libraries "${item}")
      endif()
    endforeach()
  endif()
  set(_specular_walk_libraries "${_specular_walk_libraries}" PARENT_SCOPE)
  set(_specular_walk_includes "${_specular_walk_includes}" PARENT_SCOPE)
endfunction()

# "C++17" for 17, "C++ with __cplusplus 202100L" for what is not a standard's value.
function(_specular_systemc_cxx_name out cxx api)
  if(cxx)
    set(${out} "C++${cxx}" PARENT_SCOPE)
  elseif(api MATCHES "_cxx([0-9]+L)$")
    set(${out} "C++ with __cplusplus ${CMAKE_MATCH_1}" PARENT_SCOPE)
  else()
    set(${out} "an unknown C++ standard" PARENT_SCOPE)
  endif()
endfunction()

# Sets SPECULAR_SYSTEMC_* (above) for SystemC::systemc, found by `found_by` at `location`.
function(_specular_systemc_describe found_by location)
  set(_specular_walk_libraries "")
  set(_specular_walk_includes "")
  _specular_systemc_walk(SystemC::systemc 0)
  set(pattern "sc_api_version_[0-9]+_[0-9]+_[0-9]+_cxx[0-9]+L")
  set(library "")
  set(api "")
  foreach(file IN LISTS _specular_walk_libraries)
    get_filename_component(name "${file}" NAME)
    if(name MATCHES "systemc" AND EXISTS "${file}" AND NOT IS_DIRECTORY "${file}")
      set(library "${file}")
      file(STRINGS "${file}" texts REGEX "${pattern}")
      string(REGEX MATCHALL "${pattern}" apis "${texts}")
      list(REMOVE_DUPLICATES apis)
      list(LENGTH apis count)
      if(count EQUAL 1)
        set(api "${apis}")
      endif()
      break()
    endif()
  endforeach()

  set(version "")
  set(cxx "")
  if(api MATCHES "^sc_api_version_([0-9]+)_([0-9]+)_([0-9]+)_cxx([0-9]+)L$")
    set(version "${CMAKE_MATCH_1}.${CMAKE_MATCH_2}.${CMAKE_MATCH_3}")
    set(cplusplus ${CMAKE_MATCH_4})
    # __cplusplus is the standard's year and month.
    foreach(pair 199711:98 201103:11 201402:14 201703:17 202002:20 202302:23)
      string(REPLACE ":" ";" pair "${pair}")
      list(GET pair 0 value)
      if(cplusplus STREQUAL value)
        list(GET pair 1 cxx)
      endif()
    endforeach()
  else()  # no library to read (e.g. built later, in the same project): the headers' version
    foreach(dir IN LISTS _specular_walk_includes CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES)
      if(NOT dir MATCHES "\\$<" AND EXISTS "${dir}/sysc/kernel/sc_ver.h")
        file(STRINGS "${dir}/sysc/kernel/sc_ver.h" defines
             REGEX "^#[ \t]*define[ \t]+SC_VERSION_(MAJOR|MINOR|PATCH)[ \t]+[0-9]+")
        set(parts "")
        foreach(part MAJOR MINOR PATCH)
          foreach(line IN LISTS defines)
            if(line MATCHES "SC_VERSION_${part}[ \t]+([0-9]+)")
              list(APPEND parts ${CMAKE_MATCH_1})
            endif()
          endforeach()
        endforeach()
        string(REPLACE ";" "." version "${parts}")
        break()
      endif()
    endforeach()
  endif()
  if(found_by STREQUAL "target")
    set(location "${library}")
  endif()
  set(SPECULAR_SYSTEMC_FOUND_BY "${found_by}" PARENT_SCOPE)
  set(SPECULAR_SYSTEMC_LOCATION "${location}" PARENT_SCOPE)
  set(SPECULAR_SYSTEMC_LIBRARY "${library}" PARENT_SCOPE)
  set(SPECULAR_SYSTEMC_VERSION "${version}" PARENT_SCOPE)
  set(SPECULAR_SYSTEMC_API "${api}" PARENT_SCOPE)
  set(SPECULAR_SYSTEMC_CXX "${cxx}" PARENT_SCOPE)
endfunction()

# pkg-config's systemc.pc as SystemC::systemc: an INTERFACE IMPORTED target whose include
# folder is a SYSTEM one (our -Werror must not fire on SystemC's headers). `only_dir`:
# look there only (the recorded SystemC), else pkg-config's usual search. Sets
# _specular_pc_dir to the folder of the systemc.pc found.
macro(_specular_systemc_pkg_config only_dir)
  find_package(PkgConfig QUIET)
  set(_specular_pc_dir "")
  if(PKG_CONFIG_FOUND)
    set(_specular_saved_path "$ENV{PKG_CONFIG_PATH}")
    set(_specular_saved_use_prefix "${PKG_CONFIG_USE_CMAKE_PREFIX_PATH}")
    if(NOT "${only_dir}" STREQUAL "")
      set(ENV{PKG_CONFIG_PATH} "${only_dir}")
      set(PKG_CONFIG_USE_CMAKE_PREFIX_PATH FALSE)
    endif()
    pkg_check_modules(SYSTEMC_PC QUIET IMPORTED_TARGET systemc)
    if(SYSTEMC_PC_FOUND)
      pkg_get_variable(_specular_pc_dir systemc pcfiledir)
    endif()
    set(ENV{PKG_CONFIG_PATH} "${_specular_saved_path}")
    set(PKG_CONFIG_USE_CMAKE_PREFIX_PATH "${_specular_saved_use_prefix}")
    if(SYSTEMC_PC_FOUND AND NOT "${only_dir}" STREQUAL "" AND NOT _specular_pc_dir STREQUAL "${only_dir}")
      set(SYSTEMC_PC_FOUND FALSE)  # another systemc.pc than the recorded one
    endif()
    if(SYSTEMC_PC_FOUND)
      add_library(SystemC::systemc INTERFACE IMPORTED)
      target_link_libraries(SystemC::systemc INTERFACE PkgConfig::SYSTEMC_PC)
      set_target_properties(SystemC::systemc PROPERTIES
        INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${SYSTEMC_PC_INCLUDE_DIRS}")
      find_package(Threads REQUIRED)
      target_link_libraries(SystemC::systemc INTERFACE Threads::Threads)
    endif()
  endif()
endmacro()

# Accellera's CMake package; its include folders made SYSTEM ones too.
macro(_specular_systemc_cmake_package)
  find_package(SystemCLanguage CONFIG QUIET ${ARGN})
  if(SystemCLanguage_FOUND AND TARGET SystemC::systemc)
    get_target_property(_specular_dirs SystemC::systemc INTERFACE_INCLUDE_DIRECTORIES)
    if(_specular_dirs)
      set_property(TARGET SystemC::systemc APPEND PROPERTY
                   INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${_specular_dirs})
    endif()
  endif()
endmacro()

# ---- a second SystemC beside the package's (issue 35) ---------------------------------
# A program that links the package's SystemC and another one (say its own pkg-config
# systemc, Debian's 2.3.4, beside a package built on 3.0.2) links, then crashes in
# SystemC's static initialisers. When the project's top-level CMakeLists.txt has been
# read, every target that links SpecularUnit::specular is checked for a SystemC library
# file other than the package's (a target such as PkgConfig::X, or a path); one is a
# configure error naming the target and both files. (A bare `-lsystemc` is not resolved.)

# The library files `item` (a target or a path) brings, through its link items.
function(_specular_systemc_link_files item depth out)
  set(files "")
  string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
  if(depth GREATER 8 OR item MATCHES "\\$<")
  elseif(TARGET "${item}")
    get_target_property(aliased "${item}" ALIASED_TARGET)
    if(aliased)
      set(item "${aliased}")
    endif()
    get_target_property(type "${item}" TYPE)
    get_target_property(imported "${item}" IMPORTED)
    if(imported AND NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(location "${item}" LOCATION)
      if(location)
        list(APPEND files "${location}")
      endif()
    endif()
    set(links "")
    foreach(property LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
      if(NOT (property STREQUAL "LINK_LIBRARIES" AND (imported OR type STREQUAL "INTERFACE_LIBRARY")))
        get_target_property(more "${item}" ${property})
        if(more)
          list(APPEND links ${more})
        endif()
      endif()
    endforeach()
    math(EXPR next "${depth} + 1")
    foreach(link IN LISTS links)
      _specular_systemc_link_files("${link}" ${next} more)
      list(APPEND files ${more})
    endforeach()
  elseif(IS_ABSOLUTE "${item}")
    list(APPEND files "${item}")
  endif()
  set(${out} "${files}" PARENT_SCOPE)
endfunction()

function(_specular_systemc_check_mix ours)
  get_filename_component(ours_real "${ours}" REALPATH)
  set(folders "${CMAKE_SOURCE_DIR}")
  while(folders)
    list(POP_FRONT folders folder)
    get_property(subfolders DIRECTORY "${folder}" PROPERTY SUBDIRECTORIES)
    list(APPEND folders ${subfolders})
    get_property(targets DIRECTORY "${folder}" PROPERTY BUILDSYSTEM_TARGETS)
    foreach(target IN LISTS targets)
      get_target_property(type ${target} TYPE)
      if(NOT type MATCHES "^(EXECUTABLE|SHARED_LIBRARY|MODULE_LIBRARY)$")
        continue()
      endif()
      _specular_systemc_link_files(${target} 0 files)
      set(has_ours FALSE)
      set(others "")
      foreach(file IN LISTS files)
        get_filename_component(name "${file}" NAME)
        if(name MATCHES "^(lib)?systemc([-.].*)?\\.(so|a|dylib|lib)(\\..*)?$")
          get_filename_component(real "${file}" REALPATH)
          if(real STREQUAL ours_real)
            set(has_ours TRUE)
          else()
            list(APPEND others "${file}")
          endif()
        endif()
      endforeach()
      if(has_ours AND others)
        list(REMOVE_DUPLICATES others)
        string(JOIN ", " others ${others})
        message(FATAL_ERROR "Target ${target} (${folder}) links SpecularUnit's SystemC, ${ours}, "
                "and another SystemC library beside it: ${others}. Two SystemC libraries in one "
                "program break in SystemC's static initialisers before main runs. Link only "
                "SystemC::systemc, the one SpecularUnit gives (docs/integration/package.md).")
      endif()
    endforeach()
  endwhile()
endfunction()

function(_specular_systemc_defer_mix_check ours)
  get_property(deferred GLOBAL PROPERTY SPECULAR_SYSTEMC_MIX_CHECK)
  if(deferred OR NOT ours OR CMAKE_VERSION VERSION_LESS 3.19)  # cmake_language(DEFER): 3.19
    return()
  endif()
  set_property(GLOBAL PROPERTY SPECULAR_SYSTEMC_MIX_CHECK TRUE)
  cmake_language(EVAL CODE
    "cmake_language(DEFER DIRECTORY [[${CMAKE_SOURCE_DIR}]] CALL _specular_systemc_check_mix [[${ours}]])")
endfunction()

# ---- find -------------------------------------------------------------------------
set(_specular_by "")
set(_specular_where "")
# Whether SystemC::systemc is one this file made (here or in an earlier run), not the project's.
get_property(_specular_systemc_ours GLOBAL PROPERTY SPECULAR_SYSTEMC_MADE_HERE)
if(TARGET SystemC::systemc)  # the including project's own (or an earlier run of this file)
  if(TARGET PkgConfig::SYSTEMC_PC AND DEFINED _specular_systemc_pc_dir)
    set(_specular_by "pkg-config")
    set(_specular_where "${_specular_systemc_pc_dir}")
  elseif(SystemCLanguage_FOUND AND SystemCLanguage_DIR AND EXISTS "${SystemCLanguage_DIR}")
    # Only when find_package(SystemCLanguage) made it: a SystemCLanguage_DIR left in the
    # cache says nothing of a target the project made otherwise (issue 35).
    set(_specular_by "CMake package")
    set(_specular_where "${SystemCLanguage_DIR}")
  else()
    set(_specular_by "target")
  endif()
else()
  # 1. The installed package: the recorded SystemC, by its route at its place, unless the
  #    consumer named one with SystemCLanguage_DIR.
  if(NOT SystemCLanguage_DIR AND EXISTS "${SpecularUnit_SYSTEMC_LOCATION}")
    if(SpecularUnit_SYSTEMC_FOUND_BY STREQUAL "CMake package")
      _specular_systemc_cmake_package(PATHS "${SpecularUnit_SYSTEMC_LOCATION}" NO_DEFAULT_PATH)
      if(TARGET SystemC::systemc)
        set(_specular_by "CMake package")
      endif()
    elseif(SpecularUnit_SYSTEMC_FOUND_BY STREQUAL "pkg-config")
      _specular_systemc_pkg_config("${SpecularUnit_SYSTEMC_LOCATION}")
      if(TARGET SystemC::systemc)
        set(_specular_by "pkg-config")
      endif()
    endif()
  endif()
  # 2. Otherwise (the IP's build, or the recorded SystemC is gone): a CMake package,
  #    else pkg-config.
  if(NOT TARGET SystemC::systemc)
    _specular_systemc_cmake_package()
    if(TARGET SystemC::systemc)
      set(_specular_by "CMake package")
    endif()
  endif()
  if(NOT TARGET SystemC::systemc)
    _specular_systemc_pkg_config("")
    if(TARGET SystemC::systemc)
      set(_specular_by "pkg-config")
    endif()
  endif()
  if(TARGET SystemC::systemc)
    set(_specular_systemc_ours TRUE)
    set_property(GLOBAL PROPERTY SPECULAR_SYSTEMC_MADE_HERE TRUE)
  endif()
  if(_specular_by STREQUAL "CMake package")
    set(_specular_where "${SystemCLanguage_DIR}")
  elseif(_specular_by STREQUAL "pkg-config")
    set(_specular_where "${_specular_pc_dir}")
    set(_specular_systemc_pc_dir "${_specular_pc_dir}")  # for a later run of this file
  endif()
endif()

# What a message says of a SystemC: "3.0.2 for C++17 (sc_api_version_3_0_2_cxx201703L,
# CMake package at /opt/systemc/lib/cmake/SystemCLanguage)".
function(_specular_systemc_text out version cxx api by where)
  _specular_systemc_cxx_name(cxx_name "${cxx}" "${api}")
  if(NOT version)
    set(version "of unknown version")
  endif()
  if(by STREQUAL "target")
    set(place "this project's own SystemC::systemc target, library ${where}")
  else()
    set(place "${by} at ${where}")
  endif()
  if(api)
    set(text "${version} for ${cxx_name} (${api}, ${place})")
  else()
    set(text "${version} (${place}, whose library could not be read for its C++ standard)")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

set(_specular_set_it "SystemCLanguage_DIR=<prefix>/lib/cmake/SystemCLanguage (a SystemC built with CMake) or the environment variable PKG_CONFIG_PATH=<folder of its systemc.pc>")

# The whole fix that gives the installed package its recorded SystemC (issue 35): what to
# set, and what to unset or change first so that the setting is the one used — a
# SystemCLanguage_DIR is used before pkg-config, and a SystemC::systemc the project makes
# before find_package(SpecularUnit) is used before either.
function(_specular_systemc_fix out)
  set(by "${SpecularUnit_SYSTEMC_FOUND_BY}")
  set(at "${SpecularUnit_SYSTEMC_LOCATION}")
  set(steps "")
  if(TARGET SystemC::systemc AND NOT _specular_systemc_ours)
    if(SystemCLanguage_FOUND)
      set(how "by find_package(SystemCLanguage) at ${SystemCLanguage_DIR}")
    else()
      set(how "not by SpecularUnit")
    endif()
    list(APPEND steps "this project makes SystemC::systemc itself before find_package(SpecularUnit) (${how}): make it from that SystemC, or call find_package(SpecularUnit) first, which then makes it")
  endif()
  if(NOT EXISTS "${at}")
    list(APPEND steps "it is no longer at ${at}: install it there again, or point to where it is now with ${_specular_set_it}")
  elseif(by STREQUAL "CMake package")
    list(APPEND steps "set SystemCLanguage_DIR=${at} (cmake -DSystemCLanguage_DIR=${at})")
  elseif(by STREQUAL "pkg-config")
    if(SystemCLanguage_DIR)
      list(APPEND steps "unset SystemCLanguage_DIR (cmake -U SystemCLanguage_DIR; it is ${SystemCLanguage_DIR} and is used before pkg-config) and set the environment variable PKG_CONFIG_PATH=${at}")
    else()
      list(APPEND steps "set the environment variable PKG_CONFIG_PATH=${at}")
    endif()
  endif()
  string(JOIN "; " text ${steps})
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

if(NOT TARGET SystemC::systemc)
  set(_specular_problem "no SystemC found: neither Accellera's CMake package SystemCLanguage nor pkg-config's systemc.pc")
  if(DEFINED SpecularUnit_SYSTEMC_API)
    _specular_systemc_text(_specular_built "${SpecularUnit_SYSTEMC_VERSION}" "${SpecularUnit_SYSTEMC_CXX}"
      "${SpecularUnit_SYSTEMC_API}" "${SpecularUnit_SYSTEMC_FOUND_BY}" "${SpecularUnit_SYSTEMC_LOCATION}")
    _specular_systemc_fix(_specular_fix)
    string(CONCAT SpecularUnit_NOT_FOUND_MESSAGE
        "SpecularUnit was built with SystemC ${_specular_built}, and ${_specular_problem}. "
        "For SpecularUnit::specular and ::twin: ${_specular_fix}. For SpecularUnit::core alone, "
        "which needs no SystemC: find_package(SpecularUnit COMPONENTS core) (docs/integration/package.md).")
    return()
  endif()
  message(FATAL_ERROR "SpecularUnit needs SystemC 2.3 or 3.0: ${_specular_problem}. "
          "Install Debian's libsystemc-dev (scripts/setup.sh) or set ${_specular_set_it}.")
endif()

_specular_systemc_describe("${_specular_by}" "${_specular_where}")
_specular_systemc_text(_specular_found "${SPECULAR_SYSTEMC_VERSION}" "${SPECULAR_SYSTEMC_CXX}"
  "${SPECULAR_SYSTEMC_API}" "${SPECULAR_SYSTEMC_FOUND_BY}" "${SPECULAR_SYSTEMC_LOCATION}")

# ---- check ------------------------------------------------------------------------
if(DEFINED SpecularUnit_SYSTEMC_API)  # the installed package: the consumer's SystemC
  _specular_systemc_text(_specular_built "${SpecularUnit_SYSTEMC_VERSION}" "${SpecularUnit_SYSTEMC_CXX}"
    "${SpecularUnit_SYSTEMC_API}" "${SpecularUnit_SYSTEMC_FOUND_BY}" "${SpecularUnit_SYSTEMC_LOCATION}")
  set(_specular_differs FALSE)
  if(SPECULAR_SYSTEMC_API AND SpecularUnit_SYSTEMC_API)
    if(NOT SPECULAR_SYSTEMC_API STREQUAL SpecularUnit_SYSTEMC_API)
      set(_specular_differs TRUE)
    endif()
  elseif(NOT SPECULAR_SYSTEMC_VERSION STREQUAL SpecularUnit_SYSTEMC_VERSION)
    set(_specular_differs TRUE)
  endif()
  if(_specular_differs)
    _specular_systemc_fix(_specular_fix)
    _specular_systemc_cxx_name(_specular_built_cxx "${SpecularUnit_SYSTEMC_CXX}" "${SpecularUnit_SYSTEMC_API}")
    string(CONCAT SpecularUnit_NOT_FOUND_MESSAGE
        "SpecularUnit was built with SystemC ${_specular_built}, but this project's SystemC is "
        "${_specular_found}: a library compiled against one SystemC does not link against "
        "another. Give it SystemC ${SpecularUnit_SYSTEMC_VERSION} built for ${_specular_built_cxx}: "
        "${_specular_fix}; or rebuild SpecularUnit with SystemC ${SPECULAR_SYSTEMC_VERSION} "
        "(docs/integration/package.md).")
    return()
  endif()
  _specular_systemc_defer_mix_check("${SPECULAR_SYSTEMC_LIBRARY}")
  if(NOT SPECULAR_SYSTEMC_API AND SpecularUnit_SYSTEMC_API)
    message(WARNING "SpecularUnit was built with SystemC ${_specular_built}; this project's "
            "SystemC is ${_specular_found}: the C++ standard cannot be checked, and the link "
            "fails unless it is C++${SpecularUnit_SYSTEMC_CXX}.")
  elseif(NOT SpecularUnit_FIND_QUIETLY)
    message(STATUS "SpecularUnit: SystemC ${_specular_found}, the one it was built with")
  endif()
else()  # the IP's build: SystemC's library must be of the C++ standard we compile with
  if(SPECULAR_SYSTEMC_CXX AND CMAKE_CXX_STANDARD AND NOT SPECULAR_SYSTEMC_CXX STREQUAL CMAKE_CXX_STANDARD)
    message(FATAL_ERROR "SystemC ${_specular_found}: its library was built for "
            "C++${SPECULAR_SYSTEMC_CXX}, and SpecularUnit is compiled as C++${CMAKE_CXX_STANDARD} "
            "(CMAKE_CXX_STANDARD): objects "
            "of one do not link against the other. Build SystemC with "
            "-DCMAKE_CXX_STANDARD=${CMAKE_CXX_STANDARD}, or set SystemCLanguage_DIR to one that was.")
  endif()
  if(NOT SPECULAR_SYSTEMC_API)
    message(WARNING "SystemC ${_specular_found}: the installed package will check consumers' "
            "SystemC by version only.")
  endif()
  message(STATUS "SystemC: ${_specular_found}")
endif()
