// The controllers of the CODESYS Util library (PID, PID_FIXCYCLE, PD) in closed loop with a
// first-order-plus-dead-time plant, K e^(-theta s) / (tau s + 1), in simulated time: a step of
// the set point, a set point change, a disturbance at the plant's input, and saturation with the
// anti-windup. Prints each scenario's parameters and, sample by sample, ACTUAL (the plant's
// output, as the controller read it) and Y; tests/util/pid_scipy.py simulates the same loops
// independently (the plant discretised by scipy, the controller from docs/util.md's steps) and
// requires both to agree sample by sample.
//
// The plant is the zero-order-hold discretisation at the sample time T: y[k+1] = a y[k] +
// b u[k - d], a = exp(-T / tau), b = K (1 - a), d = the dead time in samples, in LREAL.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <iecoop/iecoop.hpp>

using namespace iecoop;

namespace {

struct scenario {
  const char* name;
  const char* block;  // "PID", "PID_FIXCYCLE" or "PD"
  int cycle_ms;
  int samples;
  double gain;  // K
  double tau;   // s
  int delay;    // samples
  float kp, tn, tv, y_offset, y_min, y_max;
  int change_at;  // the sample where the set point becomes set_point_2
  float set_point_1, set_point_2;
  int disturbance_at;  // the sample where the disturbance is added to the plant's input
  double disturbance;
  int manual_from, manual_to;  // MANUAL TRUE in [from, to)
  float y_manual;
};

// Each controller block behind one call signature.
template <class Block>
float call(Block& block, const scenario& s, float actual, float set_point, bool manual) {
  if constexpr (std::is_same_v<Block, PD>) {
    block("ACTUAL"_ = REAL(actual), "SET_POINT"_ = REAL(set_point), "KP"_ = REAL(s.kp), "TV"_ = REAL(s.tv),
          "Y_MANUAL"_ = REAL(s.y_manual), "Y_OFFSET"_ = REAL(s.y_offset), "Y_MIN"_ = REAL(s.y_min),
          "Y_MAX"_ = REAL(s.y_max), "MANUAL"_ = BOOL(manual));
  } else if constexpr (std::is_same_v<Block, PID>) {
    block("ACTUAL"_ = REAL(actual), "SET_POINT"_ = REAL(set_point), "KP"_ = REAL(s.kp), "TN"_ = REAL(s.tn),
          "TV"_ = REAL(s.tv), "Y_MANUAL"_ = REAL(s.y_manual), "Y_OFFSET"_ = REAL(s.y_offset), "Y_MIN"_ = REAL(s.y_min),
          "Y_MAX"_ = REAL(s.y_max), "MANUAL"_ = BOOL(manual));
  } else {
    block("ACTUAL"_ = REAL(actual), "SET_POINT"_ = REAL(set_point), "KP"_ = REAL(s.kp), "TN"_ = REAL(s.tn),
          "TV"_ = REAL(s.tv), "Y_MANUAL"_ = REAL(s.y_manual), "Y_OFFSET"_ = REAL(s.y_offset), "Y_MIN"_ = REAL(s.y_min),
          "Y_MAX"_ = REAL(s.y_max), "MANUAL"_ = BOOL(manual),
          "CYCLE"_ = REAL(static_cast<float>(s.cycle_ms) / 1000.0F));
  }
  return block.Y.get().value();
}

template <class Block>
void run(const scenario& s) {
  std::printf(
      "scenario %s block=%s cycle_ms=%d samples=%d K=%.17g tau=%.17g delay=%d KP=%.9g TN=%.9g TV=%.9g "
      "Y_OFFSET=%.9g Y_MIN=%.9g Y_MAX=%.9g change_at=%d SP1=%.9g SP2=%.9g disturbance_at=%d "
      "disturbance=%.17g manual_from=%d manual_to=%d Y_MANUAL=%.9g\n",
      s.name, s.block, s.cycle_ms, s.samples, s.gain, s.tau, s.delay, static_cast<double>(s.kp),
      static_cast<double>(s.tn), static_cast<double>(s.tv), static_cast<double>(s.y_offset),
      static_cast<double>(s.y_min), static_cast<double>(s.y_max), s.change_at, static_cast<double>(s.set_point_1),
      static_cast<double>(s.set_point_2), s.disturbance_at, s.disturbance, s.manual_from, s.manual_to,
      static_cast<double>(s.y_manual));
  const double t = s.cycle_ms / 1000.0;
  const double a = std::exp(-t / s.tau);
  const double b = s.gain * (1.0 - a);
  Block controller;
  double y = 0.0;
  std::vector<double> inputs;  // u[k], for the dead time
  for (int k = 0; k < s.samples; ++k) {
    cycle_clock::set(
        LTIME::from_ticks(static_cast<std::uint64_t>(k) * static_cast<std::uint64_t>(s.cycle_ms) * 1'000'000U));
    const float actual = static_cast<float>(y);
    const float set_point = k < s.change_at ? s.set_point_1 : s.set_point_2;
    const bool manual = k >= s.manual_from && k < s.manual_to;
    const float u = call(controller, s, actual, set_point, manual);
    std::printf("%d %.9g %.9g\n", k, static_cast<double>(actual), static_cast<double>(u));
    inputs.push_back(static_cast<double>(u) + (k >= s.disturbance_at ? s.disturbance : 0.0));
    const double delayed = k >= s.delay ? inputs[static_cast<std::size_t>(k - s.delay)] : 0.0;
    y = a * y + b * delayed;
  }
  std::printf("end\n");
}

}  // namespace

