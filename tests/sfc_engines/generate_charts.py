#!/usr/bin/env python3
"""Random SFC charts for the engines' differential test (tests/sfc_engines/engines_harness.hpp).

    python3 generate_charts.py --seed S --count N [--first K] [--scans M] --out batch.cpp

Writes N function blocks, each holding one random chart, a template on the scan order and on
the engine (sfc::general_engine or none): a main sequence that loops back, with alternative
and simultaneous divergences of short branches, extra jumps back (some out of a branch: such a
chart may be unsafe), conditions on inputs and step times, every qualifier (N, S, R, P, P1, P0,
L, D, SD, DS, SL) on ACTIONs and BOOL variables, CODESYS step actions, minimum and maximum
times. Action bodies read each other's counters, so that the order the actions run in shows in
the values. Each block also writes what it observes after a scan (observe()) and lists itself
in a doctest case that runs each chart on both engines in both scan orders for M scans. The
same seed gives the same file.
"""
import argparse
import os
import random

QUALIFIERS = ["N"] * 6 + ["S", "R", "P", "P1", "P0", "L", "D", "SD", "DS", "SL"]
TIMED = {"L", "D", "SD", "DS", "SL"}


class Chart:
    def __init__(self, rng, index):
        self.rng = rng
        self.name = f"FB_RC{index}"
        self.steps = []        # names
        self.items = {}        # step -> list of item strings
        self.transitions = []  # (from list, to list, condition string, priority or None)
        self.conditions = []   # member functions: (name, body)
        self.actions = []      # ACTION names
        self.bools = ["V0", "V1", "V2"]
        self.used_actions = set()
        self.step_actions = []  # method names of step actions
        self.main = []

    def new_step(self):
        s = f"S{len(self.steps)}"
        self.steps.append(s)
        self.items[s] = []
        return s

    def condition(self, sources):
        r = self.rng
        kind = r.random()
        if kind < 0.08:
            return "true"
        if kind < 0.45:
            return f"&P::I{r.randrange(6)}"
        name = f"C{len(self.conditions)}"
        step = r.choice(sources)
        ms = r.choice([0, 10, 20, 30, 50, 80])
        parts = []
        if r.random() < 0.7:
            parts.append(("!" if r.random() < 0.3 else "") + f"I{r.randrange(6)}")
        parts.append(f"{step}.T >= \"T#{ms}ms\"_iec")
        if r.random() < 0.2:
            parts.append(f"N{r.randrange(4)} % 3 != 1")
        op = " && " if r.random() < 0.7 else " || "
        self.conditions.append((name, op.join(parts)))
        return f"&P::{name}"

    def link(self, sources, targets, priority=None):
        self.transitions.append((sources, targets, self.condition(sources), priority))

    def chain(self, n):
        steps = [self.new_step() for _ in range(n)]
        for a, b in zip(steps, steps[1:]):
            self.link([a], [b])
        return steps

    def build(self):
        r = self.rng
        length = r.randint(2, 5)
        self.main = [self.new_step() for _ in range(length)]
        for i, m in enumerate(self.main):
            nxt = self.main[(i + 1) % length]
            if i == length - 1:
                # back to the start, or to another main step
                self.link([m], [r.choice(self.main[: max(1, length - 1)])])
                continue
            kind = r.random()
            if kind < 0.25:  # alternative divergence
                k = r.randint(2, 3)
                prios = [None] * k if r.random() < 0.5 else [r.randint(0, 3) for _ in range(k)]
                for b in range(k):
                    branch = self.chain(r.randint(1, 2))
                    self.link([m], [branch[0]], prios[b])
                    self.link([branch[-1]], [nxt])
            elif kind < 0.5:  # simultaneous divergence
                k = r.randint(2, 3)
                branches = [self.chain(r.randint(1, 3)) for _ in range(k)]
                self.link([m], [b[0] for b in branches])
                self.link([b[-1] for b in branches], [nxt])
            else:
                self.link([m], [nxt])
        # extra jumps back: from a main step mostly, now and then out of a branch (unsafe charts)
        for _ in range(r.randint(0, 2)):
            src = r.choice(self.main) if r.random() < 0.8 else r.choice(self.steps)
            self.link([src], [r.choice(self.main)], r.choice([None, 0, 1, 5]))
        # actions
        n_actions = r.randint(2, 6)
        self.actions = [f"A{k}" for k in range(n_actions)]
        for s in self.steps:
            for _ in range(r.choice([0, 1, 1, 2, 2, 3])):
                q = r.choice(QUALIFIERS)
                target = r.choice(self.actions + self.bools)
                ref = f"&P::{target}"
                self.used_actions.add(target)
                if q in TIMED:
                    self.items[s].append(f"sfc::{q}<{ref}, \"T#{r.choice([10, 20, 30, 40, 60])}ms\">")
                else:
                    self.items[s].append(f"sfc::{q}<{ref}>")
            if r.random() < 0.15:
                kind = r.choice(["on_entry", "while_active", "on_exit"])
                name = f"E{len(self.step_actions)}"
                self.step_actions.append(name)
                self.items[s].append(f"sfc::{kind}<&P::{name}>")
            if r.random() < 0.1:
                self.items[s].append(f"sfc::min_time<\"T#{r.choice([10, 20, 40])}ms\">")
            if r.random() < 0.1:
                self.items[s].append(f"sfc::max_time<\"T#{r.choice([20, 50, 100])}ms\">")

    def write(self, out):
        w = out.append
        w(f"// {self.name}: {len(self.steps)} steps, {len(self.transitions)} transitions")
        w("template <class Order, class... Engine>")
        w(f"struct {self.name} : function_block<{self.name}<Order, Engine...>> {{")
        w("  BOOL I0, I1, I2, I3, I4, I5;")
        w("  BOOL V0, V1, V2;")
        w("  DINT N0, N1, N2, N3, N4, N5, NE;")
        w("  sfc::step " + ", ".join(self.steps) + ";")
        for k, a in enumerate(self.actions):
            other = f"N{(k + 1) % len(self.actions)}"
            w(f"  void {a}() {{ N{k} = N{k} * 3 + {other} + {k + 1}; }}")
        for k, e in enumerate(self.step_actions):
            w(f"  void {e}() {{ NE = NE * 5 + N0 + {k + 1}; }}")
        for name, body in self.conditions:
            w(f"  BOOL {name}() {{ return {body}; }}")
        w(f"  using P = {self.name};")
        w("  sfc::chart<P, Order, Engine...,")
        elems = []
        for s in self.steps:
            kind = "INITIAL_STEP" if s == self.steps[0] else "STEP"
            items = "".join(", " + it for it in self.items[s])
            elems.append(f"      sfc::{kind}<&P::{s}{items}>")
        for src, dst, cond, prio in self.transitions:
            f = ", ".join(f"&P::{x}" for x in src)
            t = ", ".join(f"&P::{x}" for x in dst)
            p = f", sfc::PRIORITY<{prio}>" if prio is not None else ""
            elems.append(f"      sfc::TRANSITION<sfc::FROM<{f}>, sfc::TO<{t}>, {cond}{p}>")
        w(",\n".join(elems) + ">")
        w("      chart;")
        w("  void body() { chart(*this); }")
        w("  void set_inputs(const bool (&in)[6]) {")
        w("    I0 = in[0]; I1 = in[1]; I2 = in[2]; I3 = in[3]; I4 = in[4]; I5 = in[5];")
        w("  }")
        w("  void observe(observation& o) const {")
        for s in self.steps:
            w(f"    o.step(\"{s}\", {s});")
        for a in sorted(self.used_actions):
            w(f"    o.action(\"{a}\", chart.template action<&P::{a}>());")
        w("    o.value(\"N\", {N0, N1, N2, N3, N4, N5, NE});")
        w("    o.flags(V0, V1, V2);")
        w("    o.chart(chart);")
        w("  }")
        w("};")
        w("")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--count", type=int, required=True)
    parser.add_argument("--first", type=int, default=0, help="number of the first chart")
    parser.add_argument("--scans", type=int, default=3000, help="scans per chart and order")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    out = [
        f"// Generated by tests/sfc_engines/generate_charts.py --seed {args.seed} --count {args.count}"
        f" --first {args.first} --scans {args.scans}: do not edit.",
        '#include "engines_harness.hpp"',
        "",
        "namespace sfc_engines {",
        "",
    ]
    names = []
    for i in range(args.first, args.first + args.count):
        rng = random.Random(args.seed * 1_000_003 + i)
        chart = Chart(rng, i)
        chart.build()
        chart.write(out)
        names.append(chart.name)
    out.append("}  // namespace sfc_engines")
    out.append("")
    last = args.first + args.count - 1
    out.append(f'TEST_CASE("random charts {args.first} to {last} (seed {args.seed}): both engines agree after every scan") {{')
    out.append("  sfc_engines::batch b;")
    for n in names:
        out.append(f'  b.run<sfc_engines::{n}>("{n}", {args.seed}, {args.scans});')
    out.append("  b.report();")
    out.append("}")
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
