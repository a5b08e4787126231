#!/usr/bin/env bash
# Runs one build of the bare-metal example (poll, irq, irq_direct) on a RISC-V virtual
# platform that holds the IP at SPECULAR_BASE (and, for the irq build, a PLIC with
# done_irq on EXAMPLE_PLIC_SOURCE; for the irq_direct build, done_irq straight to the
# hart; for every build, a CLINT at EXAMPLE_CLINT_BASE for the watchdog), and passes when
# it exits 0 having printed its PASS line: every result equal to Core.
#
# The platform is a command that takes the ELF as its last argument (e.g.
# "tiny32-vp --intercept-syscalls" of a riscv-vp built with the IP,
# docs/integration/riscv_vp.md), named per build by an environment variable read here, at test time:
#   SPECULAR_RV32_VP_POLL, SPECULAR_RV32_VP_IRQ, SPECULAR_RV32_VP_IRQ_DIRECT
# each falling back to SPECULAR_RV32_VP (one VP for every build it fits). None named:
# exit 77, which ctest reports as skipped (Debian packages no RISC-V VP that can hold the
# IP). A named command that is not found: FAIL, naming the variable and the command.
# Usage: rv32_example_run.sh ELF VARIANT
set -uo pipefail
elf=${1:?usage: rv32_example_run.sh ELF VARIANT}
variant=${2:?usage: rv32_example_run.sh ELF VARIANT}
case $variant in
  poll | irq | irq_direct) ;;
  *) echo "rv32_example_run: VARIANT $variant: allowed: poll, irq, irq_direct" >&2; exit 1 ;;
esac
own=SPECULAR_RV32_VP_${variant^^}
if [[ -n ${!own:-} ]]; then
  name=$own
elif [[ -n ${SPECULAR_RV32_VP:-} ]]; then
  name=SPECULAR_RV32_VP
else
  echo "rv32_example_run: SKIPPED: no RISC-V virtual platform with the IP is named for the $variant build" \
       "(set $own, or SPECULAR_RV32_VP for every build, e.g. to 'tiny32-vp --intercept-syscalls' of a" \
       "riscv-vp built with the IP; none is packaged for Debian)" >&2
  exit 77
fi
command=${!name}
read -r -a vp <<<"$command"
if ! command -v "${vp[0]}" >/dev/null; then
  echo "rv32_example_run: FAIL: $name='$command': ${vp[0]} not found (not on PATH, or no executable there)" >&2
  exit 1
fi
[[ -f $elf ]] || { echo "rv32_example_run: no ELF at $elf (firmware_rv32_example_elf_$variant failed?)" >&2; exit 1; }
echo "rv32_example_run: $variant on $name='$command'"
output=$(timeout 60 "${vp[@]}" "$elf" 2>&1)
status=$?
echo "$output"
fail() { echo "rv32_example_run: FAIL: $variant on $name: $*" >&2; exit 1; }
[[ $status == 124 ]] && fail "still running after 60 s (the exit call not taken? riscv-vp needs --intercept-syscalls)"
case $status in
  0) ;;
  30) fail "exit 30: the example's watchdog fired (its FAIL line above names what it waited on)" ;;
  40) fail "exit 40: an unexpected trap (its FAIL line above)" ;;
  *) fail "exited with $status (main.c: 1-9 the driver's error, 10 the refusal not reported, 20 a result differs)" ;;
esac
grep -q '^PASS: every result equal to Core$' <<<"$output" ||
  fail "exit 0 but no PASS line (is the console taken? riscv-vp needs --intercept-syscalls)"
echo "rv32_example_run: $variant: every result equal to Core"
