// Instructions per call of the Util library's blocks (docs/util.md), for callgrind: each kernel
// repeats one call n times in a loop that sets the cycle clock (10 ms apart) and the inputs as
// a task would; bench/callgrind.sh runs it twice with different n and divides the difference.
// util_driver is the controllers' loop alone (the clock and the plant they hold), util_loop the
// other kernels' (the clock alone), so a block's cost is its kernel's count minus its loop's.
// PID and RAMP_REAL have hand-written twins — the same documented steps (docs/util.md) in plain
// floats, without iecoop's types — that must agree with them exactly before anything is counted.
//
//   iecoop_bench_util_count <kernel> <n>      iecoop_bench_util_count --list | --sizes
//   sh bench/callgrind.sh build/bench/bench/iecoop_bench_util_count
#include <cstdint>
#include <cstdio>
#include <cstring>

#include <iecoop/iecoop.hpp>

#include "count_runner.hpp"

namespace {

using namespace iecoop;

// What a kernel's loop does besides the block: the cycle clock, 10 ms apart.
void set_clock(std::uint64_t i) { cycle_clock::set(LTIME::from_ticks(i * 10'000'000U)); }

// A block's instance is kept in memory after each call (bench::keep), as it is in a program
// that a task calls; the twins' too.
using bench::keep;

// --- PID and its twin --------------------------------------------------------------------

// The documented steps in plain floats (docs/util.md, "Controllers"), measuring the time in ms.
// Like the block, it keeps its inputs: what a call was given stays readable (a trace, a watch
// list and the MQTT bridge read a block's inputs after its call), so both store them.
struct hand_pid {
  // The inputs, kept as a block keeps them (a trace or a watch reads them after the call).
  float actual = 0.0F, set_point = 0.0F;
  // The parameters, set by the program (as the ST sets the block's inputs).
  float p_kp = 0.0F, p_tn = 0.0F, p_tv = 0.0F, y_manual = 0.0F, y_offset = 0.0F, y_min = 0.0F, y_max = 0.0F;
  bool manual = false, reset = false;
  // The state.
  float x1 = 0.0F, x2 = 0.0F, x3 = 0.0F;
  float integral = 0.0F, kp = 0.0F, tn = 0.0F, tv = 0.0F;
  float y = 0.0F;
  std::uint32_t last_ms = 0;
  bool started = false, limited = false, overflow = false;

