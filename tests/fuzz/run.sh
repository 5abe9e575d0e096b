#!/usr/bin/env bash
# Runs every fuzz target (or the named ones) for SECONDS each (default 60), one after the other,
# with ASan and UBSan.
#   tests/fuzz/run.sh 600
#   tests/fuzz/run.sh 600 obj world      # two lanes on two cores: run two of these side by side
# Builds the `fuzz` preset first. Each target's growing corpus lives in build/fuzz/corpus/NAME
# (seeded from the shipped files and tests/fuzz/seeds/NAME); a crash leaves crash-* in
# build/fuzz/findings/NAME: copy it into tests/fuzz/regressions/NAME once fixed, and CTest
# replays it on every run. The last lines of each target's log give executions and cov/ft.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-60}
shift || true
only=" $* "
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
status=0
for exe in build/fuzz/tests/fuzz/fuzz_*; do
  [[ -x $exe && ! $exe == *.seeds ]] || continue
  name=${exe##*/fuzz_}
  [[ $only == "  " || $only == *" $name "* ]] || continue
  corpus=build/fuzz/corpus/$name findings=build/fuzz/findings/$name
  mkdir -p "$corpus" "$findings"
  read -r -a listed < "$exe.seeds"
  seeds=()
  for d in "${listed[@]}"; do [[ -d $d ]] && seeds+=("$d"); done  # libFuzzer stops on a missing one
  echo "== $name: ${seconds}s"
  if ! "$exe" "$corpus" "${seeds[@]}" -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
       -artifact_prefix="$findings/" -print_final_stats=1 >"build/fuzz/$name.log" 2>&1; then
    echo "   FOUND a problem: see build/fuzz/$name.log and $findings/"
    status=1
  fi
  grep -E "^#[0-9]+.*(DONE|pulse|NEW)" "build/fuzz/$name.log" | tail -1 || true
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "build/fuzz/$name.log" || true
done
exit $status
