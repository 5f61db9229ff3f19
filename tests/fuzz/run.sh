#!/usr/bin/env bash
# Runs the libFuzzer targets built in BUILD (./dev fuzz calls this).
#   run.sh BUILD regress            each target over its seeds, then 2,000 mutations (CI: a crash found
#                                   once and added to tests/fuzz/corpus/ stays fixed)
#   run.sh BUILD TARGET SECONDS     one target for SECONDS of fuzzing; new inputs go to BUILD/fuzz-corpus/
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$1; shift
shared=$(cd "$root/.." && pwd)/shared/assets/gltf

# Seeds for each target, copied flat into BUILD/fuzz-seeds/TARGET (libFuzzer takes folders).
seed() {
  local target=$1 dir="$build/fuzz-seeds/$1"
  rm -rf "$dir"; mkdir -p "$dir"
  case $target in
    scene) find "$root/assets/scenes" "$root/tests/scenes" "$root/tests/bad-inputs" \
                -name '*.json' -print0 ;;
    gltf)  { find "$root/assets/models" "$root/tests/bad-inputs" "$root/tests/gltf-variants" \( -name '*.gltf' -o -name '*.glb' \) -print0
             [ -d "$shared" ] && find "$shared" \( -name '*.gltf' -o -name '*.glb' \) -size -2M -print0; } ;;
    cli)   printf '' ;;
  esac | { n=0; while IFS= read -r -d '' f; do cp "$f" "$dir/$n-$(basename "$f" | tr -c 'A-Za-z0-9._-' _)"; n=$((n+1)); done; }
  echo "$dir"
}

run() {  # run TARGET EXTRA-ARGS...
  local target=$1; shift
  local seeds; seeds=$(seed "$target")
  local fresh="$build/fuzz-corpus/$target"
  mkdir -p "$fresh" "$build/fuzz-crashes"
  # The first folder receives new interesting inputs; the repository's folders are only read (a
  # target may have no regression inputs yet: git keeps no empty folder).
  local kept=()
  [ -d "$root/tests/fuzz/corpus/$target" ] && kept=("$root/tests/fuzz/corpus/$target")
  "$build/tests/fuzz/fuzz_$target" -artifact_prefix="$build/fuzz-crashes/$target-" -print_final_stats=1 \
      -rss_limit_mb=4096 "$@" "$fresh" "${kept[@]}" "$seeds"
}

case ${1:-regress} in
  regress)
    for t in scene gltf cli; do
      echo "fuzz: $t (regression: seeds + corpus, then 2000 runs)"
      log="$build/fuzz-$t.log"
      if ! run "$t" -runs=2000 >"$log" 2>&1; then
        tail -n 60 "$log"; echo "fuzz: $t FAILED (the crashing input is in $build/fuzz-crashes/)"; exit 1
      fi
      grep -E '^(stat::(number_of_executed_units|new_units_added|peak_rss_mb)|Done|INFO: seed corpus)' "$log" || true
    done ;;
  *)
    run "$1" -max_total_time="${2:-60}" ;;
esac
