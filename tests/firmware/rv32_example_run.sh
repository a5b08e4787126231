#!/usr/bin/env bash
# Runs the bare-metal example's ELF on a RISC-V virtual platform that holds the IP at
# 0x5000_0000 (and, for the irq build, a PLIC at 0x0C00_0000 with done_irq on source 1),
# and passes when it exits 0 having printed its PASS line: every result equal to Core.
# The platform is named by SPECULAR_RV32_VP, a command that takes the ELF as its last
# argument (e.g. "tiny32-vp --intercept-syscalls" for a riscv-vp built with the IP,
# docs/integration.md section 10). None is named, or it is not found: exit 77, which
# ctest reports as skipped: Debian packages no RISC-V VP that can hold the IP.
# Usage: rv32_example_run.sh ELF VARIANT
set -uo pipefail
elf=${1:?usage: rv32_example_run.sh ELF VARIANT}
variant=${2:?usage: rv32_example_run.sh ELF VARIANT}
if [[ -z ${SPECULAR_RV32_VP:-} ]]; then
  echo "rv32_example_run: SKIPPED: no RISC-V virtual platform with the IP is named (set SPECULAR_RV32_VP," \
       "e.g. to 'tiny32-vp --intercept-syscalls' of a riscv-vp built with the IP; none is packaged for Debian)" >&2
  exit 77
fi
read -r -a vp <<<"$SPECULAR_RV32_VP"
command -v "${vp[0]}" >/dev/null || {
  echo "rv32_example_run: SKIPPED: SPECULAR_RV32_VP names ${vp[0]}, which is not found" >&2; exit 77; }
[[ -f $elf ]] || { echo "rv32_example_run: no ELF at $elf (firmware_rv32_example_elf_$variant failed?)" >&2; exit 1; }
output=$(timeout 60 "${vp[@]}" "$elf" 2>&1)
status=$?
echo "$output"
[[ $status == 0 ]] || { echo "rv32_example_run: FAIL: $variant exited with $status" >&2; exit 1; }
grep -q '^PASS: every result equal to Core$' <<<"$output" ||
  { echo "rv32_example_run: FAIL: $variant printed no PASS line (is the console taken?)" >&2; exit 1; }
echo "rv32_example_run: $variant: every result equal to Core"
