#!/usr/bin/env bash
# Runs a command under the project's sanitizer settings: AddressSanitizer,
# UndefinedBehaviorSanitizer (every finding fatal) and LeakSanitizer with the
# suppressions of tests/lsan.supp, which name only SystemC's own allocations.
#
#   scripts/verify/sanitizer_env.sh COMMAND [ARGS...]
#
# A SPECULAR_SANITIZE build uses it as every test's launcher (test discovery
# included); scripts/verify/sanitize.sh and scripts/verify/fuzz.sh use the same settings.
# Options already set in the environment are kept and these are appended.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)

# detect_stack_use_after_return=0: SystemC's QuickThreads switch stacks by hand, which
# ASan's fake stacks do not follow.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=1:detect_stack_use_after_return=0:check_initialization_order=1:strict_init_order=1"
# LeakSanitizer takes one suppressions file: SPECULAR_LSAN_EXTRA (fuzz/lsan.supp for the
# fuzzers) is appended to tests/lsan.supp in a temporary copy.
suppressions="$root/tests/lsan.supp"
if [ -n "${SPECULAR_LSAN_EXTRA:-}" ]; then
  suppressions=$(mktemp "${TMPDIR:-/tmp}/specular_lsan.XXXXXX")
  cat "$root/tests/lsan.supp" "$SPECULAR_LSAN_EXTRA" >"$suppressions"
fi
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$suppressions:print_suppressions=0"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:+$UBSAN_OPTIONS:}print_stacktrace=1:halt_on_error=1"
if [ "$suppressions" = "$root/tests/lsan.supp" ]; then exec "$@"; fi
status=0
"$@" || status=$?
rm -f "$suppressions"
exit "$status"
