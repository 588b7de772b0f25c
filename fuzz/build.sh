#!/usr/bin/env bash
# Builds the libFuzzer target fuzz/pipeline_fuzz_target.cpp with clang (ASan + UBSan) and
# prepares its seed corpus. Usage: fuzz/build.sh [build dir]   (default: build-fuzz)
# Then run, e.g.:  build-fuzz/drycut_fuzz -max_total_time=600 -timeout=5 -rss_limit_mb=2048 \
#                    -dict=fuzz/sinumerik.dict build-fuzz/corpus build-fuzz/seeds
# Needs clang with its runtimes (libFuzzer, sanitizers) and pkg-config from Debian (bookworm):
#   apt-get install -y clang libclang-rt-14-dev pkg-config
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(readlink -f "${1:-$root/build-fuzz}")
san="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"

# The stage libraries, instrumented for coverage (fuzzer-no-link) and the sanitizers.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DDRYCUT_BUILD_TESTS=OFF \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link $san" > /dev/null
# DRYCUT=path/to/drycut (any build) generates the thesis seeds; otherwise it is built here too.
drycut=${DRYCUT:-$build/drycut}
targets=drycut_motion
[ -n "${DRYCUT:-}" ] || targets="$targets drycut"
cmake --build "$build" -j"${JOBS:-2}" --target $targets

# The fuzz target itself, linked with libFuzzer's main.
clang++ -std=c++20 -O1 -g -fsanitize=fuzzer $san \
  -I"$root/src" -I/usr/include/eigen3 \
  "$root/fuzz/pipeline_fuzz_target.cpp" \
  "$build/libdrycut_motion.a" "$build/libdrycut_interp.a" "$build/libdrycut_parser.a" \
  "$build/libdrycut_geometry.a" "$build/libdrycut_machine.a" \
  $(pkg-config --libs spdlog fmt) -o "$build/drycut_fuzz"

# Seeds: the alarm suite, the regression programs, the conformance programs (their subprograms and
# definition files as inputs of their own) and the reference experiment's programs.
seeds="$build/seeds"
rm -rf "$seeds"; mkdir -p "$seeds" "$build/corpus"
find "$root/tests/alarms" "$root/tests/programs" "$root/tests/conformance" -type f \
  \( -iname '*.mpf' -o -iname '*.spf' -o -iname '*.def' \) |
  while read -r f; do cp "$f" "$seeds/$(echo "${f#"$root"/}" | tr '/' '_')"; done
"$drycut" generate --thesis "$build/thesis" > /dev/null
find "$build/thesis" -type f | while read -r f; do cp "$f" "$seeds/thesis_$(basename "$f")"; done
echo "built $build/drycut_fuzz with $(ls "$seeds" | wc -l) seeds in $seeds"
