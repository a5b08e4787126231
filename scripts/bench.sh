#!/usr/bin/env bash
# Build specular_bench in Release and run it: every model in its own process, 5
# interleaved repetitions, figures as `name: median unit [min..max]` lines, ratios to
# std::pow, targets met / not met / within noise (docs/performance.md).
#
#   scripts/bench.sh                   full run, 5 repetitions (about 2 min on 2 quiet cores)
#   scripts/bench.sh --quick           smoke run: few operations, figures not stable
#   scripts/bench.sh --repetitions N   N interleaved repetitions (1..100) instead of 5
#   scripts/bench.sh --runs N          N whole runs one after the other
#   BUILD_DIR=dir scripts/bench.sh     build directory (default build-bench)
#
# The output is also written to $BUILD_DIR/bench-<date>.txt.
set -euo pipefail
cd "$(dirname "$0")/.."

runs=1
bench_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) bench_args+=(--quick) ;;
    --repetitions)
      [ $# -ge 2 ] || { echo "bench.sh: --repetitions needs a value (1..100)" >&2; exit 2; }
      bench_args+=(--repetitions "$2"); shift ;;
    --runs)
      [ $# -ge 2 ] || { echo "bench.sh: --runs needs a value" >&2; exit 2; }
      case "$2" in ''|*[!0-9]*|0) echo "bench.sh: --runs $2: expected a positive integer" >&2; exit 2 ;; esac
      runs=$2; shift ;;
    -h|--help) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench.sh: unknown option '$1' (allowed: --quick, --repetitions N, --runs N, --help)" >&2; exit 2 ;;
  esac
  shift
done

build=${BUILD_DIR:-build-bench}
jobs=$(nproc 2>/dev/null || echo 2)
echo "+ cmake -S . -B $build -DCMAKE_BUILD_TYPE=Release"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
echo "+ cmake --build $build -j$jobs --target specular_bench"
cmake --build "$build" -j"$jobs" --target specular_bench >/dev/null

log="$build/bench-$(date +%Y%m%d-%H%M%S).txt"
{
  echo "# $(uname -srm), $(nproc) cores, $(g++ --version | head -1), load: $(cut -d' ' -f1-3 /proc/loadavg)"
  for ((run = 1; run <= runs; ++run)); do
    [ "$runs" -gt 1 ] && echo "# ---- run $run of $runs"
    "$build/bench/specular_bench" "${bench_args[@]}"
  done
} | tee "$log"
echo "# written to $log"
