#!/usr/bin/env bash
# bfbench heldout --save writes a scene's arena and prints the bfbench pipeline command that
# replays it alone: that command must give the held-out run's own outcome (collisions and
# forward frames; the final pose error). Scenes drawn afresh; the seed is printed.
set -uo pipefail
bfbench=${1:?usage: heldout_replay_test.sh BFBENCH}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
seed=${BVB_HELDOUT_SEED:-$(( ($(date +%s%N) / 1000) % 1000000000 ))}
echo "held-out seed: $seed"

check() {
  local pipeline=$1 want_re=$2 got_re=$3
  local frames=()
  [ "$pipeline" = odometry ] || frames=(--frames 120)
  out=$("$bfbench" heldout "$pipeline" --seed "$seed" --runs 2 --run 1 "${frames[@]}" --ss 1 --save "$tmp" 2>&1)
  echo "$out"
  cmd=$(sed -n 's/^    replay alone: bfbench //p' <<<"$out")
  [ -n "$cmd" ] || fail "$pipeline: no replay command printed"
  # shellcheck disable=SC2086  # the printed command's words
  replay=$("$bfbench" $cmd --quiet 2>&1) || fail "$pipeline: the replay failed: $replay"
  want=$(grep -o -E "$want_re" <<<"$out" | head -1)
  got=$(grep -o -E "$got_re" <<<"$replay" | head -1)
  echo "held-out: $want; replayed: $got"
  [ -n "$want" ] && [ -n "$got" ] || fail "$pipeline: outcome not found"
}

check seg_avoid '[0-9]+ collisions, [0-9]+ forward' 'forward [0-9]+'
w_coll=$(sed -E 's/ collisions.*//' <<<"$want"); w_fwd=$(sed -E 's/.*, ([0-9]+) forward/\1/' <<<"$want")
g_fwd=${got#forward }
g_coll=$(grep -o -E 'collisions: [0-9]+' <<<"$replay" | grep -o -E '[0-9]+')
[ "$w_fwd" = "$g_fwd" ] && [ "$w_coll" = "$g_coll" ] ||
  fail "seg_avoid: the replay differs ($w_coll collisions, $w_fwd forward against $g_coll, $g_fwd)"

check odometry 'final error [0-9.]+ in, [-+][0-9.]+ deg' 'final pose error: [0-9.]+ in, [-0-9.]+ deg'
w=$(sed -E 's/final error ([0-9.]+) in, \+?([-0-9.]+) deg/\1 \2/' <<<"$want")
g=$(sed -E 's/final pose error: ([0-9.]+) in, ([-0-9.]+) deg/\1 \2/' <<<"$got")
[ "$w" = "$g" ] || fail "odometry: the replay differs ($w against $g)"
echo "both replays give the held-out outcome"
