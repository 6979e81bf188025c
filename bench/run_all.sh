#!/usr/bin/env bash
# `make bench`: runs every Google Benchmark program and keeps their JSON
# results in out/bench/. Medians are reported (the programs repeat each case).
set -euo pipefail
build=${1:-build}
cd "$(dirname "$0")/.."
mkdir -p out/bench
status=0
for bin in "$build"/bench/*/bench_*; do
  [ -x "$bin" ] || continue
  name=$(basename "$bin")
  echo "== $name"
  if ! "$bin" --benchmark_out="out/bench/$name.json" --benchmark_out_format=json; then
    echo "$name failed" >&2
    status=1
  fi
done
echo "results in out/bench/*.json"
exit $status
