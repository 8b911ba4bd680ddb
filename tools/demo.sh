#!/bin/sh
# Builds and runs the iecoop demo (Release). Arguments are passed to the demo.
# Installs the Debian packages it needs first. Builds with CMAKE_BUILD_PARALLEL_LEVEL jobs where
# it is set, else one per core.
set -eu
cd "$(dirname "$0")/.."
. tools/require_packages.sh
iecoop_require_packages cmake make g++ libfmt-dev
# pkg-config, libmodbus and libmosquitto: the demo's --modbus PORT and --mqtt HOST (docs/exchange.md).
iecoop_require_packages pkg-config libmodbus-dev libmosquitto-dev

cmake -S . -B build/demo -DCMAKE_BUILD_TYPE=Release -DIECOOP_BUILD_EXAMPLES=ON -DIECOOP_BUILD_TESTS=OFF -DIECOOP_BUILD_BENCH=OFF >/dev/null
cmake --build build/demo --target iecoop_demo -j "$(iecoop_jobs)" >/dev/null
exec ./build/demo/examples/iecoop_demo "$@"
