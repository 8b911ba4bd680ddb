// R_TRIG, F_TRIG (first-call behaviour in each dialect), SR and RS (both inputs TRUE), and the
// instance size of every standard block.
#include "iecoop_test.hpp"

#include <cstddef>
#include <initializer_list>
#include <utility>

using namespace iecoop;

namespace {

struct edge_step {
  bool clk;
  bool q;
};

template <class Trigger>
void check_edges(std::initializer_list<edge_step> steps) {
  Trigger trigger;
  int row = 0;
  for (const edge_step& step : steps) {
    ++row;
    trigger("CLK"_ = BOOL(step.clk));
    INFO("row ", row);
    CHECK(trigger.Q == BOOL(step.q));
  }
}

struct latch_step {
  bool set;
  bool reset;
  bool q1;
};

template <class Latch>
void check_latch(std::initializer_list<latch_step> steps) {
  Latch latch;
  int row = 0;
  for (const latch_step& step : steps) {
    ++row;
    if constexpr (std::is_same_v<Latch, SR>) {
      latch("S1"_ = BOOL(step.set), "R"_ = BOOL(step.reset));
    } else {
      latch("S"_ = BOOL(step.set), "R1"_ = BOOL(step.reset));
    }
    INFO("row ", row);
    CHECK(latch.Q1 == BOOL(step.q1));
  }
}

/// The smallest size a block with `bytes` one-byte members and `values` members of type V
/// can have: no padding beyond what V's alignment demands.
template <class V>
constexpr std::size_t packed_size(std::size_t bytes, std::size_t values) {
  const std::size_t raw = bytes + values * sizeof(V);
  return (raw + alignof(V) - 1) / alignof(V) * alignof(V);
}

}  // namespace

TEST_SUITE("standard blocks: R_TRIG and F_TRIG") {
  TEST_CASE("R_TRIG: one call TRUE per rising edge, also on a first call with CLK TRUE") {
    check_edges<R_TRIG>({{true, true}, {true, false}, {false, false}, {true, true}, {false, false}});
    check_edges<R_TRIG>({{false, false}, {true, true}});
  }

  TEST_CASE("F_TRIG, codesys: no edge on a first call with CLK FALSE (IEC edition 1)") {
    check_edges<F_TRIG>({{false, false}, {true, false}, {false, true}, {false, false}});
    check_edges<codesys::F_TRIG>({{false, false}, {false, false}});
  }

  TEST_CASE("F_TRIG, iec and matiec: a first call with CLK FALSE is a falling edge (IEC edition 2+)") {
    check_edges<iec::F_TRIG>({{false, true}, {false, false}, {true, false}, {false, true}});
    check_edges<matiec::F_TRIG>({{false, true}, {false, false}});
  }

  TEST_CASE("F_TRIG in every dialect: a first call with CLK TRUE is no edge") {
    check_edges<codesys::F_TRIG>({{true, false}, {false, true}});
    check_edges<iec::F_TRIG>({{true, false}, {false, true}});
  }
}

TEST_SUITE("standard blocks: SR and RS") {
  TEST_CASE("SR: set dominant") {
    check_latch<SR>({
        //  S1    R     Q1
        {false, false, false},
        {true, false, true},
        {false, false, true},  // holds
        {false, true, false},
        {true, true, true},  // both: set wins
        {false, false, true},
    });
  }

  TEST_CASE("RS: reset dominant") {
    check_latch<RS>({
        //  S     R1    Q1
        {true, false, true},
        {false, false, true},
        {true, true, false},  // both: reset wins
        {true, false, true},
        {false, true, false},
        {false, false, false},
    });
  }
}

// Each block is as small as its state allows: its inputs and outputs, the state the IEC
// definition needs, and no padding beyond alignment (docs/standard-library.md lists them).
// Timers: IN, Q, the state byte (TOF: and the previous IN), then PT, ET and the start time.
static_assert(sizeof(TON) == packed_size<TIME>(3, 3) && sizeof(TON) == 16);
static_assert(sizeof(TP) == packed_size<TIME>(3, 3) && sizeof(TP) == 16);
static_assert(sizeof(TOF) == packed_size<TIME>(4, 3) && sizeof(TOF) == 16);
static_assert(sizeof(LTON) == packed_size<LTIME>(3, 3) && sizeof(LTON) == 32);
static_assert(sizeof(LTP) == packed_size<LTIME>(3, 3));
static_assert(sizeof(LTOF) == packed_size<LTIME>(4, 3));
// Triggers and bistables: the input, the output, and (triggers) the memory.
static_assert(sizeof(R_TRIG) == 3 && sizeof(F_TRIG) == 3 && sizeof(iec::F_TRIG) == 3);
static_assert(sizeof(SR) == 3 && sizeof(RS) == 3);
// Counters: CU/CD, R/LD, Q, the edge memory, PV and CV (CTUD: 8 bytes, then PV and CV).
static_assert(sizeof(CTU) == packed_size<WORD>(4, 2) && sizeof(CTU) == 8);
static_assert(sizeof(CTD) == packed_size<WORD>(4, 2) && sizeof(iec::CTD) == 8);
static_assert(sizeof(CTUD) == packed_size<WORD>(8, 2) && sizeof(CTUD) == 12);
static_assert(sizeof(CTU_DINT) == packed_size<DINT>(4, 2) && sizeof(CTU_DINT) == 12);
static_assert(sizeof(CTU_UDINT) == packed_size<UDINT>(4, 2));
static_assert(sizeof(CTU_LINT) == packed_size<LINT>(4, 2));
static_assert(sizeof(CTD_ULINT) == packed_size<ULINT>(4, 2));
static_assert(sizeof(CTUD_DINT) == packed_size<DINT>(8, 2) && sizeof(CTUD_DINT) == 16);
static_assert(sizeof(CTUD_LINT) == packed_size<LINT>(8, 2));
