#!/usr/bin/env bash
# Kernel throughput against SimGrid on the same ring: N processors, each sends SIZE bytes to its
# right neighbour and receives from its left, ITERATIONS times. Needs libsimgrid-dev at build time.
# Usage: tests/bench/compare_ring.sh [BUILD_DIR] [N] [ITERATIONS] [SIZE] [REPEATS]
set -euo pipefail
build=${1:-build/release}; n=${2:-64}; it=${3:-2000}; size=${4:-64}; repeats=${5:-5}
[[ -x $build/tests/bench/simgrid_ring ]] || { echo "simgrid_ring not built: apt-get install libsimgrid-dev, then reconfigure" >&2; exit 1; }
best() { sort -g | tail -1; }
g=$(for i in $(seq "$repeats"); do "$build/apps/cli/gcsim" bench ring --nodes "$n" --iterations "$it" --size "$size" | awk '/^rate/ {print $2}'; done | best)
s=$(for i in $(seq "$repeats"); do "$build/tests/bench/simgrid_ring" "$n" "$it" "$size" --cfg=contexts/factory:boost --log=root.thres:critical 2>/dev/null | awk '/^rate/ {print $2}'; done | best)
printf 'gcsim    %12.0f simulated messages per wall second (analytic model, best of %s)\n' "$g" "$repeats"
printf 'simgrid  %12.0f simulated messages per wall second (boost contexts, best of %s)\n' "$s" "$repeats"
awk -v g="$g" -v s="$s" 'BEGIN { printf "ratio    %12.2f x\n", g / s }'
