#!/usr/bin/env bash
# Side-by-side: wingbeat's shell FE vs CalculiX (ccx, S6 shells expanded to C3D15 solids)
# on the same default-wing facet mesh. Needs `ccx` (apt-get install -y calculix-ccx).
# Usage: scripts/calculix_compare.sh [MESH_MM ...]   (default: 2.0 1.0)
set -euo pipefail
cd "$(dirname "$0")/.."
sizes=("$@"); [ ${#sizes[@]} -eq 0 ] && sizes=(2.0 1.0)
work=$(mktemp -d)
cargo build --release --example fem_ccx -q
bin="${CARGO_TARGET_DIR:-target}/release/examples/fem_ccx"
for h in "${sizes[@]}"; do
  echo "== mesh size $h mm"
  "$bin" "$h" "$work/wing.inp"
  start=$(date +%s.%N)
  (cd "$work" && OMP_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 ccx -i wing > ccx.log 2>&1)
  end=$(date +%s.%N)
  printf 'calculix: %.3f s (1 thread), f = ' "$(echo "$end - $start" | bc)"
  awk '/E I G E N V A L U E   O U T P U T/{on=1; next} on && NF==5 && $1+0>0 {printf "%.2f ", $4; n++} n==6{exit}' "$work/wing.dat"
  echo
done
rm -rf "$work"