int main() {
  constexpr int never = 1 << 30;
  // name, block, cycle, samples, K, tau, delay, KP, TN, TV, Y_OFFSET, Y_MIN, Y_MAX, change at, SP1, SP2,
  // disturbance at, disturbance, manual from, to, Y_MANUAL
  const scenario step{"step", "PID", 10,    1500, 2.0,  1.5,   20,  1.2F,  2.0F,  0.1F, 0.0F,
                      0.0F,   0.0F,  never, 1.0F, 1.0F, never, 0.0, never, never, 0.0F};
  const scenario change{"setpoint_change",
                        "PID",
                        7,
                        2500,
                        2.0,
                        1.5,
                        30,
                        1.0F,
                        1.5F,
                        0.05F,
                        0.0F,
                        0.0F,
                        0.0F,
                        1200,
                        1.0F,
                        3.0F,
                        never,
                        0.0,
                        never,
                        never,
                        0.0F};
  const scenario disturbance{"disturbance", "PID", 10,    1600, 2.0,  1.5, 20,   1.2F,  2.0F,  0.1F, 0.0F,
                             0.0F,          0.0F,  never, 1.0F, 1.0F, 700, -0.5, never, never, 0.0F};
  const scenario saturation{"saturation", "PID", 10,    1500, 2.0,  1.5, 20,   3.0F,  1.0F,  0.1F, 0.0F,
                            0.0F,         1.2F,  never, 2.0F, 2.0F, 900, -0.4, never, never, 0.0F};
  const scenario manual{"manual", "PID", 1,    6000, 2.0,  1.5,   200, 1.2F, 2.0F, 0.1F, 0.2F,
                        -5.0F,    5.0F,  3500, 1.0F, 2.0F, never, 0.0, 1000, 2500, 0.8F};
  const scenario fixcycle{"fixcycle", "PID_FIXCYCLE", 5,    3000, 2.0,  1.5,  40,  1.2F,  2.0F,  0.1F, 0.0F,
                          -1.0F,      2.0F,           1500, 1.0F, 2.5F, 2200, 0.3, never, never, 0.0F};
  const scenario pd{"pd", "PD", 10,  1000, 2.0,  1.5,   20,  1.5F,  0.0F,  0.2F, 0.5F,
                    0.0F, 0.0F, 500, 1.0F, 2.0F, never, 0.0, never, never, 0.0F};
  run<PID>(step);
  run<PID>(change);
  run<PID>(disturbance);
  run<PID>(saturation);
  run<PID>(manual);
  run<PID_FIXCYCLE>(fixcycle);
  run<PD>(pd);
  return 0;
}
