// CTU, CTD, CTUD and their typed variants in each dialect: counting on edges, R and LD
// priority, simultaneous CU and CD, the limits at PV and at the type's ends.
#include "iecoop_test.hpp"

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <type_traits>

using namespace iecoop;

namespace {

// The reset and load inputs under the dialect's name.
template <class B>
BOOL& reset_of(B& block) {
  if constexpr (requires { block.RESET; }) {
    return block.RESET;
  } else {
    return block.R;
  }
}
template <class B>
BOOL& load_of(B& block) {
  if constexpr (requires { block.LOAD; }) {
    return block.LOAD;
  } else {
    return block.LD;
  }
}

struct up_step {
  bool cu;
  bool r;
  int pv;
  bool q;
  int cv;
};

template <class Counter>
void check_up(std::initializer_list<up_step> steps) {
  using value = decltype(Counter::PV);
  Counter counter;
  int row = 0;
  for (const up_step& step : steps) {
    ++row;
    counter.CU = BOOL(step.cu);
    reset_of(counter) = BOOL(step.r);
    counter.PV = static_cast<value>(DINT(step.pv));
    counter();
    INFO("row ", row);
    CHECK(counter.Q == BOOL(step.q));
    CHECK(DINT(counter.CV.get()) == step.cv);
  }
}

struct down_step {
  bool cd;
  bool ld;
  int pv;
  bool q;
  int cv;
};

template <class Counter>
void check_down(std::initializer_list<down_step> steps) {
  using value = decltype(Counter::PV);
  Counter counter;
  int row = 0;
  for (const down_step& step : steps) {
    ++row;
    counter.CD = BOOL(step.cd);
    load_of(counter) = BOOL(step.ld);
    counter.PV = static_cast<value>(DINT(step.pv));
    counter();
    INFO("row ", row);
    CHECK(counter.Q == BOOL(step.q));
    CHECK(DINT(counter.CV.get()) == step.cv);
  }
}

struct up_down_step {
  bool cu;
  bool cd;
  bool r;
  bool ld;
  int pv;
  bool qu;
  bool qd;
  int cv;
};

template <class Counter>
void check_up_down(std::initializer_list<up_down_step> steps) {
  using value = decltype(Counter::PV);
  Counter counter;
  int row = 0;
  for (const up_down_step& step : steps) {
    ++row;
    counter.CU = BOOL(step.cu);
    counter.CD = BOOL(step.cd);
    reset_of(counter) = BOOL(step.r);
    load_of(counter) = BOOL(step.ld);
    counter.PV = static_cast<value>(DINT(step.pv));
    counter();
    INFO("row ", row);
    CHECK(counter.QU == BOOL(step.qu));
    CHECK(counter.QD == BOOL(step.qd));
    CHECK(DINT(counter.CV.get()) == step.cv);
  }
}

/// Calls `counter` with `count` rising edges of `input`.
template <class B>
void pulse_input(B& counter, BOOL B::*input, long count) {
  for (long i = 0; i < count; ++i) {
    counter.*input = TRUE;
    counter();
    counter.*input = FALSE;
    counter();
  }
}

}  // namespace

// The value types and input names of each dialect's counters.
static_assert(std::is_same_v<decltype(CTU::PV), WORD> && std::is_same_v<decltype(codesys::CTUD::PV), WORD>);
static_assert(std::is_same_v<decltype(iec::CTU::PV), INT> && std::is_same_v<decltype(matiec::CTD::PV), INT>);
static_assert(std::is_same_v<decltype(CTU_DINT::PV), DINT> && std::is_same_v<decltype(iec::CTD_LINT::PV), LINT>);
static_assert(std::is_same_v<decltype(matiec::CTUD_UDINT::PV), UDINT> &&
              std::is_same_v<decltype(CTUD_ULINT::PV), ULINT>);
template <class B>
concept has_R = requires(B b) { b.R; };
template <class B>
concept has_LOAD = requires(B b) { b.LOAD; };
static_assert(requires(CTU c) { c.RESET; } && !has_R<CTU>);
static_assert(requires(iec::CTUD c) {
  c.R;
  c.LD;
} && !has_LOAD<iec::CTUD>);
static_assert(inputs_of<CTUD>::names == std::array<std::string_view, 5>{"CU", "CD", "RESET", "LOAD", "PV"});
static_assert(inputs_of<iec::CTD>::names == std::array<std::string_view, 3>{"CD", "LD", "PV"});
static_assert(outputs_of<CTUD>::names == std::array<std::string_view, 3>{"QU", "QD", "CV"});
// CV and Q are outputs: read-only from outside.
static_assert(!std::is_assignable_v<decltype((std::declval<CTU&>().CV)), WORD>);