  void call(float new_actual, float new_set_point) {
    actual = new_actual;
    set_point = new_set_point;
    const float e = set_point - actual;
    const std::uint32_t now = static_cast<std::uint32_t>(cycle_clock::now_as<TIME>().count());
    if (!started || reset) {
      started = true;
      kp = p_kp;
      tn = p_tn;
      tv = p_tv;
      integral = 0.0F;
      overflow = false;
      x1 = x2 = x3 = e;
      y = y_offset;
      limited = false;
      last_ms = now;
      return;
    }
    if (manual) {
      kp = p_kp;
      tn = p_tn;
      tv = p_tv;
      y = y_manual;
      limited = false;
      x1 = x2 = x3 = e;
      if (kp != 0.0F && tn != 0.0F) {
        const float a = ((y_manual - y_offset) / kp - e) * tn;
        if (a <= 1e38F && a >= -1e38F) {
          integral = a;
        } else {
          overflow = true;
        }
      }
      last_ms = now;
      return;
    }
    if (overflow) return;
    const float dt = static_cast<float>(now - last_ms) / 1000.0F;
    last_ms = now;
    if (!(dt > 0.0F)) return;
    const float sum_i = integral + e * dt;
    if (!(sum_i <= 1e38F && sum_i >= -1e38F)) {
      overflow = true;
      return;
    }
    integral = sum_i;
    const float d = (3.0F * (e - x3) + x1 - x2) / (10.0F * dt);
    x3 = x2;
    x2 = x1;
    x1 = e;
    const float d_part = tv * d;
    float sum = e;
    if (tn != 0.0F) sum = sum + integral / tn;
    sum = sum + d_part;
    float out = kp * sum + y_offset;
    bool at_limit = false;
    if (y_min < y_max) {
      if (out > y_max) {
        out = y_max;
        at_limit = true;
      } else if (out < y_min) {
        out = y_min;
        at_limit = true;
      }
    }
    if (at_limit && kp != 0.0F && tn != 0.0F) {
      const float a = ((out - y_offset) / kp - e - d_part) * tn;
      if (a <= 1e38F && a >= -1e38F) {
        integral = a;
      } else {
        overflow = true;
      }
    }
    y = out;
    limited = at_limit;
  }
};

// A first-order plant the controllers hold (so that every call sees a new ACTUAL).
struct plant {
  float value = 0.0F;
  void step(float u) { value = value + (2.0F * u - value) * 0.01F; }
};
float set_point_at(std::uint64_t i) { return (i / 1000U) % 2U == 0U ? 1.0F : 1.5F; }

// Both sides as a program writes them: the parameters set once, the two signals every call.
void configure(PID& pid) {
  pid.KP = REAL(1.2F);
  pid.TN = REAL(2.0F);
  pid.TV = REAL(0.1F);
  pid.Y_MIN = REAL(-1.0F);
  pid.Y_MAX = REAL(1.0F);
}
void configure(hand_pid& pid) {
  pid.p_kp = 1.2F;
  pid.p_tn = 2.0F;
  pid.p_tv = 0.1F;
  pid.y_min = -1.0F;
  pid.y_max = 1.0F;
}

std::uint32_t pid_calls(std::uint64_t n) {
  PID pid;
  configure(pid);
  plant p;
  for (std::uint64_t i = 0; i < n; ++i) {
    set_clock(i);
    pid("ACTUAL"_ = REAL(p.value), "SET_POINT"_ = REAL(set_point_at(i)));
    p.step(pid.Y.get().value());
    keep(p);
    keep(pid);  // the instance lives in memory between cycles, as in a program
  }
  return pid.LIMITS_ACTIVE ? 1U : 0U;
}

std::uint32_t pid_hand_calls(std::uint64_t n) {
  hand_pid pid;
  configure(pid);
  plant p;
  for (std::uint64_t i = 0; i < n; ++i) {
    set_clock(i);
    pid.call(p.value, set_point_at(i));
    p.step(pid.y);
    keep(p);
    keep(pid);
  }
  return pid.limited ? 1U : 0U;
}

// --- RAMP_REAL and its twin --------------------------------------------------------------

struct hand_ramp {
  // The input, kept as a block keeps it; the parameters, set by the program; RESET.
  float in = 0.0F;
  float ascend = 0.0F, descend = 0.0F;
  std::uint32_t base_ms = 0;
  bool reset = false;
  // The state.
  float out = 0.0F;
  std::uint32_t last_ms = 0;
  bool timed = false;

