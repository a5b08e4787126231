#!/usr/bin/env bash
# Checks the bare-metal example's ELF (firmware_rv32_example_elf links it): a 32-bit
# RISC-V executable, soft-float ilp32, entered at 0x0 (riscv-vp tiny32's RAM start) by
# _start, holding main, the trap handler, the exit call (main's return, the watchdog and
# unexpected traps end there), the driver's entry points and the results' symbols in RAM.
# Usage: rv32_example_check.sh ELF [poll|irq|irq_direct]
set -euo pipefail
elf=${1:?usage: rv32_example_check.sh ELF [poll|irq|irq_direct]}
variant=${2:-poll}
readelf=riscv64-unknown-elf-readelf
nm=riscv64-unknown-elf-nm
command -v "$readelf" >/dev/null || { echo "rv32_example_check: $readelf not found: install gcc-riscv64-unknown-elf (binutils-riscv64-unknown-elf)" >&2; exit 1; }
[[ -f $elf ]] || { echo "rv32_example_check: no ELF at $elf (firmware_rv32_example_elf failed?)" >&2; exit 1; }
header=$("$readelf" -h "$elf")
fail() { echo "rv32_example_check: FAIL: $*" >&2; echo "$header" >&2; exit 1; }
grep -Eq 'Class:[[:space:]]+ELF32' <<<"$header" || fail "not ELF32"
grep -Eq 'Machine:[[:space:]]+RISC-V' <<<"$header" || fail "not RISC-V"
grep -Eq 'Type:[[:space:]]+EXEC' <<<"$header" || fail "not an executable"
grep -Eq 'Entry point address:[[:space:]]+0x0$' <<<"$header" || fail "entry is not 0x0"
grep -Eq 'Flags:.*soft-float ABI' <<<"$header" || fail "not the ilp32 (soft-float) ABI"
symbols=$("$nm" "$elf")
for symbol in _start main example_trap example_exit specular_init specular_compute specular_shade specular_irq_handler \
              example_results example_status example_console_write example_bus_faults; do
  grep -Eq "^[0-9a-f]+ [A-Za-z] $symbol\$" <<<"$symbols" || fail "symbol $symbol missing"
done
# The interrupt build through a PLIC claims and completes; the others have no PLIC code.
if [[ $variant == irq ]]; then
  grep -Eq "^[0-9a-f]+ [A-Za-z] example_plic_on\$" <<<"$symbols" || fail "the PLIC build has no example_plic_on"
else
  grep -Eq "^[0-9a-f]+ [A-Za-z] example_plic_on\$" <<<"$symbols" && fail "the $variant build has example_plic_on"
fi
start=$(awk '$3 == "_start" {print $1}' <<<"$symbols")
[[ $start == 00000000 ]] || fail "_start at 0x$start, not at the entry"
echo "rv32_example_check: $elf: RV32 ilp32 executable, entry _start at 0x0, main and the driver linked"
