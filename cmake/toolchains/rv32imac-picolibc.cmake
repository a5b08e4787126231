# CMake toolchain file: bare-metal RV32 (rv32imac, ilp32 soft float) with Debian's
# riscv64-unknown-elf-gcc and picolibc (packages gcc-riscv64-unknown-elf and
# picolibc-riscv64-unknown-elf). Installed as
# share/SpecularUnit/toolchains/rv32imac-picolibc.cmake; docs/firmware.md.
#   cmake -S PREFIX/share/SpecularUnit/firmware_rv32 -B build \
#         --toolchain PREFIX/share/SpecularUnit/toolchains/rv32imac-picolibc.cmake \
#         -DCMAKE_PREFIX_PATH=PREFIX
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_ASM_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_C_FLAGS_INIT "-march=rv32imac -mabi=ilp32 --specs=picolibc.specs -ffreestanding")
set(CMAKE_ASM_FLAGS_INIT "-march=rv32imac -mabi=ilp32")
# The compiler check links no program: a bare-metal link needs the firmware's own script.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
# Packages (SpecularUnitFirmware) from CMAKE_PREFIX_PATH; programs from the host.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
