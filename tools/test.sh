#!/bin/sh
# Builds and runs iecoop's whole test suite, the way CI does:
#   0. the layout of the code against .clang-format (sh tools/format.sh --check),
#   1. clang++ with AddressSanitizer and UndefinedBehaviorSanitizer (-O0), which also builds the
#      libFuzzer targets of tests/fuzz/ and fuzzes each for 5 s (CTest label `fuzz`;
#      docs/reliability.md),
#   2. g++ Release (-O3, the build the benchmarks are measured in: GCC warns of some things,
#      -Warray-bounds, -Wrestrict, only when it optimises),
# both with -Wall -Wextra -Wpedantic -Werror on iecoop's own code. Each build runs the unit
# tests (and the test kit's, with its JUnit reports read by xmllint), the compile-fail checks
# and the examples; the g++ build also runs iecoop-check's tests, builds the consumer projects
# (find_package, add_subdirectory, FetchContent, each with unit tests written with the test
# kit), checks every example clean with iecoop-check, builds the benchmarks and compiles every
# header on its own with -fno-exceptions -fno-rtti.
#   3. the data exchange's tests (Modbus, MQTT, against real peers) once more under clang++ with
#      ThreadSanitizer (docs/exchange.md),
#   4. the firmware examples for six Cortex-M cores (CMake presets cortex-m0plus, cortex-m3,
#      cortex-m4f, cortex-m7, cortex-m33, cortex-m55), each run under QEMU on a board that has
#      the core, and the check that they link no heap, exceptions or RTTI (CTest label
#      `embedded`; see docs/embedded.md).
# Installs the Debian packages it needs first, the cross toolchain and QEMU included; if they
# cannot be installed, it fails. Builds and tests run CMAKE_BUILD_PARALLEL_LEVEL jobs at once
# where it is set (a shared machine), else one per core.
set -eu
cd "$(dirname "$0")/.."
started=$(date +%s)
. tools/require_packages.sh
iecoop_require_packages cmake make g++ clang doctest-dev libfmt-dev libbenchmark-dev
# python3 writes the random SFC charts of the engines' differential test (tests/sfc_engines);
# scipy simulates the Util library's PID loops that tests/util/pid_scipy.py compares with iecoop's.
iecoop_require_packages python3 python3-scipy
# valgrind's memcheck runs the initial-values program in the g++ build (tests initial_values.*).
iecoop_require_packages valgrind
# iecoop-check (docs/iecoop-check.md) is built on libclang's C API: its headers come with
# libclang-14-dev (23 MB to download; clang above already brings the library).
iecoop_require_packages libclang-14-dev
# clang's sanitizer libraries and libFuzzer, for the clang build (clang only recommends them).
iecoop_require_packages libclang-rt-14-dev
# The slim set of docs/embedded.md: the firmware links with arm-none-eabi-gcc and needs
# neither libstdc++-arm-none-eabi-newlib's 1.5 GB of libraries nor QEMU's recommends.
iecoop_require_packages gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-dev qemu-system-arm
# The trace writers' real readers (docs/trace.md): GTKWave's vcd2fst and fst2vcd read every VCD,
# rsvg-convert renders every SVG and xmllint parses it.
iecoop_require_packages gtkwave librsvg2-bin libxml2-utils
# The data exchange (docs/exchange.md): libmodbus and libmosquitto, and the real peers its tests
# start on localhost: mbpoll, pymodbus (with python3-serial-asyncio, which pymodbus's server needs
# and only recommends), the mosquitto broker and its clients.
iecoop_require_packages pkg-config libmodbus-dev libmosquitto-dev mosquitto mosquitto-clients mbpoll python3-pymodbus \
  python3-serial-asyncio
# gcovr: iecoop_coverage()'s reports (docs/testing.md, "Coverage"; test consumer.coverage).
iecoop_require_packages gcovr
for tool in gcovr arm-none-eabi-gcc arm-none-eabi-g++ qemu-system-arm vcd2fst fst2vcd rsvg-convert xmllint mbpoll mosquitto_sub; do
  command -v "$tool" >/dev/null 2>&1 || { echo "iecoop: $tool is missing: the tests that need it cannot run" >&2; exit 1; }
done

# The layout of the code (.clang-format), checked first: it takes seconds.
echo "== iecoop: layout (clang-format-16)"
sh tools/format.sh --check

jobs=$(iecoop_jobs)

# Each stage ends with the minutes and seconds since the start (CI's budget is 20 minutes).
elapsed() {
  seconds=$(($(date +%s) - started))
  echo "== iecoop: $1 done, $((seconds / 60)) min $((seconds % 60)) s since the start"
}

