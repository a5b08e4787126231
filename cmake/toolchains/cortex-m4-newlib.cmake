# CMake toolchain file: bare-metal Cortex-M4 (Thumb-2) with Debian's arm-none-eabi-gcc
# and newlib (packages gcc-arm-none-eabi and libnewlib-arm-none-eabi). Installed as
# share/SpecularUnit/toolchains/cortex-m4-newlib.cmake; docs/firmware.md. The RV32
# example's startup and linker script are RISC-V's: with this file the example project
# builds the driver and the checking program into a library for the Cortex-M4 (the
# platform's own startup and linker script make it a program).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-m4 -mthumb -ffreestanding")
set(CMAKE_ASM_FLAGS_INIT "-mcpu=cortex-m4 -mthumb")
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
