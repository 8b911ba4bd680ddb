// The differential test of the two SFC engines (docs/sfc.md, "How a chart is run"): each chart
// of generate_charts.py runs on the engine compiled from its states and on the general engine
// (sfc::general_engine), in both scan orders, with the same random inputs, cycle times and SFC
// flags, and after every scan everything a program can see of them must be the same: each
// step's X and T, each action's Q and A, the variables the actions write, the chart's flags and
// the faults reported.
#pragma once

#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "iecoop_test.hpp"

namespace sfc_engines {

using namespace iecoop;

/// What a chart's function block shows after a scan, as text (a difference names its place).
class observation {
 public:
  void step(const char* name, const sfc::step& s) {
    text_ += name;
    text_ += s.X ? ":1/" : ":0/";
    text_ += std::to_string(s.T.get().count());
    text_ += s.X_next() ? "+" : "-";
    text_ += ' ';
  }
  void action(const char* name, const sfc::action_state& a) {
    text_ += name;
    text_ += a.Q ? "=Q" : "=q";
    text_ += a.A ? "A " : "a ";
  }
  void value(const char* name, std::initializer_list<DINT> values) {
    text_ += name;
    for (const DINT v : values) {
      text_ += ' ';
      text_ += std::to_string(v.value());
    }
    text_ += ' ';
  }
  void flags(bool a, bool b, bool c) {
    text_ += a ? 'V' : 'v';
    text_ += b ? 'V' : 'v';
    text_ += c ? 'V' : 'v';
    text_ += ' ';
  }
  template <class Chart>
  void chart(const Chart& c) {
    text_ += c.SFCError ? "E:" : "e:";
    text_ += std::string(c.SFCErrorStep.get().view());
    text_ += c.SFCTrans ? " T " : " t ";
    text_ += std::string(c.SFCCurrentStep.view());
  }
  [[nodiscard]] const std::string& text() const noexcept { return text_; }

 private:
  std::string text_;
};

/// The inputs and flags of one scan.
struct stimulus {
  bool inputs[6];
  std::uint32_t elapsed_ms;
  bool init, reset, pause, quit_error, tip_mode, tip;
};

/// A random sequence of stimuli: inputs of different biases, cycle times of 1 to 25 ms, and
/// now and then an SFC flag held for a few scans.
class stimuli {
 public:
  explicit stimuli(std::uint64_t seed) : rng_(seed) {}
  stimulus next() {
    stimulus s{};
    static constexpr double bias[6] = {0.5, 0.2, 0.8, 0.05, 0.5, 0.35};
    for (int i = 0; i < 6; ++i) s.inputs[i] = unit() < bias[i];
    s.elapsed_ms = 1 + static_cast<std::uint32_t>(unit() * 25);
    hold(init_, 0.004, 3);
    hold(reset_, 0.004, 1);
    hold(pause_, 0.01, 4);
    hold(quit_, 0.006, 2);
    hold(tip_mode_, 0.003, 30);
    s.init = init_ > 0;
    s.reset = reset_ > 0;
    s.pause = pause_ > 0;
    s.quit_error = quit_ > 0;
    s.tip_mode = tip_mode_ > 0;
    s.tip = unit() < 0.3;
    return s;
  }

 private:
  double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
  void hold(int& left, double probability, int scans) {
    if (left > 0) {
      --left;
    } else if (unit() < probability) {
      left = scans;
    }
  }
  std::mt19937_64 rng_;
  int init_ = 0, reset_ = 0, pause_ = 0, quit_ = 0, tip_mode_ = 0;
};

template <class FB>
void apply(FB& fb, const stimulus& s) {
  fb.set_inputs(s.inputs);
  fb.chart.SFCInit = s.init;
  fb.chart.SFCReset = s.reset;
  fb.chart.SFCPause = s.pause;
  fb.chart.SFCQuitError = s.quit_error;
  fb.chart.SFCTipMode = s.tip_mode;
  fb.chart.SFCTip = s.tip;
}

template <class FB>
std::string observe(const FB& fb) {
  observation o;
  fb.observe(o);
  return o.text();
}

/// What a run found: the scans compared, and the first difference ("" if none).
struct run_result {
  std::uint64_t scans = 0;
  std::string difference;
};

/// Runs chart FB in scan order Order on both engines for `scans` scans of the stimuli of
/// `seed`, comparing after each.
template <template <class, class...> class FB, class Order>
run_result compare_engines(std::uint64_t seed, std::uint64_t scans) {
  iecoop_test::fault_recorder faults;  // an unsafe chart reports faults: each engine's are counted
  FB<Order, sfc::compiled_engine> compiled;
  FB<Order, sfc::general_engine> general;
  stimuli input(seed);
  std::uint64_t now_ms = 0;
  run_result result;
  for (std::uint64_t k = 0; k < scans; ++k) {
    const stimulus s = input.next();
    now_ms += s.elapsed_ms;
    cycle_clock::set(LTIME::from_ticks(now_ms * 1'000'000U));
    apply(compiled, s);
    apply(general, s);
    const int before = faults.count;
    compiled();
    const int compiled_faults = faults.count - before;
    general();
    const int general_faults = faults.count - before - compiled_faults;
    ++result.scans;
    const std::string a = observe(compiled);
    const std::string b = observe(general);
    if (a != b || compiled_faults != general_faults) {
      result.difference = "scan " + std::to_string(k) + ":\n  compiled " + a + " (faults " +
                          std::to_string(compiled_faults) + ")\n  general  " + b + " (faults " +
                          std::to_string(general_faults) + ")";
      return result;
    }
  }
  return result;
}

/// The charts of one generated file: each on both engines in both orders, its first
/// difference a failed check that names the chart, the order and the scan.
struct batch {
  int charts = 0;
  int compiled = 0;  // charts on the compiled engine (the others run on the general engine twice)
  std::uint64_t scans = 0;

  template <template <class, class...> class FB>
  void run(const char* name, std::uint64_t seed, std::uint64_t count) {
    ++charts;
    if (decltype(FB<sfc::codesys, sfc::compiled_engine>::chart)::runs_compiled()) ++compiled;
    const std::uint64_t stimuli_seed = seed * 7919U + static_cast<std::uint64_t>(charts);
    const run_result codesys = compare_engines<FB, sfc::codesys>(stimuli_seed, count);
    INFO(std::string(name), " in the codesys order, ", codesys.difference);
    CHECK(codesys.difference.empty());
    const run_result matiec = compare_engines<FB, sfc::matiec>(stimuli_seed + 1, count);
    INFO(std::string(name), " in the matiec order, ", matiec.difference);
    CHECK(matiec.difference.empty());
    scans += codesys.scans + matiec.scans;
  }
  void report() const {
    MESSAGE(charts, " charts (", compiled, " on the compiled engine), ", scans, " scans on each engine");
    CHECK(compiled * 10 >= charts * 7);  // the charts do exercise the compiled engine
  }
};

}  // namespace sfc_engines