  void call(float new_in) {
    in = new_in;
    const std::uint32_t now = static_cast<std::uint32_t>(cycle_clock::now_as<TIME>().count());
    const std::uint32_t elapsed = timed ? now - last_ms : 0U;
    last_ms = now;
    timed = true;
    if (reset) {
      timed = false;
      return;
    }
    float up = ascend;
    float down = descend;
    if (base_ms != 0U) {
      up = up * static_cast<float>(elapsed) / static_cast<float>(base_ms);
      down = down * static_cast<float>(elapsed) / static_cast<float>(base_ms);
    }
    if (up < 0.0F) up = 0.0F;
    if (down < 0.0F) down = 0.0F;
    if (in > out) {
      out = in - out <= up ? in : out + up;
    } else if (in < out) {
      out = out - in <= down ? in : out - down;
    }
  }
};
float ramp_target_at(std::uint64_t i) { return (i / 200U) % 2U == 0U ? 100.0F : -40.0F; }

void configure(RAMP_REAL& ramp) {
  ramp.ASCEND = REAL(50.0F);
  ramp.DESCEND = REAL(80.0F);
  ramp.TIMEBASE = "T#1s"_iec;
}
void configure(hand_ramp& ramp) {
  ramp.ascend = 50.0F;
  ramp.descend = 80.0F;
  ramp.base_ms = 1000U;
}

std::uint32_t ramp_real_calls(std::uint64_t n) {
  RAMP_REAL ramp;
  configure(ramp);
  float sink = 0.0F;
  for (std::uint64_t i = 0; i < n; ++i) {
    set_clock(i);
    ramp("IN"_ = REAL(ramp_target_at(i)));
    sink = ramp.OUT.get().value();
    keep(sink);
    keep(ramp);
  }
  return sink > 1e30F ? 1U : 0U;
}

std::uint32_t ramp_real_hand_calls(std::uint64_t n) {
  hand_ramp ramp;
  configure(ramp);
  float sink = 0.0F;
  for (std::uint64_t i = 0; i < n; ++i) {
    set_clock(i);
    ramp.call(ramp_target_at(i));
    sink = ramp.out;
    keep(sink);
    keep(ramp);
  }
  return sink > 1e30F ? 1U : 0U;
}

// --- The other blocks: one call per iteration, the inputs from i -------------------------

std::uint32_t driver(std::uint64_t n) {
  plant p;
  for (std::uint64_t i = 0; i < n; ++i) {
    set_clock(i);
    p.step(set_point_at(i));
    keep(p);
  }
  return p.value > 1e30F ? 1U : 0U;
}

// An instance of nothing, for the loop alone.
struct no_block {
  int unused = 0;
};

template <class Block, class Call>
std::uint32_t block_calls(std::uint64_t n, Call call) {
  Block block;
  for (std::uint64_t i = 0; i < n; ++i) {
    set_clock(i);
    call(block, i);
    keep(block);
  }
  return 0;
}

REAL real_at(std::uint64_t i) { return REAL(static_cast<float>(i % 97U) * 0.5F); }
INT int_at(std::uint64_t i) { return INT(static_cast<std::int16_t>(static_cast<int>(i % 2000U) - 1000)); }

std::uint32_t loop_calls(std::uint64_t n) {
  return block_calls<no_block>(n, [](no_block&, std::uint64_t) {});
}
std::uint32_t pd_calls(std::uint64_t n) {
  return block_calls<PD>(n, [](PD& b, std::uint64_t i) {
    b("ACTUAL"_ = real_at(i), "SET_POINT"_ = REAL(20.0F), "KP"_ = REAL(1.5F), "TV"_ = REAL(0.2F));
  });
}
std::uint32_t pid_fixcycle_calls(std::uint64_t n) {
  return block_calls<PID_FIXCYCLE>(n, [](PID_FIXCYCLE& b, std::uint64_t i) {
    b("ACTUAL"_ = real_at(i), "SET_POINT"_ = REAL(20.0F), "KP"_ = REAL(1.2F), "TN"_ = REAL(2.0F), "TV"_ = REAL(0.1F),
      "CYCLE"_ = REAL(0.01F));
  });
}
std::uint32_t derivative_calls(std::uint64_t n) {
  return block_calls<DERIVATIVE>(n, [](DERIVATIVE& b, std::uint64_t i) { b("IN"_ = real_at(i), "TM"_ = DWORD(10)); });
}
std::uint32_t integral_calls(std::uint64_t n) {
  return block_calls<INTEGRAL>(n, [](INTEGRAL& b, std::uint64_t i) { b("IN"_ = real_at(i), "TM"_ = DWORD(10)); });
}
std::uint32_t lin_trafo_calls(std::uint64_t n) {
  return block_calls<LIN_TRAFO>(n, [](LIN_TRAFO& b, std::uint64_t i) {
    b("IN"_ = real_at(i), "IN_MIN"_ = REAL(0.0F), "IN_MAX"_ = REAL(50.0F), "OUT_MIN"_ = REAL(-20.0F),
      "OUT_MAX"_ = REAL(40.0F));
  });
}
std::uint32_t statistics_int_calls(std::uint64_t n) {
  return block_calls<STATISTICS_INT>(n, [](STATISTICS_INT& b, std::uint64_t i) { b("IN"_ = int_at(i)); });
}
std::uint32_t statistics_real_calls(std::uint64_t n) {
  return block_calls<STATISTICS_REAL>(n, [](STATISTICS_REAL& b, std::uint64_t i) { b("IN"_ = real_at(i)); });
}
std::uint32_t variance_calls(std::uint64_t n) {
  return block_calls<VARIANCE>(n, [](VARIANCE& b, std::uint64_t i) { b("IN"_ = real_at(i)); });
}
std::uint32_t blink_calls(std::uint64_t n) {
  return block_calls<BLINK>(
      n, [](BLINK& b, std::uint64_t) { b("ENABLE"_ = TRUE, "TIMELOW"_ = "T#500ms"_iec, "TIMEHIGH"_ = "T#200ms"_iec); });
}
std::uint32_t gen_triangle_calls(std::uint64_t n) {
  return block_calls<GEN>(n, [](GEN& b, std::uint64_t) {
    b("MODE"_ = GEN_MODE::TRIANGLE, "BASE"_ = TRUE, "PERIOD"_ = "T#2s"_iec, "AMPLITUDE"_ = INT(100));
  });
}
std::uint32_t gen_sine_calls(std::uint64_t n) {
  return block_calls<GEN>(n, [](GEN& b, std::uint64_t) {
    b("MODE"_ = GEN_MODE::SINE, "BASE"_ = TRUE, "PERIOD"_ = "T#2s"_iec, "AMPLITUDE"_ = INT(100));
  });
}
std::uint32_t freq_measure_calls(std::uint64_t n) {
  return block_calls<FREQ_MEASURE>(
      n, [](FREQ_MEASURE& b, std::uint64_t i) { b("IN"_ = BOOL(i % 7U == 0U), "PERIODS"_ = INT(4)); });
}
std::uint32_t charcurve_calls(std::uint64_t n) {
  static ARRAY<POINT, 0, 10> curve = {POINT{INT(0), INT(0)}, POINT{INT(250), INT(50)}, POINT{INT(500), INT(150)},
                                      POINT{INT(750), INT(400)}, POINT{INT(1000), INT(1000)}};
  return block_calls<CHARCURVE>(n, [](CHARCURVE& b, std::uint64_t i) {
    b("IN"_ = INT(static_cast<std::int16_t>(i % 1000U)), "N"_ = BYTE(5), "P"_ = curve);
  });
}
std::uint32_t ramp_int_calls(std::uint64_t n) {
  return block_calls<RAMP_INT>(n, [](RAMP_INT& b, std::uint64_t i) {
    b("IN"_ = INT(static_cast<std::int16_t>((i / 200U) % 2U == 0U ? 100 : -40)), "ASCEND"_ = INT(50),
      "DESCEND"_ = INT(80), "TIMEBASE"_ = "T#1s"_iec);
  });
}
std::uint32_t hysteresis_calls(std::uint64_t n) {
  return block_calls<HYSTERESIS>(
      n, [](HYSTERESIS& b, std::uint64_t i) { b("IN"_ = int_at(i), "HIGH"_ = INT(300), "LOW"_ = INT(-300)); });
}
std::uint32_t limitalarm_calls(std::uint64_t n) {
  return block_calls<LIMITALARM>(
      n, [](LIMITALARM& b, std::uint64_t i) { b("IN"_ = int_at(i), "HIGH"_ = INT(300), "LOW"_ = INT(-300)); });
}
std::uint32_t bcd_calls(std::uint64_t n) {
  std::uint32_t sum = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    set_clock(i);
    const INT value = BCD_TO_INT(BYTE(static_cast<std::uint8_t>(i)));
    const BYTE bcd = INT_TO_BCD(value);
    sum += bcd.value();
    keep(sum);
  }
  return sum == 0xFFFFFFFFU ? 1U : 0U;
}
std::uint32_t bits_calls(std::uint64_t n) {
  UNPACK bits;
  DWORD word = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    set_clock(i);
    word = PUTBIT(word, BYTE(static_cast<std::uint8_t>(i % 32U)),
                  EXTRACT(word, BYTE(static_cast<std::uint8_t>(i % 31U))) == FALSE);
    bits("B"_ = PACK(bits.B1, bits.B2, bits.B3, bits.B4, bits.B5, bits.B6, bits.B7, BOOL((word.value() & 1U) != 0U)));
    keep(bits);
  }
  return word == DWORD(0xFFFFFFFFU) ? 1U : 0U;
}