TEST_SUITE("standard blocks: CTU") {
  TEST_CASE("counts rising edges, not levels, Q once CV >= PV, RESET clears") {
    check_up<CTU>({
        //  CU    R     PV  Q      CV
        {false, false, 2, false, 0},
        {true, false, 2, false, 1},
        {true, false, 2, false, 1},  // still TRUE: no edge
        {false, false, 2, false, 1},
        {true, false, 2, true, 2},  // CV = PV
        {false, false, 2, true, 2},
        {true, false, 2, true, 3},  // CODESYS counts on past PV (up to the type's limit)
        {false, true, 2, false, 0},
    });
  }

  TEST_CASE("R has priority, the edge memory follows CU also while R is TRUE") {
    check_up<iec::CTU>({
        {true, false, 5, false, 1},
        {false, true, 5, false, 0},
        {true, true, 5, false, 0},   // edge during reset: not counted...
        {true, false, 5, false, 0},  // ...and not counted when the reset ends either
        {false, false, 5, false, 0},
        {true, false, 5, false, 1},
    });
  }

  TEST_CASE("a first call with CU TRUE counts, and PV = 0 makes Q TRUE at once") {
    check_up<CTU>({{true, false, 0, true, 1}});
    check_up<CTU>({{false, false, 0, true, 0}});
  }

  TEST_CASE("matiec stops counting at PV") {
    check_up<matiec::CTU>({
        {true, false, 1, true, 1},
        {false, false, 1, true, 1},
        {true, false, 1, true, 1},
        {false, false, 3, false, 1},  // PV raised: counting goes on
        {true, false, 3, false, 2},
    });
  }

  TEST_CASE("iec and codesys stop at the type's maximum, matiec at PV") {
    CTU word_counter;  // WORD: 65535
    word_counter.PV = 10;
    pulse_input(word_counter, &CTU::CU, 70000);
    CHECK(word_counter.CV == 65535);
    CHECK(word_counter.Q == TRUE);

    iec::CTU int_counter;  // INT: 32767, never wrapping to -32768
    int_counter.PV = 100;
    pulse_input(int_counter, &iec::CTU::CU, 40000);
    CHECK(int_counter.CV == 32767);

    matiec::CTU preset_counter;
    preset_counter.PV = 100;
    pulse_input(preset_counter, &matiec::CTU::CU, 40000);
    CHECK(preset_counter.CV == 100);
  }
}

TEST_SUITE("standard blocks: CTD") {
  TEST_CASE("the seed's way: LOAD 0-1-0, then count down to 0") {
    check_down<CTD>({
        //  CD    LD    PV  Q     CV
        {false, false, 3, true, 0},  // CV starts at 0: Q is TRUE before anything is loaded
        {false, true, 3, false, 3},
        {false, false, 3, false, 3},
        {true, false, 3, false, 2},
        {false, false, 3, false, 2},
        {true, false, 3, false, 1},
        {false, false, 3, false, 1},
        {true, false, 3, true, 0},
        {false, false, 3, true, 0},
        {true, false, 3, true, 0},  // WORD: stops at 0
    });
  }

  TEST_CASE("LD has priority over counting") {
    check_down<iec::CTD>({
        {false, true, 2, false, 2},
        {true, true, 2, false, 2},   // edge during load: not counted
        {true, false, 2, false, 2},  // nor after
        {false, false, 2, false, 2},
        {true, false, 2, false, 1},
    });
  }

  TEST_CASE("iec counts below 0 down to the type's minimum, matiec stops at 0") {
    check_down<iec::CTD>({
        {true, false, 0, true, -1},
        {false, false, 0, true, -1},
        {true, false, 0, true, -2},
    });
    check_down<matiec::CTD>({
        {true, false, 0, true, 0},
        {false, false, 0, true, 0},
    });
    iec::CTD counter;
    pulse_input(counter, &iec::CTD::CD, 40000);
    CHECK(counter.CV == -32768);
  }
}

