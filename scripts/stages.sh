# Stage timing for scripts/test.sh and .ci/run (sourced, not run): `stage NAME CMD...`
# runs CMD, remembers its wall time, and the table of every stage's time with the total
# is printed when the script exits, passed or failed, so a stage that grew shows in the
# CI log before the whole run nears CI's limit. Budgets: docs/testing.md ("CI budget").
# Printed, not asserted: timings on a shared machine are no test.
# shellcheck shell=bash

SPECULAR_STAGES=()
# The first script that sources this sets the origin of the total (.ci/run's total
# includes setup; scripts/test.sh run alone counts from its own start).
SPECULAR_STAGES_START=${SPECULAR_STAGES_START:-$(date +%s)}
SPECULAR_STAGES_ORIGIN=${SPECULAR_STAGES_ORIGIN:-$(basename "$(dirname "$0")")/$(basename "$0")}
export SPECULAR_STAGES_START SPECULAR_STAGES_ORIGIN

minutes() { awk -v s="$1" 'BEGIN { printf "%.1f", s / 60 }'; }

stage() {
  local name=$1 started status
  shift
  started=$(date +%s)
  echo "=== stage $name: started $(date -u +%H:%M:%S) UTC"
  set +e
  "$@"
  status=$?
  set -e
  local seconds=$(($(date +%s) - started))
  SPECULAR_STAGES+=("$(printf '%-22s %5d s  %5s min%s' "$name" "$seconds" "$(minutes "$seconds")" \
                      "$([ "$status" -eq 0 ] || echo "  (failed, exit $status)")")")
  echo "=== stage $name: ${seconds} s (exit $status)"
  return "$status"
}

print_stages() {
  local total=$(($(date +%s) - SPECULAR_STAGES_START))
  echo "=== stage times ($1)"
  local line
  for line in "${SPECULAR_STAGES[@]}"; do echo "    $line"; done
  printf '    %-22s %5d s  %5s min (since %s started)\n' total "$total" "$(minutes "$total")" \
    "$SPECULAR_STAGES_ORIGIN"
}
