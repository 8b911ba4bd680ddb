#!/usr/bin/env python3
"""The deepest stack a firmware image can reach through direct calls, from GCC's call graphs.

    python3 embedded/stack_depth.py <file.ci>... [--root NAME]...

Each .ci file is what `-fcallgraph-info=su` writes beside an object (embedded/CMakeLists.txt
compiles iecoop's images so): every function of the translation unit with the bytes its frame
takes (-fstack-usage's figure) and the calls it makes. The script follows the calls from the
roots (default: main, and the exception handlers of startup.cpp, which may interrupt it), adds
up the frames along each chain and prints the deepest one:

    static stack: 424 bytes (main > ...), 3 indirect calls not followed

What it cannot see, it says: a call through a pointer (a virtual method, a task's program, a
function table) is not followed, so where there are some the figure is a lower bound, and the
measured high-water mark (exit_status.hpp) is the other half of the picture; a function of a
library (newlib's memcpy, libgcc's division) has no frame in the graph and counts as 0; a frame
of dynamic size, or a recursion, is reported as such.
"""
import re
import sys

NODE = re.compile(r'^node: \{ title: "([^"]*)" label: "(.*?)"(?: shape : \w+)? \}$')
EDGE = re.compile(r'^edge: \{ sourcename: "([^"]*)" targetname: "([^"]*)"')
BYTES = re.compile(r'\\n(\d+) bytes \((static|dynamic|dynamic,bounded)\)$')


def main(argv):
    files = [a for a in argv if not a.startswith("--")]
    roots = []
    args = iter(argv)
    for a in args:
        if a == "--root":
            roots.append(next(args))
    files = [f for f in files if f not in roots]
    frames = {}  # symbol -> (bytes, kind)
    labels = {}  # symbol -> readable name
    calls = {}   # symbol -> [symbol]
    for path in files:
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                line = line.rstrip("\n")
                m = NODE.match(line)
                if m:
                    title, label = m.groups()
                    symbol = title.split(":")[-1]
                    b = BYTES.search(label)
                    if b:
                        frames[symbol] = (int(b.group(1)), b.group(2))
                    else:
                        frames.setdefault(symbol, (0, "external"))
                    labels.setdefault(symbol, label.split("\\n")[0])
                    continue
                m = EDGE.match(line)
                if m:
                    source = m.group(1).split(":")[-1]
                    target = m.group(2).split(":")[-1]
                    calls.setdefault(source, []).append(target)
    if not roots:
        roots = ["main"] + [s for s in frames if s.endswith("_Handler") or s == "iecoop_reset"]
    indirect = 0
    dynamic = []
    recursive = []
    memo = {}

    def depth(symbol, path):
        nonlocal indirect
        if symbol in memo:
            return memo[symbol]
        if symbol in path:
            recursive.append(symbol)
            return (0, [])
        own, kind = frames.get(symbol, (0, "external"))
        if kind.startswith("dynamic") and symbol not in dynamic:
            dynamic.append(symbol)
        best = (0, [])
        for callee in calls.get(symbol, []):
            if callee == "__indirect_call":
                indirect += 1
                continue
            d = depth(callee, path | {symbol})
            if d[0] > best[0]:
                best = d
        memo[symbol] = (own + best[0], [symbol] + best[1])
        return memo[symbol]

    deepest = (0, [])
    for root in roots:
        if root in frames or root in calls:
            d = depth(root, frozenset())
            if d[0] > deepest[0]:
                deepest = d
    chain = " > ".join(labels.get(s, s).split("(")[0].split(" ")[-1] for s in deepest[1])
    notes = []
    if indirect:
        notes.append(f"{indirect} indirect calls not followed")
    if dynamic:
        notes.append(f"{len(dynamic)} frames of dynamic size")
    if recursive:
        notes.append(f"recursion through {', '.join(sorted(set(recursive)))}")
    print(f"static stack: {deepest[0]} bytes ({chain})" + (", " + ", ".join(notes) if notes else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
