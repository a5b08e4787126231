#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang (ASan + UBSan) in build-fuzz and
# runs each for a bounded time, starting from the seed corpus in fuzz/corpus/<target>
# after replaying every saved finding in fuzz/regressions/<target>.
#
#   scripts/verify/fuzz.sh [SECONDS]    seconds per target (default 60)
#
# Build directory: $SPECULAR_FUZZ_BUILD_DIR, else the sanitizer stage's build-asan (or
# $SPECULAR_ASAN_BUILD_DIR) when it holds the targets (sanitize.sh with clang), else
# build-fuzz; a folder configured with -DSPECULAR_FUZZ=ON is built as it is configured.
# New corpus entries go to <build>/corpus/<target>, crashes to <build>/artifacts/<target>/
# (copy a crash to fuzz/regressions/<target>/ once fixed: every later run replays it).
# Needs clang-14 and libclang-rt-14-dev (scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/../.."

seconds=${1:-60}
case "$seconds" in
  -h|--help) sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
esac
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [ "$seconds" -lt 1 ] || [ "$seconds" -gt 86400 ]; then
  echo "fuzz.sh: SECONDS = '$seconds' must be an integer in [1, 86400]" >&2
  exit 2
fi
# Debian's clang-14 package installs clang++-14; the clang package adds clang++.
cxx=${SPECULAR_FUZZ_CXX:-$(command -v clang++ || command -v clang++-14 || true)}
if [ -z "$cxx" ] || ! command -v "$cxx" >/dev/null 2>&1; then
  echo "fuzz.sh: clang++ not found; install clang-14 and libclang-rt-14-dev (scripts/setup.sh)" >&2
  exit 1
fi

asan_build=${SPECULAR_ASAN_BUILD_DIR:-build-asan}
if [ -n "${SPECULAR_FUZZ_BUILD_DIR:-}" ]; then
  build=$SPECULAR_FUZZ_BUILD_DIR
elif grep -qs '^SPECULAR_FUZZ:BOOL=ON$' "$asan_build/CMakeCache.txt"; then
  build=$asan_build  # the sanitizer stage's clang build holds the targets: no second build
else
  build=build-fuzz
fi
jobs=$(nproc 2>/dev/null || echo 2)
targets=(fuzz_csv_options fuzz_tlm_registers fuzz_tlm_sequences)
# -O1 -gline-tables-only: what libFuzzer's documentation builds with; line numbers in
# reports, a quarter less compile time than RelWithDebInfo's -O2 -g (docs/testing.md).
configure=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG"
           -DSPECULAR_FUZZ=ON -DSPECULAR_BUILD_TESTS=OFF -DSPECULAR_BUILD_BENCH=OFF)
if grep -qs '^SPECULAR_FUZZ:BOOL=ON$' "$build/CMakeCache.txt"; then
  # The sanitizer stage's build (or an earlier run of this script's): its configuration stays.
  echo "fuzz.sh: $build is configured with SPECULAR_FUZZ=ON; building its fuzz targets as configured"
else
  # The compiler is set on the first configure only: changing it later empties the cache.
  if [ ! -f "$build/CMakeCache.txt" ]; then configure+=(-DCMAKE_CXX_COMPILER="$cxx"); fi
  echo "+ cmake -S . -B $build ${configure[*]}"
  cmake -S . -B "$build" "${configure[@]}" >/dev/null
fi
echo "+ cmake --build $build -j$jobs --target ${targets[*]}"
cmake --build "$build" -j"$jobs" --target "${targets[@]}"

export SPECULAR_LSAN_EXTRA="$PWD/fuzz/lsan.supp"
# fuzz_one TARGET: replays its saved findings, then fuzzes it; prints its lines, writes
# the log that failed (if one did) to <build>/<target>.failed.
fuzz_one() {
  local target=$1 exe work artifacts asan_options regressions
  exe="$build/fuzz/$target"
  work="$build/corpus/$target"
  artifacts="$build/artifacts/$target/"
  mkdir -p "$work" "$artifacts"
  # fuzz_tlm_sequences: the full stack on every malloc, so that lsan.supp's FuzzerDriver
  # entry matches libFuzzer's program-name strings at exit (the fast unwinder stops
  # inside libstdc++ there and the suppression misses; about half the speed).
  asan_options=${ASAN_OPTIONS:-}
  if [ "$target" = fuzz_tlm_sequences ]; then
    asan_options="${asan_options:+$asan_options:}fast_unwind_on_malloc=0"
  fi
  regressions=(fuzz/regressions/"$target"/*)
  if [ -e "${regressions[0]}" ]; then
    echo "+ $target: replaying ${#regressions[@]} saved finding(s)"
    if ! ASAN_OPTIONS="$asan_options" scripts/verify/sanitizer_env.sh "$exe" "${regressions[@]}" >"$build/$target.regressions.log" 2>&1; then
      echo "fuzz.sh: $target: a saved finding fails again; see $build/$target.regressions.log" >&2
      echo "$build/$target.regressions.log" >"$build/$target.failed"
      return 1
    fi
  fi
  echo "+ $target: fuzzing for $seconds s"
  # -timeout: one input taking 10 s is a hang; -rss_limit_mb: a growing model is a finding.
  if ASAN_OPTIONS="$asan_options" scripts/verify/sanitizer_env.sh "$exe" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$artifacts" "$work" "fuzz/corpus/$target" \
      >"$build/$target.log" 2>&1; then
    # One line of figures: executions, speed, coverage, corpus.
    grep -E '^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)' \
      "$build/$target.log" | tr '\n' ' ' | sed "s/^/  $target: /; s/\$/\n/"
    grep -E '^#[0-9]+.*DONE' "$build/$target.log" | tail -1 | sed "s/^/  $target: /"
  else
    echo "fuzz.sh: $target found a problem; the input is in $artifacts, the log in $build/$target.log" >&2
    tail -n 40 "$build/$target.log" >&2
    echo "$build/$target.log" >"$build/$target.failed"
    return 1
  fi
}
# The targets side by side, one per core (each libFuzzer run is one process): the same
# seconds per target in less wall time; their lines printed in the targets' order.
status=0
failed_logs=()
pids=()
for target in "${targets[@]}"; do
  rm -f "$build/$target.failed"
  fuzz_one "$target" >"$build/$target.out" 2>&1 &
  pids+=($!)
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
done
for index in "${!targets[@]}"; do
  target=${targets[$index]}
  run_status=0
  wait "${pids[$index]}" || run_status=$?
  cat "$build/$target.out"
  if [ -f "$build/$target.failed" ]; then
    failed_logs+=("$(cat "$build/$target.failed")")
  fi
  if [ "$run_status" -ne 0 ]; then
    echo "fuzz.sh: $target: exit $run_status" >&2
    status=1
  fi
done
if [ "$status" -eq 0 ]; then
  echo "fuzz.sh: no findings (${seconds} s per target)"
else
  # Each failed run's class (sanitizer fatal error, leak, ASan, UBSan, other): issue 45.
  python3 scripts/verify/sanitizer_failures.py --logs "${failed_logs[@]}" || true
fi
exit "$status"
