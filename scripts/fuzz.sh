#!/usr/bin/env bash
# Fuzzing (tests/fuzz/README.md): builds the CMake preset `fuzz` (clang,
# AddressSanitizer + UBSan, libFuzzer) and runs each fuzz target for a
# bounded time, on a copy of its corpus (tests/fuzz/corpus/<target>/, plus
# the saved crashers in tests/fuzz/regressions/<target>/), so the tree stays
# clean. Fails if any target finds a crash, a leak, undefined behaviour, a
# timeout or runs out of memory, and says where the input was saved.
#   scripts/fuzz.sh                 every target, 60 s in all (what CI runs)
#   scripts/fuzz.sh SECONDS         every target, SECONDS in all
#   scripts/fuzz.sh SECONDS TARGET  one target (mesh_import, runtime_file, hull_obj, cell_result, scene_snapshot)
# HULLCOVER_WARNINGS_AS_ERRORS=ON in the environment fails the build on any warning (CI sets it).
set -euo pipefail
cd "$(dirname "$0")/.."
total="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(mesh_import runtime_file hull_obj cell_result scene_snapshot)
per_target=$(( total / ${#targets[@]} ))
[ "$per_target" -ge 1 ] || per_target=1

scripts/setup.sh
cmake --preset fuzz -DHULLCOVER_WARNINGS_AS_ERRORS="${HULLCOVER_WARNINGS_AS_ERRORS:-OFF}" >/dev/null
cmake --build --preset fuzz -j"$(nproc)" --target "${targets[@]/#/fuzz_}"

# Crashers go where a failed CI run keeps them (build/ is not tracked); the
# working corpus, which libFuzzer grows, goes to a temp folder.
artifacts="$PWD/build/fuzz/fuzz-artifacts"
work="$(mktemp -d "${TMPDIR:-/tmp}/hullcover-fuzz-corpus-XXXXXX")"
trap 'rm -rf "$work"' EXIT
# The targets' scratch folders go there too: libFuzzer ends with _Exit, so
# a target cannot remove its own.
export TMPDIR="$work"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
# Leaks inside Debian's libraries that hullcover cannot fix (the file says which).
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan_suppressions.txt:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"

failed=()
for target in "${targets[@]}"; do
  binary="build/fuzz/tests/fuzz/fuzz_$target"
  [ -x "$binary" ] || { echo "fuzz: no target '$target' (mesh_import, runtime_file, hull_obj, cell_result, scene_snapshot)" >&2; exit 2; }
  mkdir -p "$work/$target" "$artifacts/$target"
  cp tests/fuzz/corpus/"$target"/* "$work/$target"/
  echo "fuzz: $target for ${per_target} s"
  # -timeout: one input running 10 s is a hang; -rss_limit_mb: CI's memory.
  if "$binary" "$work/$target" "tests/fuzz/regressions/$target" \
       -max_total_time="$per_target" -timeout=10 -rss_limit_mb=2048 \
       -artifact_prefix="$artifacts/$target/" -print_final_stats=1 >"$work/$target.log" 2>&1; then
    grep -E '^(Done|stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb)|cov: ' \
      "$work/$target.log" | tail -n 5
  else
    tail -n 60 "$work/$target.log"
    echo "fuzz: $target FAILED; the input that failed it:" >&2
    ls -1t "$artifacts/$target"/* 2>/dev/null | head -n 3 >&2 || true
    echo "fuzz: reproduce with $binary FILE; once fixed, add FILE to tests/fuzz/regressions/$target/" \
         "(every test run replays it: test_fuzz_corpus)" >&2
    failed+=("$target")
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: failed: ${failed[*]}" >&2
  exit 1
fi
echo "fuzz: ${targets[*]}: no failure in ${total} s"
