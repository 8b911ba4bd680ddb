#!/usr/bin/env python3
"""The closed loops of tests/util/pid_loop.cpp, simulated independently, compared sample by sample.

usage: pid_scipy.py <pid_loop executable>

The plant, K e^(-theta s) / (tau s + 1), is discretised by scipy (scipy.signal.cont2discrete,
zero-order hold at the sample time), its dead time a delay of whole samples. The controller is
docs/util.md's "Controllers" steps in REAL (IEEE single precision, numpy.float32), operation by
operation — written here from the documentation, not from the C++. Every sample's ACTUAL and Y
must agree to 1e-6 relative (relative to the larger of the two values and 1.0, so that values
near zero compare absolutely). Exit status 0 when every scenario agrees, 1 otherwise.
"""
import subprocess
import sys

try:
    import numpy as np
    from scipy import signal
except ImportError as error:  # CI installs python3-scipy (tools/test.sh): a missing one is a failure
    print(f"iecoop: the PID comparison needs python3-scipy ({error}); apt-get install python3-scipy")
    sys.exit(1)

F = np.float32
TOLERANCE = 1e-6
INTEGRAL_LIMIT = F(1e38)


class FourPointSlope:
    """DERIVATIVE's slope through the last four values."""

    def __init__(self):
        self.x1 = self.x2 = self.x3 = F(0)

    def reset(self, value):
        self.x1 = self.x2 = self.x3 = value

    def next(self, value, dt):
        difference = value - self.x3
        weighted = F(3) * difference
        total = weighted + self.x1
        numerator = total - self.x2
        denominator = F(10) * dt
        self.x3, self.x2, self.x1 = self.x2, self.x1, value
        return numerator / denominator


class Controller:
    """PD (integral False), PID and PID_FIXCYCLE (integral True), per docs/util.md."""

    def __init__(self, integral):
        self.has_integral = integral
        self.slope = FourPointSlope()
        self.integral = F(0)
        self.kp = self.tn = self.tv = F(0)
        self.started = False
        self.y = F(0)
        self.limits_active = False
        self.overflow = False

    def call(self, p, actual, set_point, manual, reset, dt):
        e = set_point - actual
        if not self.started or reset:
            self.started = True
            self.kp, self.tn, self.tv = p["KP"], p["TN"], p["TV"]
            self.integral = F(0)
            self.overflow = False
            self.slope.reset(e)
            self.y = p["Y_OFFSET"]
            self.limits_active = False
            return False  # the interval starts now
        if manual:
            self.kp, self.tn, self.tv = p["KP"], p["TN"], p["TV"]
            self.y = p["Y_MANUAL"]
            self.limits_active = False
            self.slope.reset(e)
            if self.has_integral and self.kp != 0 and self.tn != 0:
                a = p["Y_MANUAL"] - p["Y_OFFSET"]
                a = a / self.kp
                a = a - e
                self.set_integral(a * self.tn)
            return False
        if self.overflow or not dt > 0:
            return True
        if self.has_integral:
            total = self.integral + e * dt
            if not (-INTEGRAL_LIMIT <= total <= INTEGRAL_LIMIT):
                self.overflow = True
                return True
            self.integral = total
        d = self.slope.next(e, dt)
        d_part = self.tv * d
        s = e
        if self.has_integral and self.tn != 0:
            s = s + self.integral / self.tn
        s = s + d_part
        y = self.kp * s
        y = y + p["Y_OFFSET"]
        limited = False
        if p["Y_MIN"] < p["Y_MAX"]:
            if y > p["Y_MAX"]:
                y, limited = p["Y_MAX"], True
            elif y < p["Y_MIN"]:
                y, limited = p["Y_MIN"], True
        if self.has_integral and limited and self.kp != 0 and self.tn != 0:
            a = y - p["Y_OFFSET"]
            a = a / self.kp
            a = a - e
            a = a - d_part
            self.set_integral(a * self.tn)
        self.y = y
        self.limits_active = limited
        return True

    def set_integral(self, value):
        if -INTEGRAL_LIMIT <= value <= INTEGRAL_LIMIT:
            self.integral = value
        else:
            self.overflow = True