struct kernel {
  const char* name;
  std::uint32_t (*run)(std::uint64_t n);
};

const kernel all_kernels[] = {
    {"util_driver", driver},
    {"util_loop", loop_calls},
    {"util_pid", pid_calls},
    {"util_pid_handwritten", pid_hand_calls},
    {"util_ramp_real", ramp_real_calls},
    {"util_ramp_real_handwritten", ramp_real_hand_calls},
    {"util_pd", pd_calls},
    {"util_pid_fixcycle", pid_fixcycle_calls},
    {"util_derivative", derivative_calls},
    {"util_integral", integral_calls},
    {"util_lin_trafo", lin_trafo_calls},
    {"util_statistics_int", statistics_int_calls},
    {"util_statistics_real", statistics_real_calls},
    {"util_variance", variance_calls},
    {"util_blink", blink_calls},
    {"util_gen_triangle", gen_triangle_calls},
    {"util_gen_sine", gen_sine_calls},
    {"util_freq_measure", freq_measure_calls},
    {"util_charcurve", charcurve_calls},
    {"util_ramp_int", ramp_int_calls},
    {"util_hysteresis", hysteresis_calls},
    {"util_limitalarm", limitalarm_calls},
    {"util_bcd", bcd_calls},
    {"util_bits", bits_calls},
};

