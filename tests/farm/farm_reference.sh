#!/usr/bin/env bash
# The unsharded run of every group of the farm's smoke regression (scripts/farm/farm.sh
# list smoke): each group's tool on the group's arguments without --shard, its output in
# OUT_DIR/GROUP.txt and its partial in OUT_DIR/GROUP.json. What tests/farm/farm_test.sh
# compares every merged result with; ctest runs it once as the fixture
# farm_smoke_reference for both farm tests (the Slurm and the local executor), which
# computed the same references each (about 20 s of tools).
# Usage: farm_reference.sh BUILD_DIR OUT_DIR   (OUT_DIR is emptied first)
set -euo pipefail
if [[ $# -ne 2 ]]; then
  echo "usage: farm_reference.sh BUILD_DIR OUT_DIR" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
out=$2
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
farm="$root/scripts/farm/farm.sh"
rm -rf "$out"
mkdir -p "$out"
groups=0
while IFS=$'\t' read -r group kind args; do
  tool="$build/tools/$kind/specular_$kind"; [[ $kind != tb ]] || tool="$build/testbench/specular_tb"
  # shellcheck disable=SC2086  # the task's arguments, as farm.sh runs them
  if ! "$tool" $args --partial "$out/$group.json" >"$out/$group.txt"; then
    echo "farm_reference.sh: FAIL: the unsharded $group ($tool $args) failed" >&2
    exit 1
  fi
  groups=$((groups + 1))
done < <("$farm" list smoke --build "$build" | awk -F'\t' '!seen[$2]++ {sub(/ --shard [0-9]+\/[0-9]+$/, "", $4); print $2 "\t" $3 "\t" $4}')
if ((groups == 0)); then
  echo "farm_reference.sh: FAIL: the smoke regression lists no group" >&2
  exit 1
fi
echo "farm_reference.sh: $groups unsharded groups in $out"