def parse(output):
    """The scenarios: their parameters and their (k, ACTUAL, Y) rows."""
    scenarios = []
    for line in output.splitlines():
        words = line.split()
        if not words:
            continue
        if words[0] == "scenario":
            params = dict(w.split("=", 1) for w in words[2:])
            scenarios.append({"name": words[1], "params": params, "rows": []})
        elif words[0] != "end":
            scenarios[-1]["rows"].append((int(words[0]), float(words[1]), float(words[2])))
    return scenarios


def simulate(raw):
    """ACTUAL and Y of every sample, as the documented loop gives them."""
    real = {k: F(float(raw[k])) for k in ("KP", "TN", "TV", "Y_OFFSET", "Y_MIN", "Y_MAX", "SP1", "SP2", "Y_MANUAL")}
    cycle_ms, samples, delay = int(raw["cycle_ms"]), int(raw["samples"]), int(raw["delay"])
    gain, tau = float(raw["K"]), float(raw["tau"])
    change_at, disturbance_at = int(raw["change_at"]), int(raw["disturbance_at"])
    disturbance = float(raw["disturbance"])
    manual_from, manual_to = int(raw["manual_from"]), int(raw["manual_to"])
    sample_time = cycle_ms / 1000.0
    numerator, denominator, _ = signal.cont2discrete(([gain], [tau, 1.0]), sample_time, method="zoh")
    numerator = np.asarray(numerator, dtype=float).ravel()
    a, b = -float(denominator[1]), float(numerator[-1])
    block = raw["block"]
    controller = Controller(integral=block != "PD")
    # PID and PD measure the interval on the cycle clock in whole ms; PID_FIXCYCLE is told CYCLE.
    dt = F(cycle_ms) / F(1000) if block != "PID_FIXCYCLE" else F(float(cycle_ms) / 1000.0)
    y, inputs, rows = 0.0, [], []
    for k in range(samples):
        actual = F(y)
        set_point = real["SP1"] if k < change_at else real["SP2"]
        manual = manual_from <= k < manual_to
        controller.call(real, actual, set_point, manual, False, dt)
        u = controller.y
        rows.append((k, float(actual), float(u)))
        inputs.append(float(u) + (disturbance if k >= disturbance_at else 0.0))
        delayed = inputs[k - delay] if k >= delay else 0.0
        y = a * y + b * delayed
    return rows


def differs(mine, theirs):
    return abs(mine - theirs) > TOLERANCE * max(1.0, abs(mine), abs(theirs))


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    output = subprocess.run([sys.argv[1]], check=True, capture_output=True, text=True, timeout=120).stdout
    scenarios = parse(output)
    if len(scenarios) < 7:
        print(f"iecoop: expected 7 scenarios from {sys.argv[1]}, got {len(scenarios)}")
        return 1
    failed = False
    for s in scenarios:
        expected = simulate(s["params"])
        rows = s["rows"]
        if len(rows) != len(expected):
            print(f"{s['name']}: {len(rows)} samples, expected {len(expected)}")
            failed = True
            continue
        worst = 0.0
        first_difference = None
        for (k, actual, y), (_, actual_ref, y_ref) in zip(rows, expected):
            for what, mine, theirs in (("ACTUAL", actual, actual_ref), ("Y", y, y_ref)):
                worst = max(worst, abs(mine - theirs) / max(1.0, abs(mine), abs(theirs)))
                if first_difference is None and differs(mine, theirs):
                    first_difference = f"sample {k}: {what} {mine!r} from iecoop, {theirs!r} from the model"
        if first_difference is not None:
            print(f"{s['name']}: {first_difference}")
            failed = True
        print(f"{s['name']} ({s['params']['block']}, {s['params']['cycle_ms']} ms, {len(rows)} samples): "
              f"largest relative difference {worst:.2e}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