// The twins must compute what the blocks compute, call for call.
bool twins_agree() {
  PID pid;
  hand_pid hand;
  configure(pid);
  configure(hand);
  plant p1, p2;
  RAMP_REAL ramp;
  hand_ramp hand_r;
  configure(ramp);
  configure(hand_r);
  for (std::uint64_t i = 0; i < 20000; ++i) {
    set_clock(i);
    pid("ACTUAL"_ = REAL(p1.value), "SET_POINT"_ = REAL(set_point_at(i)), "MANUAL"_ = BOOL(i >= 9000 && i < 9500));
    hand.manual = i >= 9000 && i < 9500;
    hand.call(p2.value, set_point_at(i));
    if (pid.Y.get().value() != hand.y || static_cast<bool>(pid.LIMITS_ACTIVE) != hand.limited) {
      std::fprintf(stderr, "iecoop_bench_util_count: PID and its twin differ at call %llu\n",
                   static_cast<unsigned long long>(i));
      return false;
    }
    p1.step(pid.Y.get().value());
    p2.step(hand.y);
    ramp("IN"_ = REAL(ramp_target_at(i)), "RESET"_ = BOOL(i >= 5000 && i < 5100));
    hand_r.reset = i >= 5000 && i < 5100;
    hand_r.call(ramp_target_at(i));
    if (ramp.OUT.get().value() != hand_r.out) {
      std::fprintf(stderr, "iecoop_bench_util_count: RAMP_REAL and its twin differ at call %llu\n",
                   static_cast<unsigned long long>(i));
      return false;
    }
  }
  return true;
}

void print_sizes() {
  std::printf("PD %zu\nPID %zu\nPID_FIXCYCLE %zu\nDERIVATIVE %zu\nINTEGRAL %zu\nLIN_TRAFO %zu\n", sizeof(PD),
              sizeof(PID), sizeof(PID_FIXCYCLE), sizeof(DERIVATIVE), sizeof(INTEGRAL), sizeof(LIN_TRAFO));
  std::printf("STATISTICS_INT %zu\nSTATISTICS_REAL %zu\nVARIANCE %zu\nBLINK %zu\nGEN %zu\nFREQ_MEASURE %zu\n",
              sizeof(STATISTICS_INT), sizeof(STATISTICS_REAL), sizeof(VARIANCE), sizeof(BLINK), sizeof(GEN),
              sizeof(FREQ_MEASURE));
  std::printf("CHARCURVE %zu\nRAMP_INT %zu\nRAMP_REAL %zu\nHYSTERESIS %zu\nLIMITALARM %zu\nUNPACK %zu\n",
              sizeof(CHARCURVE), sizeof(RAMP_INT), sizeof(RAMP_REAL), sizeof(HYSTERESIS), sizeof(LIMITALARM),
              sizeof(UNPACK));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--sizes") == 0) {
    print_sizes();
    return 0;
  }
  if (!twins_agree()) return 1;
  return bench::run_count_main(argc, argv, all_kernels, "iecoop_bench_util_count");
}
