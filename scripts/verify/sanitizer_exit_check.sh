#!/usr/bin/env bash
# The sanitizer build's exit, checked where luck cannot hide a fault (issue 45): SystemC
# programs run under scripts/verify/sanitizer_env.sh with address randomisation off
# (`setarch -R`), where a LeakSanitizer that scans a coroutine's stack for the main
# thread's faults at exit every time (docs/testing/sanitizers.md, "Sanitizers and SystemC's
# coroutines").
#
#   scripts/verify/sanitizer_exit_check.sh [BUILD] [RUNS]    default build-asan, 20 runs
#
# 1. specular_tb (one operation, the pin-level device) RUNS times. A run fails on a
#    non-zero exit, a LeakSanitizer fatal error, or LeakSanitizer's own note that a
#    thread's stack pointer is not in the stack it scans (the cause, seen on every run
#    before the fix, whether the tracer then faulted or not).
# 2. BUILD/tests/specular_planted_leak once: its planted leak must be reported, the block
#    its sc_main holds on the main stack must not be, and no fatal error.
# Exit 0 when all pass, 1 otherwise, 2 on bad arguments. Needs a SPECULAR_SANITIZE build.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)

build=${1:-build-asan}
runs=${2:-20}
case "$build" in -h|--help) sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
if ! [[ "$runs" =~ ^[0-9]+$ ]] || [ "$runs" -lt 1 ] || [ "$runs" -gt 10000 ]; then
  echo "sanitizer_exit_check.sh: RUNS = '$runs' must be an integer in [1, 10000]" >&2
  exit 2
fi
tb="$build/testbench/specular_tb"
planted="$build/tests/specular_planted_leak"
for exe in "$tb" "$planted"; do
  if [ ! -x "$exe" ]; then
    echo "sanitizer_exit_check.sh: $exe not found: build '$build' with -DSPECULAR_SANITIZE=ON" \
         "(scripts/verify/sanitize.sh)" >&2
    exit 2
  fi
done
if ! setarch -R true 2>/dev/null; then
  echo "sanitizer_exit_check.sh: 'setarch -R' (util-linux) cannot turn address randomisation" \
       "off here; the check would depend on luck" >&2
  exit 1
fi

scratch=$(mktemp -d "${TMPDIR:-/tmp}/specular_exit_check.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
# verbosity=1:log_threads=1: LeakSanitizer prints each thread's stack and stack pointer.
lsan_verbose="${LSAN_OPTIONS:+$LSAN_OPTIONS:}verbosity=1:log_threads=1"
fault_pattern='LeakSanitizer has encountered a fatal error|Tracer caught signal|stack pointer not in stack range'

failed=0
for ((i = 1; i <= runs; i++)); do
  status=0
  LSAN_OPTIONS="$lsan_verbose" setarch -R "$root/scripts/verify/sanitizer_env.sh" "$tb" \
    --cos 0.9 --n 10 --rgb 200,100,50 >"$scratch/tb.out" 2>"$scratch/tb.err" </dev/null || status=$?
  if [ "$status" -ne 0 ] || grep -qE "$fault_pattern" "$scratch/tb.err"; then
    failed=$((failed + 1))
    if [ "$failed" -eq 1 ]; then
      echo "sanitizer_exit_check.sh: run $i of specular_tb failed (exit $status):" >&2
      grep -E "$fault_pattern|Stack at|ERROR" "$scratch/tb.err" | head -n 8 >&2 || true
    fi
  fi
done
if [ "$failed" -eq 0 ]; then
  echo "sanitizer_exit_check.sh: specular_tb under setarch -R: $runs of $runs runs exited cleanly"
else
  echo "sanitizer_exit_check.sh: specular_tb under setarch -R: $failed of $runs runs failed" >&2
fi

status=0
setarch -R "$root/scripts/verify/sanitizer_env.sh" "$planted" >"$scratch/leak.out" 2>"$scratch/leak.err" \
  </dev/null || status=$?
problems=()
[ "$status" -ne 0 ] || problems+=("exited 0: LeakSanitizer reported nothing")
grep -q "ERROR: LeakSanitizer: detected memory leaks" "$scratch/leak.err" ||
  problems+=("no 'detected memory leaks' report")
grep -q "specular_planted_leak_on_coroutine" "$scratch/leak.err" ||
  problems+=("the planted leak (specular_planted_leak_on_coroutine) not reported")
if grep -q "specular_held_on_main_stack" "$scratch/leak.err"; then
  problems+=("the block held on the main stack reported as a leak: the main stack was not scanned")
fi
if grep -qE "$fault_pattern" "$scratch/leak.err"; then problems+=("a LeakSanitizer fatal error"); fi
if [ "${#problems[@]}" -eq 0 ]; then
  echo "sanitizer_exit_check.sh: the planted leak is reported, the main stack's block is not"
else
  failed=$((failed + 1))
  echo "sanitizer_exit_check.sh: specular_planted_leak (exit $status):" >&2
  printf '  %s\n' "${problems[@]}" >&2
  grep -E "ERROR|fatal|#[0-9] .*specular_" "$scratch/leak.err" | head -n 12 >&2 || true
fi
[ "$failed" -eq 0 ]
