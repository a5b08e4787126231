# rtl_rom_images_current: specular_romgen writes the default-width images again, into a
# scratch folder, and each must equal the committed one in rtl/ byte for byte (the places:
# SPECULAR_RTL_ROM_IMAGES of rtl/sources.cmake). After a change to the C++ tables,
# regenerate the committed images with UPDATE=ON:
#   cmake -DROMGEN=build/rtl/specular_romgen -DSCRATCH=build/rom_update -DUPDATE=ON
#         -P rtl/tb/rom_images_current.cmake
# -DROMGEN=... -DSCRATCH=... [-DRTL_DIR=rtl] [-DIMAGES=device/rom5.hex;...] [-DUPDATE=ON]
if(NOT RTL_DIR)
  get_filename_component(RTL_DIR ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
endif()
if(NOT IMAGES)
  include(${RTL_DIR}/sources.cmake)
  set(IMAGES ${SPECULAR_RTL_ROM_IMAGES})
endif()
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH})
execute_process(COMMAND ${ROMGEN} --out-dir ${SCRATCH} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "specular_romgen --out-dir ${SCRATCH} failed (status ${status})")
endif()
set(stale "")
foreach(image IN LISTS IMAGES)
  get_filename_component(name ${image} NAME)
  if(NOT EXISTS ${SCRATCH}/${name})
    message(FATAL_ERROR "specular_romgen wrote no ${name}")
  endif()
  if(UPDATE)
    execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${SCRATCH}/${name} ${RTL_DIR}/${image})
    continue()
  endif()
  if(NOT EXISTS ${RTL_DIR}/${image})
    list(APPEND stale "rtl/${image} (missing)")
    continue()
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${SCRATCH}/${name} ${RTL_DIR}/${image}
                  RESULT_VARIABLE differs)
  if(differs)
    list(APPEND stale "rtl/${image}")
  endif()
endforeach()
if(UPDATE)
  string(REPLACE ";" ", " IMAGES "${IMAGES}")
  message(STATUS "rtl/: ${IMAGES} written by specular_romgen")
elseif(stale)
  string(REPLACE ";" ", " stale "${stale}")
  message(FATAL_ERROR "${stale} differ(s) from what specular_romgen writes now (${SCRATCH}): "
          "regenerate with cmake -DROMGEN=<build>/rtl/specular_romgen -DSCRATCH=<scratch> "
          "-DUPDATE=ON -P rtl/tb/rom_images_current.cmake")
else()
  list(LENGTH IMAGES count)
  message(STATUS "rtl/: the ${count} committed ROM images equal specular_romgen's")
endif()
