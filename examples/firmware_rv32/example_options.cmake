# The bare-metal example's build options (issue 60), as cache variables, each checked:
# one file for the example's own project (CMakeLists.txt here, installed beside it) and
# the project's tests (tests/firmware/CMakeLists.txt), so that both pass the same -D
# defines to main.c (whose comment says what each does; docs/firmware.md lists them).
# Sets EXAMPLE_DEFINES: NAME=VALUE, for target_compile_definitions or as -D arguments.
#
# PLIC per-context strides (only a context above 0 uses them):
#   SiFive's PLIC (FE310, FU540 manuals; riscv-vp's FU540_PLIC of its linux platforms):
#     enables at base + 0x2000 + 0x80 * context, threshold at base + 0x200000 + 0x1000 *
#     context, claim/complete 4 bytes above it: ENABLE_STRIDE 0x80, CONTEXT_STRIDE 0x1000.
#   riscv-vp's FE310_PLIC (its hifive-vp and riscv-vp platforms): one context per hart,
#     packed: enables 4 bytes per 32 interrupt entries per hart (8 on hifive-vp, 64
#     entries; 12 on riscv-vp, 96), threshold/claim 8 bytes per hart:
#     ENABLE_STRIDE 8 (or 12), CONTEXT_STRIDE 8.

# example_option(NAME DEFAULT MIN MAX ALIGN DOC): a cache variable holding a C integer
# constant (decimal or 0x hex, optional u suffix) in MIN..MAX and a multiple of ALIGN; a
# bad one stops the configure naming the value and the range.
function(example_option name default min max align doc)
  set(${name} "${default}" CACHE STRING "${doc}")
  set(value "${${name}}")
  set(allowed "${min}..${max}")
  if(NOT align EQUAL 1)
    string(APPEND allowed ", a multiple of ${align}")
  endif()
  if(NOT value MATCHES "^(0[xX][0-9a-fA-F]+|[0-9]+)[uU]?$")
    message(FATAL_ERROR "${name}=${value}: not an integer constant (decimal or 0x hex, optional u); "
                        "allowed: ${allowed}")
  endif()
  string(REGEX REPLACE "[uU]$" "" digits "${value}")
  math(EXPR number "${digits}")
  math(EXPR low "${min}")
  math(EXPR high "${max}")
  math(EXPR rest "${number} % ${align}")
  if(number LESS low OR number GREATER high OR NOT rest EQUAL 0)
    message(FATAL_ERROR "${name}=${value}: out of range; allowed: ${allowed}")
  endif()
endfunction()

example_option(SPECULAR_BASE "0x50000000u" 0 0xFFFF8000 4 "the IP's base address (its 32 KiB window)")
example_option(EXAMPLE_PLIC_BASE "0x0C000000u" 0 0xFC000000 4 "the PLIC's base address (the irq build)")
example_option(EXAMPLE_PLIC_SOURCE "1u" 1 1023 1 "done_irq's PLIC source number (the irq build)")
example_option(EXAMPLE_PLIC_CONTEXT "0u" 0 15871 1
               "the PLIC context the irq build enables and claims in (0: hart 0's machine mode)")
example_option(EXAMPLE_PLIC_ENABLE_STRIDE "0x80u" 4 0x80 4
               "bytes of enable bits per PLIC context: 0x80 SiFive's; riscv-vp's FE310_PLIC 8 or 12")
example_option(EXAMPLE_PLIC_CONTEXT_STRIDE "0x1000u" 8 0x1000 4
               "bytes of threshold/claim per PLIC context: 0x1000 SiFive's; riscv-vp's FE310_PLIC 8")
example_option(EXAMPLE_CLINT_BASE "0x02000000u" 0 0xFFFF0000 4 "the CLINT whose mtime bounds each wait")
example_option(EXAMPLE_WATCHDOG_TICKS "65536u" 0 0xFFFFFFFF 1
               "the watchdog's bound in mtime ticks (0: no watchdog, no CLINT access)")
set(EXAMPLE_UART_BASE "" CACHE STRING "a byte-wide UART transmit register; empty: the write system call")
if(NOT EXAMPLE_UART_BASE STREQUAL "")
  example_option(EXAMPLE_UART_BASE "" 0 0xFFFFFFFF 1 "a byte-wide UART transmit register; empty: the write system call")
endif()

set(EXAMPLE_ENERGY_COUNTER "" CACHE STRING "the platform's energy counter (docs/energy.md); empty: none read")
if(NOT EXAMPLE_ENERGY_COUNTER STREQUAL "")
  example_option(EXAMPLE_ENERGY_COUNTER "" 0 0xFFFFFFF0 4 "the platform's energy counter (docs/energy.md); empty: none read")
endif()

set(EXAMPLE_DEFINES "")
foreach(name SPECULAR_BASE EXAMPLE_PLIC_BASE EXAMPLE_PLIC_SOURCE EXAMPLE_PLIC_CONTEXT EXAMPLE_PLIC_ENABLE_STRIDE
             EXAMPLE_PLIC_CONTEXT_STRIDE EXAMPLE_CLINT_BASE EXAMPLE_WATCHDOG_TICKS EXAMPLE_UART_BASE
             EXAMPLE_ENERGY_COUNTER)
  if(NOT "${${name}}" STREQUAL "")
    list(APPEND EXAMPLE_DEFINES "${name}=${${name}}")
  endif()
endforeach()