# run <name> <compiler> "<ctest options>" <cmake options>...
run() {
  name=$1
  compiler=$2
  ctest_options=$3
  shift 3
  echo "== iecoop: $name"
  cmake -S . -B "build/$name" -DCMAKE_CXX_COMPILER="$compiler" -DIECOOP_WERROR=ON -DIECOOP_BUILD_CHECK=ON \
    -DIECOOP_BUILD_TESTS=ON -DIECOOP_BUILD_EXAMPLES=ON -DIECOOP_BUILD_BENCH=ON -DIECOOP_BUILD_TOOLS=ON "$@"
  cmake --build "build/$name" -j "$jobs"
  elapsed "$name build"
  # The options are words (split, never expanded as file names: set -f).
  set -f
  # shellcheck disable=SC2086
  ctest --test-dir "build/$name" -j "$jobs" --output-on-failure $ctest_options
  set +f
  elapsed "$name tests"
}

# A firmware build: the toolchain, flags and board come from the preset (CMakePresets.json).
firmware() {
  echo "== iecoop: $1 firmware under QEMU"
  cmake --preset "$1"
  cmake --build --preset "$1" -j "$jobs"
  ctest --preset "$1" -j "$jobs"
  elapsed "$1 firmware"
}

# The sanitizers run with clang at -O0 (-g1: line tables for the reports, without the full debug
# information): AddressSanitizer and UndefinedBehaviorSanitizer check the same at every level,
# Clang warns the same at every level, and -O1 takes twice as long to compile; the optimiser's
# part is the g++ build's (-O3: GCC warns of some things only when it optimises). The examples
# are checked with iecoop-check by the g++ build, which also runs iecoop-check's own tests
# (label check): under AddressSanitizer each libclang parse takes two to three times as long.
# The benchmarks (and their cross-check test) are built by the g++ build only: their figures
# mean something only without the sanitizers. So are the header checks (each public header
# compiled on its own, without exceptions and RTTI): whether a header includes what it uses does
# not depend on the compiler, and the clang build compiles every header through the tests.
# Each compile-fail check runs with both compilers (both must reject the misuse, with the
# message); its compiling twin runs in the clang build only (Clang checks it in two thirds of
# GCC's time, and the same correct code compiles with g++ throughout the tests and examples).
# The data exchange's tests against real peers (label exchange) run in the clang build (ASan and
# UBSan) and again under ThreadSanitizer (the exchange-tsan stage below), not in the g++ build,
# which compiles the exchange's headers in its header checks and its benchmarks.
# valgrind's memcheck runs in the g++ build (IECOOP_VALGRIND_TESTS=ON: the initial-values
# program, tests initial_values.memcheck*): valgrind does not run the clang build's sanitized
# programs.
# The clang build runs the unit tests in 6 slices, each one process (IECOOP_UNIT_TEST_SHARDS):
# a sanitized process start costs more than most test cases; the g++ build runs each case alone.
run clang-sanitize clang++ "-LE ^check$" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O0 -g1 -DNDEBUG" \
  "-DIECOOP_SANITIZE=address;undefined" -DIECOOP_CHECK_EXAMPLES=OFF -DIECOOP_BUILD_FUZZ=ON -DIECOOP_FUZZ_SECONDS=5 \
  -DIECOOP_BUILD_BENCH=OFF -DIECOOP_HEADER_CHECKS=OFF -DIECOOP_CONSUMER_TESTS=OFF -DIECOOP_UNIT_TEST_SHARDS=6 \
  -DIECOOP_EXCHANGE_TESTS=ON
run gcc-release g++ "-E ^compile_fail\\..*\\.twin$" -DCMAKE_BUILD_TYPE=Release -DIECOOP_EXCHANGE_TESTS=OFF \
  -DIECOOP_VALGRIND_TESTS=ON
# The data exchange under ThreadSanitizer: its network threads and the task cycles meet through
# lock-free buffers, which AddressSanitizer does not check. Only what its tests need is built
# (the tests, the MQTT child, the demo); libmosquitto's own mutexes take turns in an order TSan
# reports as a possible deadlock (inside the bridge's one thread, so none): detect_deadlocks=0.
echo "== iecoop: exchange-tsan"
cmake -S . -B build/exchange-tsan -DCMAKE_CXX_COMPILER=clang++ -DIECOOP_WERROR=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DIECOOP_SANITIZE=thread -DIECOOP_BUILD_TESTS=ON \
  -DIECOOP_BUILD_EXAMPLES=ON -DIECOOP_BUILD_BENCH=OFF -DIECOOP_BUILD_TOOLS=OFF -DIECOOP_BUILD_CHECK=OFF \
  -DIECOOP_HEADER_CHECKS=OFF -DIECOOP_CONSUMER_TESTS=OFF -DIECOOP_EXCHANGE_TESTS=ON
cmake --build build/exchange-tsan -j "$jobs" --target iecoop_exchange_tests
TSAN_OPTIONS="halt_on_error=1 detect_deadlocks=0" ctest --test-dir build/exchange-tsan -j "$jobs" --output-on-failure -L exchange
elapsed "exchange-tsan tests"

for core in cortex-m0plus cortex-m3 cortex-m4f cortex-m7 cortex-m33 cortex-m55; do
  firmware "$core"
done
echo "== iecoop: all tests passed"
