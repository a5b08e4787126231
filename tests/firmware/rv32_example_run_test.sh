#!/usr/bin/env bash
# Checks rv32_example_run.sh (issue 60) with stand-in VPs, in the current folder (the
# test's own): a VP per build (SPECULAR_RV32_VP_POLL, _IRQ, _IRQ_DIRECT) before the
# common SPECULAR_RV32_VP; none named: skipped (77); a named command that is not found:
# FAIL (1) naming the variable and the command; the firmware's exit codes reported.
# Usage: rv32_example_run_test.sh RUN_SCRIPT
set -uo pipefail
run=${1:?usage: rv32_example_run_test.sh RUN_SCRIPT}
failures=0
here=$PWD
elf=$here/example.elf
echo "not an ELF: the stand-ins never read it" >"$elf"
# vp_pass ARGS... ELF: prints the PASS line when its last argument is the ELF and its
# first is the option it was named with; vp_watchdog: the example's watchdog exit.
cat >"$here/vp_pass" <<'VP'
#!/usr/bin/env bash
[[ $1 == --intercept-syscalls && -f ${!#} ]] || { echo "vp_pass: arguments $*" >&2; exit 3; }
echo "specular example: IP at 0x50000000, polled"
echo "PASS: every result equal to Core"
VP
cat >"$here/vp_watchdog" <<'VP'
#!/usr/bin/env bash
echo "FAIL: no done_irq interrupt within 65536 mtime ticks (stand-in)"
exit 30
VP
cat >"$here/vp_silent" <<'VP'
#!/usr/bin/env bash
exit 0
VP
chmod +x "$here/vp_pass" "$here/vp_watchdog" "$here/vp_silent"

# expect STATUS TEXT VARIANT [NAME=VALUE...]: runs the script with only those variables
# set; its exit status must be STATUS and its output must hold TEXT.
expect() {
  local status=$1 text=$2 variant=$3
  shift 3
  local output got
  output=$(env -u SPECULAR_RV32_VP -u SPECULAR_RV32_VP_POLL -u SPECULAR_RV32_VP_IRQ -u SPECULAR_RV32_VP_IRQ_DIRECT \
           "$@" "$run" "$elf" "$variant" 2>&1)
  got=$?
  if [[ $got != "$status" ]] || ! grep -qF -- "$text" <<<"$output"; then
    echo "rv32_example_run_test: FAIL: $variant with ${*:-nothing named}: exit $got (expected $status)," \
         "output must hold: $text" >&2
    echo "$output" >&2
    failures=$((failures + 1))
  else
    echo "rv32_example_run_test: ok: $variant with ${*:-nothing named}: exit $got"
  fi
}

expect 77 "set SPECULAR_RV32_VP_IRQ_DIRECT, or SPECULAR_RV32_VP" irq_direct
expect 1 "FAIL: SPECULAR_RV32_VP_IRQ='$here/no-such-vp --intercept-syscalls': $here/no-such-vp not found" irq \
       "SPECULAR_RV32_VP_IRQ=$here/no-such-vp --intercept-syscalls"
expect 1 "FAIL: SPECULAR_RV32_VP='no-such-vp-on-path': no-such-vp-on-path not found" poll \
       "SPECULAR_RV32_VP=no-such-vp-on-path"
# The build's own variable first, the common one for the others.
expect 0 "poll: every result equal to Core" poll \
       "SPECULAR_RV32_VP=$here/vp_pass --intercept-syscalls" "SPECULAR_RV32_VP_IRQ=$here/vp_watchdog"
expect 1 "FAIL: irq on SPECULAR_RV32_VP_IRQ: exit 30: the example's watchdog fired" irq \
       "SPECULAR_RV32_VP=$here/vp_pass --intercept-syscalls" "SPECULAR_RV32_VP_IRQ=$here/vp_watchdog"
expect 0 "irq_direct: every result equal to Core" irq_direct \
       "SPECULAR_RV32_VP=$here/vp_watchdog" "SPECULAR_RV32_VP_IRQ_DIRECT=$here/vp_pass --intercept-syscalls"
# A named but missing per-build VP fails even where the common one would run.
expect 1 "FAIL: SPECULAR_RV32_VP_POLL='$here/no-such-vp': $here/no-such-vp not found" poll \
       "SPECULAR_RV32_VP=$here/vp_pass --intercept-syscalls" "SPECULAR_RV32_VP_POLL=$here/no-such-vp"
expect 1 "exit 0 but no PASS line" irq "SPECULAR_RV32_VP=$here/vp_silent"
expect 1 "VARIANT both: allowed: poll, irq, irq_direct" both "SPECULAR_RV32_VP=$here/vp_pass"

if [[ $failures != 0 ]]; then
  echo "rv32_example_run_test: $failures case(s) failed" >&2
  exit 1
fi
echo "rv32_example_run_test: every case as expected"
