#!/usr/bin/env bash
# The gate-level regression sharded (issue 25): scripts/flows/gatelevel/gatesim.sh --shard I/N --partial F
# over two policies at T_sim / 2 (each fails: a register or pin captures too early), the
# unsharded run and 3 shards (one policy, the other, none); the merge of the 3 partials
# must give the unsharded run's verdict, exit status and summary (every policy's verdict,
# vectors and first mismatch), its first mismatch the one the unsharded run printed; a
# missing shard, a shard given twice and a shard of other settings are refused by name.
#
#   gatesim_shard_test.sh GATESIM NETLIST_DIR SPECULAR_TB ROM_DIR SCRATCH
set -euo pipefail
gatesim=$1 netlist=$2 tb=$3 rom=$4 scratch=$5
partial_py="$(dirname "$gatesim")/silicon/gatesim_partial.py"
rm -rf "$scratch"; mkdir -p "$scratch"
fail() { echo "FAIL: $*" >&2; exit 1; }
policies=patent/patent/clamp,minimax/none/literal
period=13.35
run() {  # run NAME [--shard I/N]: the status
  local name=$1; shift
  set +e
  bash "$gatesim" --quiet --netlist-dir "$netlist" --specular-tb "$tb" --policies "$policies" --groups 1 --random 0 \
    --partial "$scratch/$name.json" "$@" "$period" "$scratch/$name" "$rom" >"$scratch/$name.out" 2>&1
  local s=$?
  set -e
  return $s
}
status=0; run whole || status=$?
[[ $status -eq 1 ]] || fail "the unsharded run at $period ns exited $status, not 1: $(cat "$scratch/whole.out")"
# The unsharded run's first mismatch, as it printed it (policy patent_patent_clamp first).
first=$(grep -m1 'policy patent_patent_clamp: .*MISMATCH' "$scratch/whole.out" | sed 's/^.*policy patent_patent_clamp: //')
[[ -n $first ]] || fail "the unsharded run printed no mismatch for patent_patent_clamp: $(cat "$scratch/whole.out")"
grep -q 'policy minimax_none_literal: .*MISMATCH' "$scratch/whole.out" || fail "the unsharded run stopped after the first policy"
for i in 0 1 2; do run "s$i" --shard "$i/3" || true; done
grep -q 'policy patent_patent_clamp' "$scratch/s0.out" && ! grep -q 'policy minimax' "$scratch/s0.out" || fail "shard 0/3 did not run exactly policy 0"
grep -q 'policy minimax_none_literal' "$scratch/s1.out" && ! grep -q 'policy patent_' "$scratch/s1.out" || fail "shard 1/3 did not run exactly policy 1"
! grep -q 'policy ' "$scratch/s2.out" || fail "shard 2/3 ran a policy"

status=0
bash "$gatesim" --merge --partial "$scratch/merged.json" "$scratch/s2.json" "$scratch/s0.json" "$scratch/s1.json" \
  >"$scratch/merge.out" 2>"$scratch/merge.err" || status=$?
[[ $status -eq 1 ]] || fail "the merge exited $status, not 1 (FAIL): $(cat "$scratch/merge.out" "$scratch/merge.err")"
grep -q ': 2 policies, 20 vectors, 0 passed, 2 failed: FAIL$' "$scratch/merge.out" || fail "merged verdict: $(cat "$scratch/merge.out")"
grep -qF "first mismatch: policy patent_patent_clamp: $first" "$scratch/merge.out" \
  || fail "merged first mismatch is not the unsharded run's ($first): $(cat "$scratch/merge.out")"
diff <(python3 "$partial_py" summary "$scratch/whole.json") <(python3 "$partial_py" summary "$scratch/merged.json") \
  || fail "the merged summary differs from the unsharded run's"

refused() {  # refused TEXT FILES...: the merge exits 2 naming TEXT
  local text=$1; shift
  set +e
  bash "$gatesim" --merge --partial "$scratch/refused.json" "$@" >"$scratch/refused.out" 2>"$scratch/refused.err"
  local s=$?
  set -e
  [[ $s -eq 2 ]] || fail "merge of $* exited $s, not 2"
  grep -qF -- "$text" "$scratch/refused.err" || fail "merge of $* did not say '$text': $(cat "$scratch/refused.err")"
  [[ ! -e $scratch/refused.json ]] || fail "a refused merge wrote its partial"
}
refused "1 of 3 shards missing: 1/3" "$scratch/s0.json" "$scratch/s2.json"
refused "shard 2/3 is given twice: '$scratch/s2.json' and '$scratch/s2.json'" "$scratch/s0.json" "$scratch/s1.json" "$scratch/s2.json" "$scratch/s2.json"
python3 - "$scratch/s1.json" "$scratch/other.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1])); p["settings"]["random"] = 8
json.dump(p, open(sys.argv[2], "w"))
PY
refused "'$scratch/other.json' has other settings than '$scratch/s0.json' (random 8 vs 0)" "$scratch/s0.json" "$scratch/other.json" "$scratch/s2.json"
echo "gatesim shards: the merge of 3 shards equals the unsharded run (FAIL, first mismatch: $first); bad sets refused"
