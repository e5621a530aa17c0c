#!/usr/bin/env bash
# Runs every benchmark program (bench/*.cpp) built in BUILD_DIR, one after the other.
set -euo pipefail
build_dir=${1:-build}
cmake --build "$build_dir" --target bench_all
shopt -s nullglob
benches=("$build_dir"/bench/villa_bench_*)
if [[ ${#benches[@]} -eq 0 ]]; then echo "bench: no benchmarks yet"; exit 0; fi
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
for b in "${benches[@]}"; do
  [[ -x "$b" ]] || continue
  echo "== $(basename "$b")"
  "$b"
  # The furnish bench once more with the offline critic: relations before and after, the critic's time.
  if [[ "$(basename "$b")" == villa_bench_furnish ]]; then
    echo "== $(basename "$b") --critic offline"
    "$b" --critic offline
  fi
done