TEST_SUITE("standard blocks: CTUD") {
  TEST_CASE("R before LD before counting, simultaneous CU and CD cancel") {
    check_up_down<CTUD>({
        //  CU    CD     R      LD    PV  QU     QD    CV
        {false, false, false, false, 3, false, true, 0},
        {true, false, false, false, 3, false, false, 1},
        {false, true, false, false, 3, false, true, 0},  // CD rises: down
        {false, false, false, false, 3, false, true, 0},
        {true, true, false, false, 3, false, true, 0},   // both rise at once: nothing
        {false, false, false, true, 3, true, false, 3},  // LD: CV := PV
        {false, false, true, true, 3, false, true, 0},   // R and LD: R wins
        {true, false, false, true, 3, true, false, 3},   // LD and an edge of CU: LD wins
        {false, false, false, false, 3, true, false, 3},
        {true, false, false, false, 3, true, false, 4},  // codesys: up past PV
    });
  }

  TEST_CASE("limits: codesys WORD 0..65535, iec INT -32768..32767, matiec 0..PV") {
    check_up_down<CTUD>({
        {false, true, false, false, 65534, false, true, 0},  // at 0: no further down
        {false, false, false, true, 65534, true, false, 65534},
        {true, false, false, false, 65534, true, false, 65535},
        {false, false, false, false, 65534, true, false, 65535},
        {true, false, false, false, 65534, true, false, 65535},
    });
    check_up_down<iec::CTUD>({
        {false, true, false, false, 32766, false, true, -1},
        {false, false, false, true, 32766, true, false, 32766},
        {true, false, false, false, 32766, true, false, 32767},
        {false, false, false, false, 32766, true, false, 32767},
        {true, false, false, false, 32766, true, false, 32767},
    });
    check_up_down<matiec::CTUD>({
        {false, true, false, false, 1, false, true, 0},
        {true, false, false, false, 1, true, false, 1},
        {false, false, false, false, 1, true, false, 1},
        {true, false, false, false, 1, true, false, 1},
    });
  }

  TEST_CASE("the typed variants stop at their own limits") {
    CTUD_DINT d;
    d.LOAD = TRUE;
    d.PV = std::numeric_limits<DINT>::max() - 1;
    d();
    d.LOAD = FALSE;
    pulse_input(d, &CTUD_DINT::CU, 3);
    CHECK(d.CV == std::numeric_limits<DINT>::max());

    iec::CTUD_LINT l;
    l.LD = TRUE;
    l.PV = std::numeric_limits<LINT>::min() + 1;
    l();
    l.LD = FALSE;
    pulse_input(l, &iec::CTUD_LINT::CD, 3);
    CHECK(l.CV == std::numeric_limits<LINT>::min());
    CHECK(l.QD == TRUE);

    iec::CTUD_ULINT u;
    u.LD = TRUE;
    u.PV = std::numeric_limits<ULINT>::max() - 1;
    u();
    u.LD = FALSE;
    pulse_input(u, &iec::CTUD_ULINT::CU, 3);
    CHECK(u.CV == std::numeric_limits<ULINT>::max());
    u.R = TRUE;
    u();
    u.R = FALSE;
    pulse_input(u, &iec::CTUD_ULINT::CD, 2);
    CHECK(u.CV == 0u);  // unsigned: the minimum is 0

    iec::CTD_UDINT ud;
    pulse_input(ud, &iec::CTD_UDINT::CD, 2);
    CHECK(ud.CV == 0u);
    CHECK(ud.Q == TRUE);

    CTU_LINT big;
    big.PV = 3;
    pulse_input(big, &CTU_LINT::CU, 3);
    CHECK(big.Q == TRUE);
  }

  TEST_CASE("named calls use the dialect's names") {
    CTUD codesys_counter;
    BOOL qu;
    WORD cv;
    codesys_counter("CU"_ = TRUE, "RESET"_ = FALSE, "LOAD"_ = FALSE, "PV"_ = WORD(1), "QU"_ >> qu, "CV"_ >> cv);
    CHECK(qu == TRUE);
    CHECK(cv == 1);
    iec::CTUD iec_counter;
    INT icv;
    iec_counter("LD"_ = TRUE, "PV"_ = INT(7), "CV"_ >> icv);
    CHECK(icv == 7);
    iec_counter("R"_ = TRUE, "CV"_ >> icv);
    CHECK(icv == 0);
  }
}
