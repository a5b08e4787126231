#!/usr/bin/env bash
# scripts/verify/sanitizer_failures.py on a real ctest JUnit file (issue 45): a scratch project
# whose tests fail the way sanitizer runs fail (each class once, two of them twice; a timeout is an
# ordinary failure) and pass; the
# summary must count each class as planted, name the failed tests and exit 1; a run
# where nothing failed exits 0; fuzz.sh's form (--logs) the same on log files.
#   sanitizer_failures_test.sh SCRATCH_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
scratch=${1:?usage: sanitizer_failures_test.sh SCRATCH_DIR}
rm -rf "$scratch" && mkdir -p "$scratch/project"
fail() { echo "sanitizer_failures_test: $*" >&2; exit 1; }

# Each test prints what a failing sanitizer run prints, then exits as it would.
cat >"$scratch/project/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.16)
project(planted NONE)
enable_testing()
function(planted name status text)
  add_test(NAME ${name} COMMAND sh -c "printf '%s\\n' '${text}'; exit ${status}")
endfunction()
planted(passes 0 "all good")
planted(tracer_a 1 "Tracer caught signal 11: addr=0x7f95109a3000")
planted(tracer_b 1 "==2175==LeakSanitizer has encountered a fatal error.")
planted(leaks 23 "==9==ERROR: LeakSanitizer: detected memory leaks")
planted(overflow 1 "==9==ERROR: AddressSanitizer: heap-buffer-overflow on address")
planted(shift 1 "arith.cpp:12:5: runtime error: shift exponent 40 is too large")
planted(assertion 1 "test_x.cpp:40: Failure Expected equality of these values")
add_test(NAME slow COMMAND sh -c "sleep 5")
set_tests_properties(slow PROPERTIES TIMEOUT 1)
CMAKE
cmake -S "$scratch/project" -B "$scratch/build" >/dev/null
ctest --test-dir "$scratch/build" -j2 --output-junit "$scratch/junit.xml" >/dev/null 2>&1 &&
  fail "the planted ctest run passed"

status=0
python3 "$root/scripts/verify/sanitizer_failures.py" --junit "$scratch/junit.xml" >"$scratch/summary" || status=$?
cat "$scratch/summary"
[ "$status" -eq 1 ] || fail "exit $status on failures, expected 1"
expected="7 of 8 tests failed: 2 sanitizer fatal error, 1 leak, 1 memory error, 1 undefined behaviour, 2 test failure"
grep -qF "$expected" "$scratch/summary" || fail "summary line is not: $expected"
grep -qE "^  sanitizer fatal error: (tracer_a, tracer_b|tracer_b, tracer_a)$" "$scratch/summary" ||
  fail "the fatal errors are not named tracer_a and tracer_b"
grep -qE "^  test failure: (assertion, slow|slow, assertion)$" "$scratch/summary" ||
  fail "the ordinary failure and the timeout are not named"
grep -q "passes" "$scratch/summary" && fail "a passed test is named"

# Nothing failed: exit 0.
ctest --test-dir "$scratch/build" -R '^passes$' --output-junit "$scratch/pass.xml" >/dev/null
python3 "$root/scripts/verify/sanitizer_failures.py" --junit "$scratch/pass.xml" >"$scratch/pass" ||
  fail "exit non-zero when nothing failed"
grep -qF "none of 1 tests failed" "$scratch/pass" || fail "no 'none of 1 tests failed' line"

# fuzz.sh's form: the log of each failed run.
printf 'Tracer caught signal 11\n' >"$scratch/a.log"
printf 'ERROR: LeakSanitizer: detected memory leaks\n' >"$scratch/b.log"
status=0
python3 "$root/scripts/verify/sanitizer_failures.py" --logs "$scratch/a.log" "$scratch/b.log" >"$scratch/logs" || status=$?
[ "$status" -eq 1 ] || fail "--logs exit $status, expected 1"
grep -qF "2 runs failed: 1 sanitizer fatal error, 1 leak" "$scratch/logs" || fail "--logs summary wrong"
echo "sanitizer_failures_test: passed"
