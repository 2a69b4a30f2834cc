#!/usr/bin/env bash
# bfbench heldout must fail a broken pipeline: each variant below breaks one pipeline with a
# parameter and must end in exit status 1 with that pipeline's verdict FAIL, on scenes drawn
# afresh (the seed is printed; BVB_HELDOUT_SEED=N replays it). Usage: BFBENCH [bfbench options]
#   seg_avoid go_rows=0 stall_frames=1000000: drives on whatever the free space ahead, and
#     never turns away from a stall (avoidance off)
#   flow_avoid thresh_q9=4000 stall_q9=0 stall_turn_frames=1: no flow is ever too much, and a
#     stall (the view still while the wheels turn) turns one frame away (avoidance off)
#   odometry rot_feat=0: the rotation from the scan-line profile alone, which drifts on
#     straight legs (the floor features' rotation off)
set -uo pipefail
bfbench=${1:?usage: heldout_broken_test.sh BFBENCH [options]}
shift
seed=${BVB_HELDOUT_SEED:-$(( ($(date +%s%N) / 1000) % 1000000000 ))}
echo "held-out seed for the broken variants: $seed (BVB_HELDOUT_SEED=$seed replays)"
fail() { echo "FAIL: $*"; exit 1; }

run_broken() {
  local pipeline=$1; shift
  local out status
  out=$("$bfbench" heldout "$pipeline" --seed "$seed" --quiet "$@" 2>&1)
  status=$?
  echo "$out"
  [ "$status" -eq 1 ] || fail "$pipeline $*: exit status $status, want 1 (a broken pipeline passed)"
  grep -q "^$pipeline: .*: FAIL$" <<<"$out" || fail "$pipeline $*: no FAIL verdict"
  grep -q "^held-out seed $seed (--seed)$" <<<"$out" || fail "$pipeline $*: the seed is not printed"
  grep -q "^replay: bfbench heldout $pipeline --seed $seed " <<<"$out" || fail "$pipeline $*: no replay command"
}

run_broken seg_avoid "$@" --param go_rows=0 --param stall_frames=1000000
run_broken flow_avoid "$@" --param thresh_q9=4000 --param stall_q9=0 --param stall_turn_frames=1
run_broken odometry "$@" --param rot_feat=0

# Bad input: one line, exit 2.
"$bfbench" heldout --seed x >/dev/null 2>&1; [ $? -eq 2 ] || fail "--seed x: want exit 2"
BVB_HELDOUT_SEED=-1 "$bfbench" heldout odometry >/dev/null 2>&1; [ $? -eq 2 ] || fail "BVB_HELDOUT_SEED=-1: want exit 2"
"$bfbench" heldout seg_avoid --run 4 --runs 4 >/dev/null 2>&1; [ $? -eq 2 ] || fail "--run past the last scene: want exit 2"
"$bfbench" heldout nosuch >/dev/null 2>&1; [ $? -eq 2 ] || fail "unknown pipeline: want exit 2"
echo "every broken variant failed, as it must"
