# twin_reads_no_rom_file: the installed twin must work wherever it is copied, so its two
# archives may name no ROM image and no file of the build tree's ROM folder (the words
# are written from C++, twin/src/rom_loader.h; before, Verilator baked the absolute
# $readmemh paths into the model; Verilator's runtime still carries $readmem's messages).
# -DARCHIVES=a;b -DROM_DIR=<build>/rtl/rom
foreach(archive IN LISTS ARCHIVES)
  if(NOT EXISTS "${archive}")
    message(FATAL_ERROR "no archive ${archive}")
  endif()
  file(STRINGS "${archive}" named REGEX "rom5\\.hex|rom38\\.hex")
  file(STRINGS "${archive}" all_strings)
  set(rom_dir_named "")
  foreach(text IN LISTS all_strings)
    string(FIND "${text}" "${ROM_DIR}" at)
    if(NOT at EQUAL -1)
      list(APPEND rom_dir_named "${text}")
    endif()
  endforeach()
  if(named OR rom_dir_named)
    message(FATAL_ERROR "${archive} names a ROM image file: ${named} ${rom_dir_named}")
  endif()
  message(STATUS "${archive}: no ROM image file named")
endforeach()
