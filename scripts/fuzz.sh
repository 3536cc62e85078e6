#!/usr/bin/env bash
# Fuzzes Kiln's input path with libFuzzer (doc/fuzzing.md).
#   scripts/fuzz.sh [SECONDS] [TARGET...]   TARGET: input, exodus (default both); SECONDS per
#                                           target (default 300)
# Builds the "sanitize" preset (clang, ASan + UBSan, -DKILN_FUZZ=ON) in build-sanitize, then
# runs each target for SECONDS on one core, starting from fuzz/corpus/<target>. New corpus
# entries go to build-sanitize/fuzz-work/<target>/corpus, crashes to .../artifacts. Prints the
# executions run and the crashes found; exits 1 if there were any. A crash input, once fixed,
# goes to fuzz/regressions/<target>/, which ctest replays with the normal build
# (fuzz_replay_<target>).
# Needs clang and libclang-rt-14-dev (Debian 12; installed here when missing).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-300}
shift || true
targets=${*:-input exodus}

if ! command -v clang++ >/dev/null || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  apt-get update -q && apt-get install -y -q clang libclang-rt-14-dev
fi
[ -f build-sanitize/CMakeCache.txt ] || nice cmake --preset sanitize
for t in $targets; do
  nice cmake --build build-sanitize -j 2 --target "fuzz_$t"
done

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0:detect_odr_violation=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
status=0
for t in $targets; do
  work=build-sanitize/fuzz-work/$t
  mkdir -p "$work/corpus" "$work/artifacts"
  dict=()
  [ "$t" = input ] && dict=(-dict=fuzz/xml.dict)
  log=$work/fuzz.log
  echo "fuzz_$t: $seconds s (log $log)"
  set +e
  nice build-sanitize/fuzz/fuzz_"$t" "${dict[@]}" -max_total_time="$seconds" -timeout=20 \
    -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$work/artifacts/" \
    "$work/corpus" "fuzz/corpus/$t" >"$log" 2>&1
  rc=$?
  set -e
  execs=$(grep -Eo 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -Eo '[0-9]+$' || echo "?")
  crashes=$(find "$work/artifacts" -type f | wc -l)
  echo "fuzz_$t: $execs executions, exit status $rc, $crashes crash inputs in $work/artifacts"
  if [ "$rc" -ne 0 ] || [ "$crashes" -ne 0 ]; then
    grep -E '^==[0-9]+==ERROR|runtime error|SUMMARY|uncaught|deadly signal' "$log" | head -5 || true
    status=1
  fi
done
exit $status
