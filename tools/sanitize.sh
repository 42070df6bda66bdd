#!/usr/bin/env bash
# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer, then the input-parser
# fuzzer (libFuzzer) for a short run over the bundled and malformed inputs, both from one clang
# build. Both are part of CI (.ci/run); FUZZ_SECONDS sets the fuzzing time (default 60),
# FUZZ_MAX_LEN the largest input (default 20000 bytes).
set -euo pipefail
cd "$(dirname "$0")/.."
# With clang and its runtime (libFuzzer, the sanitisers), in the same apt run.
bash tools/install_dependencies.sh clang libclang-rt-14-dev
jobs="$(nproc)"
# Each stage's processor time (user and system, children included) and wall time, for the
# figures in docs/architecture.md, "Build".
TIMEFORMAT='%U s user, %S s system, %R s wall'

# One build for both: the library, tests and tools with -fsanitize=address,undefined, the
# library also with libFuzzer's coverage feedback (-fsanitize=fuzzer-no-link: in the tests its
# callbacks do nothing), and fuzz_inputs linked with libFuzzer. CI used to compile everything
# under the sanitisers with g++ and the library a second time with clang for the fuzzer; one
# clang build saves that second build, about a quarter of CI's processor time
# (docs/architecture.md, "Build"). The sanitised suite is the same tests, with clang's ASan/UBSan.
# -O1: the sanitised build is for finding errors, and compiles in about 40 % of the time at -O2 -g.
# The test files compile in batches (RAILMODAL_UNITY_TESTS; docs/architecture.md, "Build"); the
# header examples, 41 small programs, are compiled and run by the release build (tools/test.sh).
CC=clang CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" \
  -DRAILMODAL_SANITIZE=ON -DRAILMODAL_BUILD_FUZZERS=ON -DRAILMODAL_BUILD_BENCHMARKS=OFF -DRAILMODAL_PYTHON=OFF \
  -DRAILMODAL_UNITY_TESTS=ON -DRAILMODAL_UNITY_LIBRARY=ON -DRAILMODAL_HEADER_EXAMPLES=OFF >/dev/null
echo "CI stage: sanitized build (clang, with the fuzzer)"
time cmake --build build-asan -j"$jobs"
# Each slow analysis runs here once, not once a format or a test: the golden, cli and GoogleTest
# lists of what the sanitized build leaves out say which other sanitized test runs its code
# (tests/golden/CMakeLists.txt, tests/cli/, tests/CMakeLists.txt); the release build runs them all.
echo "CI stage: sanitized ctest"
time ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-asan --output-on-failure --no-tests=error -j"$jobs" -E package_consumer

# Seed corpus: every bundled and malformed input, each under the parser its extension names.
corpus=build-asan/corpus
rm -rf "$corpus" && mkdir -p "$corpus"
i=0
for f in data/vehicles/*.toml tests/cli/bad/*.toml tests/corpus/bad_inputs/*.toml; do
  [ -e "$f" ] || continue
  if grep -q '^\[scene\]' "$f"; then p='\x01'; elif grep -q '^\[study\]' "$f"; then p='\x03'; else p='\x00'; fi
  { printf "$p"; cat "$f"; } > "$corpus/seed$((i++))"
done
for f in data/scenes/*.toml; do { printf '\x01'; cat "$f"; } > "$corpus/seed$((i++))"; done
for f in data/studies/*.toml; do { printf '\x03'; cat "$f"; } > "$corpus/seed$((i++))"; done
for f in data/matrices/*.mtx tests/cli/bad/*.mtx tests/corpus/bad_inputs/*.mtx; do
  [ -e "$f" ] || continue
  { printf '\x02'; cat "$f"; } > "$corpus/seed$((i++))"
done
# Inputs at the parsers' limits (docs/input.md, "Resource limits"), for the mutations to cross:
# a key 64 tables deep, a header 64 deep, a line of 8192 bytes of the densest values.
printf '\x00[vehicle]\n%sa = 1\n' "$(printf 'a.%.0s' {1..63})" > "$corpus/seed$((i++))"
printf '\x00[%sa]\nb = 1\n' "$(printf 'a.%.0s' {1..63})" > "$corpus/seed$((i++))"
printf '\x00[vehicle]\na = [ %s1]\n' "$(printf '"",%.0s' {1..2728})" > "$corpus/seed$((i++))"
printf '\x03[study]\n%s' "$(printf '[[variant]]\nname = "v%s"\n' {1..200})" > "$corpus/seed$((i++))"
# The fuzzer writes each input to /dev/shm/railmodal_fuzz_<pid>/ (fuzz_inputs.cpp): remove those
# directories whose process has ended (this run's, and any an interrupted run left), on any exit.
# Crash, leak and timeout reproducers go to build-asan/, not the working directory.
clean_fuzz_scratch() {
  local d
  for d in /dev/shm/railmodal_fuzz_*; do
    [ -d "$d" ] || continue
    kill -0 "${d##*_}" 2>/dev/null || rm -rf "$d" 2>/dev/null || true
  done
}
trap clean_fuzz_scratch EXIT
# -max_len: inputs up to 20 000 bytes, past the 8192-byte line limit and the 64-level nesting
# limit (libFuzzer's default follows the largest seed). -timeout: an input parsed for longer
# than 10 s is a time bug (issue 18: 30 000 strings on one line took 32 s), not a slow run.
echo "CI stage: fuzz run"
time build-asan/tools/fuzz/fuzz_inputs -max_total_time="${FUZZ_SECONDS:-60}" -max_len="${FUZZ_MAX_LEN:-20000}" -timeout=10 \
  -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix=build-asan/ "$corpus" 2>&1 | tail -15
