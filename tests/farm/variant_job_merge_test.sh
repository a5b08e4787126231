#!/usr/bin/env bash
# scripts/farm/variant_job.py --merge (issue 26): the farm's merge of a variant's RTL-proof
# and silicon tasks takes one complete set of passed shards and refuses anything else,
# naming the shard or file: a missing shard, a duplicate, other settings, a failed shard.
# Partials are written here by hand (no build needed). Also farm.sh's layout regression's
# task list (issue 48).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
job=("python3" "$root/scripts/farm/variant_job.py")
scratch=$(mktemp -d "${TMPDIR:-/tmp}/variant_job_test.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
fail() { echo "variant_job_merge_test.sh: FAIL: $*" >&2; exit 1; }

partial() {  # partial FILE INDEX COUNT EXIT [NAME]
  printf '{"kind": "specular_variant_job partial result", "version": 1, "settings": {"job": "rtl", "name": "%s"}, "shard": {"index": %d, "count": %d}, "summary": {"exit": %d, "passed_tests": 1}, "timing": {"wall_seconds": 1.5}}\n' \
    "${5:-patent}" "$2" "$3" "$4" >"$1"
}
for i in 0 1 2; do partial "$scratch/p$i.json" "$i" 3 0; done
partial "$scratch/failed1.json" 1 3 1
partial "$scratch/other1.json" 1 3 0 exp2

expect() {  # expect STATUS TEXT COMMAND...
  local status=$1 text=$2 got=0 output
  shift 2
  output=$("$@" 2>&1) || got=$?
  ((got == status)) || fail "'$*' exited $got, not $status: $output"
  [[ $output == *"$text"* ]] || fail "'$*' does not say '$text': $output"
}
expect 0 "variant patent, rtl: 3 shard(s), 3 test(s) passed, 4.5 s of tasks: PASS" \
  "${job[@]}" --merge "$scratch/p2.json" "$scratch/p0.json" "$scratch/p1.json"
expect 2 "1 of 3 shards missing: 1/3" "${job[@]}" --merge "$scratch/p0.json" "$scratch/p2.json"
expect 2 "shard 0/3 is given twice" "${job[@]}" --merge "$scratch/p0.json" "$scratch/p0.json" "$scratch/p1.json" "$scratch/p2.json"
expect 2 "other settings" "${job[@]}" --merge "$scratch/p0.json" "$scratch/other1.json" "$scratch/p2.json"
expect 1 "failed: $scratch/failed1.json" "${job[@]}" --merge "$scratch/p0.json" "$scratch/failed1.json" "$scratch/p2.json"
expect 2 "unknown job 'proof'" "${job[@]}" proof patent --partial "$scratch/x.json"
expect 2 "energy is one task: --shard 0/1" "${job[@]}" energy device --shard 0/2 --partial "$scratch/x.json"
expect 2 "layout is one task: --shard 0/1" "${job[@]}" layout device_sync --shard 0/2 --partial "$scratch/x.json"
expect 2 "--utilisation is an option of layout, not of energy" "${job[@]}" energy exp2 --utilisation 0.45 --partial "$scratch/x.json"
expect 2 "--utilisation: '0.95' is not a density from 0.2 to 0.9" "${job[@]}" layout exp2 --utilisation 0.95 --partial "$scratch/x.json"
expect 2 "--utilisation: 'half' is not a density from 0.2 to 0.9" "${job[@]}" layout exp2 --utilisation half --partial "$scratch/x.json"
expect 2 "--no-cleanup is an option of layout, not of silicon" "${job[@]}" silicon exp2 --no-cleanup --partial "$scratch/x.json"
# farm.sh's layout regression (issue 48): one variant_job layout task per design, the two
# device tops first, then every name the variant registry lists (a stand-in lister here:
# no build needed), one_pass and one_pass_pipelined with their lower density and no
# stage 3, schlick with no stage 3.
mkdir -p "$scratch/build/tools/variant_error"
printf '#!/bin/sh\necho exp2 one_pass one_pass_pipelined schlick us5739820\n' >"$scratch/build/tools/variant_error/specular_variant_error"
chmod +x "$scratch/build/tools/variant_error/specular_variant_error"
diff <(bash "$root/scripts/farm/farm.sh" list layout --build "$scratch/build") - <<'EOF' || fail "farm.sh list layout: not one layout task per design"
0	layout_device	variant_job	layout device --shard 0/1
1	layout_device_sync	variant_job	layout device_sync --shard 0/1
2	layout_exp2	variant_job	layout exp2 --shard 0/1
3	layout_one_pass	variant_job	layout one_pass --utilisation 0.45 --no-cleanup --shard 0/1
4	layout_one_pass_pipelined	variant_job	layout one_pass_pipelined --utilisation 0.45 --no-cleanup --shard 0/1
5	layout_schlick	variant_job	layout schlick --no-cleanup --shard 0/1
6	layout_us5739820	variant_job	layout us5739820 --shard 0/1
EOF
# farm.sh's mutants regression (issue 46): the whole IP's two targets, 2 shards of 100 each,
# after the device's groups.
diff <(bash "$root/scripts/farm/farm.sh" list mutants --build "$scratch/build" | grep -P '\trtl_mutants_specular_(reg_block|ip_axi)\t') - <<'EOF' || fail "farm.sh list mutants: not 2 shards per IP target"
18	rtl_mutants_specular_reg_block	rtl_mutants	--target specular_reg_block --count 100 --seed 1 --shard 0/2
19	rtl_mutants_specular_reg_block	rtl_mutants	--target specular_reg_block --count 100 --seed 1 --shard 1/2
20	rtl_mutants_specular_ip_axi	rtl_mutants	--target specular_ip_axi --count 100 --seed 1 --shard 0/2
21	rtl_mutants_specular_ip_axi	rtl_mutants	--target specular_ip_axi --count 100 --seed 1 --shard 1/2
EOF
echo "variant_job_merge_test.sh: PASS"
