#!/usr/bin/env bash
# The MPI layer's speed and memory (docs/mpi-performance.md):
#  - messages per wall second: a ring of MPI_Sendrecv (examples/mpi/ring.c REPS) on RANKS ranks,
#    analytic model, --compute none; messages = RANKS * (RANKS - 1) * REPS, wall = the simulation's
#    own wall time from --json (loading the program copies excluded; the whole process's shown too);
#  - memory per rank: peak resident memory (/usr/bin/time -v) of examples/mpi/jacobi.c on BIG ranks
#    of the what-if 64x64 machine, less that of 1 rank, divided by BIG - 1.
# usage: bench/mpi/mpi_bench.sh [BUILD_DIR (build/release)] [RANKS (64)] [REPS (200)] [BIG (4096)]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build/release}
ranks=${2:-64}
reps=${3:-200}
big=${4:-4096}
gcsim=$build/apps/cli/gcsim
mpicc=$build/apps/mpi/gcsim-mpicc
for f in "$gcsim" "$mpicc"; do
  [[ -x $f ]] || { echo "mpi_bench: $f not built (cmake --build $build --target gcsim)" >&2; exit 2; }
done
[[ -x /usr/bin/time ]] || { echo "mpi_bench: /usr/bin/time missing (apt-get install time)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$mpicc" -O2 -o "$work/ring" "$here/examples/mpi/ring.c"
"$mpicc" -O2 -o "$work/jacobi" "$here/examples/mpi/jacobi.c" -lm

# peak_kib COMMAND...: runs it quietly, prints its peak resident KiB.
peak_kib() {
  /usr/bin/time -v -o "$work/time.txt" "$@" > "$work/out.txt" 2>&1 || { cat "$work/out.txt" >&2; exit 1; }
  sed -n 's/^.*Maximum resident set size (kbytes): //p' "$work/time.txt"
}
elapsed_s() { sed -n 's/^.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time.txt" |
  awk -F: '{ s = 0; for (i = 1; i <= NF; ++i) s = s * 60 + $i; print s }'; }

cpu_s() { awk -F': ' '/User time|System time/ { s += $2 } END { print s }' "$work/time.txt"; }

ring_kib=$(peak_kib "$gcsim" mpirun -np "$ranks" --model analytic --compute none --json "$work/ring.json" "$work/ring" "$reps")
python3 - "$work/ring.json" "$ranks" "$reps" "$(elapsed_s)" "$ring_kib" "$(cpu_s)" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
ranks, reps, elapsed, kib, cpu = int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5]), float(sys.argv[6])
messages = ranks * (ranks - 1) * reps
wall = j["wall"]["total_s"]
print(f"ring     {ranks} ranks x {reps} rings: {messages} MPI messages ({j['messages']} letters), simulated {j['simulated']['total_s']:.6f} s")
print(f"ring     simulation wall {wall:.3f} s: {messages / wall / 1e6:.2f} M messages/s "
      f"(whole process {elapsed:.2f} s: {messages / elapsed / 1e6:.2f} M/s), peak RSS {kib / 1024:.1f} MiB")
print(f"ring     whole process CPU {cpu:.2f} s (user + system): {messages / cpu / 1e6:.2f} M messages per CPU second "
      f"(what one free core gives on a loaded host)")
PY

config=$here/configs/whatif-4096-nodes.toml
one_kib=$(peak_kib "$gcsim" mpirun -np 1 --config "$config" --model analytic "$work/jacobi" 128 20)
big_kib=$(peak_kib "$gcsim" mpirun -np "$big" --config "$config" --model analytic "$work/jacobi" 128 20)
big_s=$(elapsed_s)
grep -m1 "^jacobi" "$work/out.txt" || true
echo "jacobi   $big ranks on the 64x64 what-if machine: peak RSS $((big_kib / 1024)) MiB in ${big_s} s" \
     "(1 rank: $((one_kib / 1024)) MiB): $(((big_kib - one_kib) / (big - 1))) KiB per rank"
