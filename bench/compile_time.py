#!/usr/bin/env python3
"""Compile time of iecoop in a user's translation unit (docs/performance.md, "Compile time").

Measures, for g++ and clang++ (and clang++-16 where installed):
  - stl:      a translation unit of a typical C++ program's standard headers, the baseline;
  - umbrella: one that includes only <iecoop/iecoop.hpp>, at -O0 (a PLC engineer's edit loop);
  - each public header alone, at -O0 (what a user of one layer pays);
  - the demo's five translation units and each feature example, at -O2.
Each figure is the median of --runs compilations (the compilers and the files take turns, so a
busy moment of a shared machine spreads over all of them), with the spread (min..max). Prints a
Markdown table and the machine's CPU; `--only umbrella` (or stl, headers, examples) for a part,
`--only demo` for the STL baseline, the umbrella and the demo's translation units side by side.

    python3 bench/compile_time.py [--runs 5] [--only umbrella] [--compilers g++ clang++]
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STL_HEADERS = ["algorithm", "array", "chrono", "cstdint", "functional", "iostream", "map", "memory", "string",
               "vector"]


def cpu_name():
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True, check=True).stdout
        for line in out.splitlines():
            if line.startswith("Model name:"):
                return line.split(":", 1)[1].strip()
    except (OSError, subprocess.CalledProcessError):
        pass
    return "unknown CPU"


def public_headers():
    base = os.path.join(ROOT, "include")
    found = []
    for folder, _, files in os.walk(os.path.join(base, "iecoop")):
        for name in files:
            path = os.path.relpath(os.path.join(folder, name), base)
            if name.endswith(".hpp") and "/detail/" not in path and "/exchange/" not in path:
                found.append(path)
    return sorted(found)


def cases(only, scratch):
    """(name, source file, optimisation, extra flags) of every translation unit measured."""
    result = []
    if only in (None, "stl", "umbrella", "demo"):
        stl = os.path.join(scratch, "stl.cpp")
        with open(stl, "w") as f:
            f.write("".join(f"#include <{h}>\n" for h in STL_HEADERS) + "int main() {}\n")
        result.append(("STL baseline (" + ", ".join(STL_HEADERS) + ")", stl, "-O0", []))
    if only in (None, "umbrella", "demo"):
        umbrella = os.path.join(scratch, "umbrella.cpp")
        with open(umbrella, "w") as f:
            f.write("#include <iecoop/iecoop.hpp>\nint main() {}\n")
        result.append(("<iecoop/iecoop.hpp>", umbrella, "-O0", []))
    if only in (None, "headers"):
        for header in public_headers():
            if header.startswith("iecoop/testing") or header in ("iecoop/fmt.hpp", "iecoop/iecoop.hpp"):
                continue  # need doctest or fmt (measured through the examples), or measured above
            source = os.path.join(scratch, header.replace("/", "_") + ".cpp")
            with open(source, "w") as f:
                f.write(f"#include <{header}>\nint main() {{}}\n")
            result.append((f"<{header}>", source, "-O0", []))
    examples = os.path.join(ROOT, "examples")
    if only in (None, "examples", "demo"):
        # The demo's five translation units; its network part as CMake builds it where libmodbus
        # and libmosquitto are installed (else without them, and the table says so).
        for name in ("demo.cpp", "demo_print.cpp", "demo_realtime.cpp", "demo_trace.cpp"):
            result.append((f"examples/{name}", os.path.join(examples, name), "-O2", []))
        network = exchange_flags()
        label = "examples/demo_exchange.cpp" + ("" if network else " (without libmodbus, libmosquitto)")
        result.append((label, os.path.join(examples, "demo_exchange.cpp"), "-O2", network))
    if only in (None, "examples"):
        features = os.path.join(examples, "features")
        for name in sorted(os.listdir(features)):
            if name.endswith(".cpp"):
                result.append((f"examples/features/{name}", os.path.join(features, name), "-O2", []))
    return result


def exchange_flags():
    """-D and -I flags of the demo's Modbus server and MQTT bridge, or [] where pkg-config does
    not find libmodbus and libmosquitto."""
    try:
        done = subprocess.run(["pkg-config", "--cflags", "libmodbus", "libmosquitto"], capture_output=True, text=True)
    except OSError:
        return []
    if done.returncode != 0:
        return []
    return ["-DIECOOP_DEMO_MODBUS=1", "-DIECOOP_DEMO_MQTT=1"] + done.stdout.split()


def compile_once(compiler, source, optimisation, extra, scratch):
    command = [compiler, "-std=c++20", optimisation, "-I" + os.path.join(ROOT, "include"),
               "-I" + os.path.join(ROOT, "examples"), "-c", source, "-o", os.path.join(scratch, "out.o")] + extra
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"compile_time: {' '.join(command)} failed:\n{done.stderr[:2000]}")
    return seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--only", choices=["stl", "umbrella", "headers", "examples", "demo"])
    parser.add_argument("--compilers", nargs="+")
    options = parser.parse_args()
    compilers = options.compilers or [c for c in ("g++", "clang++", "clang++-16") if shutil.which(c)]
    with tempfile.TemporaryDirectory() as scratch:
        measured = cases(options.only, scratch)
        times = {(name, c): [] for name, *_ in measured for c in compilers}
        for run in range(options.runs):
            for name, source, optimisation, extra in measured:
                for compiler in compilers:
                    times[(name, compiler)].append(compile_once(compiler, source, optimisation, extra, scratch))
            print(f"compile_time: run {run + 1} of {options.runs} done", file=sys.stderr)
    versions = {c: subprocess.run([c, "--version"], capture_output=True, text=True).stdout.splitlines()[0]
                for c in compilers}
    print(f"CPU: {cpu_name()}, {os.cpu_count()} cores; median of {options.runs} runs (min..max), seconds")
    for c in compilers:
        print(f"- {c}: {versions[c]}")
    print()
    print("| translation unit | flags | " + " | ".join(compilers) + " |")
    print("|---|---|" + "---|" * len(compilers))
    for name, _, optimisation, _ in measured:
        cells = []
        for c in compilers:
            t = times[(name, c)]
            cells.append(f"{statistics.median(t):.2f} ({min(t):.2f}..{max(t):.2f})")
        label = name if name.startswith("STL") else f"`{name}`"
        print(f"| {label} | {optimisation} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
