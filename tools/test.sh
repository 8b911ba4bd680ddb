#!/bin/sh
# Builds and runs iecoop's whole test suite, the way CI does:
#   1. g++ with AddressSanitizer and UndefinedBehaviorSanitizer (-O2),
#   2. clang++ (-O3),
# both with -Wall -Wextra -Wpedantic -Werror on iecoop's own code. Each build runs the unit
# tests, the compile-fail checks, the header self-containment and -fno-exceptions -fno-rtti
# checks, the examples and the consumer projects (find_package and add_subdirectory).
# Installs the Debian packages it needs first.
set -eu
cd "$(dirname "$0")/.."
. tools/require_packages.sh
iecoop_require_packages cmake make g++ clang doctest-dev libfmt-dev libbenchmark-dev

jobs=$(nproc 2>/dev/null || echo 2)

run() {
  name=$1
  compiler=$2
  shift 2
  echo "== iecoop: $name"
  cmake -S . -B "build/$name" -DCMAKE_CXX_COMPILER="$compiler" -DIECOOP_WERROR=ON "$@"
  cmake --build "build/$name" -j "$jobs"
  ctest --test-dir "build/$name" -j "$jobs" --output-on-failure
}

run gcc-sanitize g++ -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DIECOOP_SANITIZE=address;undefined"
run clang clang++ -DCMAKE_BUILD_TYPE=Release
echo "== iecoop: all tests passed"
