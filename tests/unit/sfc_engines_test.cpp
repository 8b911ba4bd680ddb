// The two SFC engines (docs/sfc.md, "How a chart is run") on the cases the random charts found
// them to differ in, written out: each is run on the compiled and on the general engine, and the
// expected values are worked out by hand beside the checks. The random charts themselves are
// the test sfc.engines_agree_on_random_charts (tests/sfc_engines).
#include <array>

#include "iecoop_test.hpp"

using namespace iecoop;

namespace {

// FUNCTION_BLOCK FB_ENTER_AND_LEAVE: INIT diverges into A and B; A leads to B (B is active: an
// unsafe chart) and B to C, both on GO. In the scan where both fire, one transition enters B
// and the next leaves it.
template <class Order, class Engine>
struct FB_ENTER_AND_LEAVE : function_block<FB_ENTER_AND_LEAVE<Order, Engine>> {
  BOOL GO;
  sfc::step INIT, A, B, C;
  using P = FB_ENTER_AND_LEAVE;
  sfc::chart<P, Order, Engine, sfc::INITIAL_STEP<&P::INIT>,
             sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::A, &P::B>, true>, sfc::STEP<&P::A>,
             sfc::TRANSITION<sfc::FROM<&P::A>, sfc::TO<&P::B>, &P::GO>, sfc::STEP<&P::B>,
             sfc::TRANSITION<sfc::FROM<&P::B>, sfc::TO<&P::C>, &P::GO>, sfc::STEP<&P::C, sfc::final_step>>
      chart;
  void body() { chart(*this); }
};

struct seen {
  bool a, b, c;
  std::uint64_t b_t;
  int faults;
  friend bool operator==(const seen&, const seen&) = default;
};

// Scans 0..3 at 10 ms each, GO from scan 1 on; what the block shows after scan 3.
template <class Order, class Engine>
seen run_enter_and_leave() {
  iecoop_test::fault_recorder faults;
  FB_ENTER_AND_LEAVE<Order, Engine> fb;
  static_assert(decltype(fb.chart)::runs_compiled() == std::is_same_v<Engine, sfc::compiled_engine>);
  for (std::uint64_t k = 0; k <= 3; ++k) {
    cycle_clock::set(LTIME::from_ticks(k * 10'000'000U));
    fb.GO = k >= 1;
    fb();
  }
  return {bool(fb.A.X), bool(fb.B.X), bool(fb.C.X), fb.B.T.get().count(), faults.count};
}

// FUNCTION_BLOCK FB_WINDOW_AFTER_ENTRY: INIT diverges into A and L1 on GO; A (A_A qualified N)
// leads to B after 10 ms; L1 holds A_L qualified L T#20ms; B and L1 converge back to INIT on
// DONE. The L duration ends in the scan after A -> B fired, the step that has it unchanged.
template <class Engine>
struct FB_WINDOW_AFTER_ENTRY : function_block<FB_WINDOW_AFTER_ENTRY<Engine>> {
  BOOL GO, DONE;
  INT C_A, C_L;
  sfc::step INIT, A, B, L1;
  void A_A() { C_A = C_A + 1; }
  void A_L() { C_L = C_L + 1; }
  using P = FB_WINDOW_AFTER_ENTRY;
  sfc::chart<P, sfc::codesys, Engine, sfc::INITIAL_STEP<&P::INIT>,
             sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::A, &P::L1>, &P::GO>, sfc::STEP<&P::A, sfc::N<&P::A_A>>,
             sfc::TRANSITION<sfc::FROM<&P::A>, sfc::TO<&P::B>, [](auto& p) { return p.A.T >= "T#10ms"_iec; }>,
             sfc::STEP<&P::B>, sfc::STEP<&P::L1, sfc::L<&P::A_L, "T#20ms">>,
             sfc::TRANSITION<sfc::FROM<&P::B, &P::L1>, sfc::TO<&P::INIT>, &P::DONE>>
      chart;
  void body() { chart(*this); }
};

struct window_seen {
  int c_a, c_l;
  bool l_q, l_a;
  friend bool operator==(const window_seen&, const window_seen&) = default;
};

// Scan k at k x 10 ms, GO from scan 0 on, DONE never; what the block shows after each scan.
template <class Engine>
std::array<window_seen, 6> run_window_after_entry() {
  FB_WINDOW_AFTER_ENTRY<Engine> fb;
  static_assert(decltype(fb.chart)::runs_compiled() == std::is_same_v<Engine, sfc::compiled_engine>);
  std::array<window_seen, 6> seen{};
  for (std::uint64_t k = 0; k < seen.size(); ++k) {
    cycle_clock::set(LTIME::from_ticks(k * 10'000'000U));
    fb.GO = TRUE;
    fb();
    const auto& l = fb.chart.template action<&FB_WINDOW_AFTER_ENTRY<Engine>::A_L>();
    seen[k] = {fb.C_A.value(), fb.C_L.value(), bool(l.Q), bool(l.A)};
  }
  return seen;
}

}  // namespace

TEST_SUITE("SFC engines") {
  TEST_CASE("codesys: an L duration ends in the scan after another branch's transition fired") {
    // Scan 0: INIT fires. Scan 1: A and L1 active, T 0: A_A and A_L run. Scan 2: T 10 ms: both
    // run again; A -> B fires. Scan 3: B and L1; L1's T is 20 ms, the L duration: A_L's Q falls
    // and its final scan runs (A still TRUE), as A_A's (A was left). Scan 4: A_L's A falls;
    // neither runs again.
    const auto compiled = run_window_after_entry<sfc::compiled_engine>();
    const auto general = run_window_after_entry<sfc::general_engine>();
    CHECK(compiled == general);
    CHECK(general[1] == window_seen{1, 1, true, true});
    CHECK(general[2] == window_seen{2, 2, true, true});
    CHECK(general[3] == window_seen{3, 3, false, true});
    CHECK(general[4] == window_seen{3, 3, false, false});
    CHECK(general[5] == window_seen{3, 3, false, false});
  }

  TEST_CASE("codesys: a step one transition enters and a later one leaves in the same scan is not active") {
    // Scan 0: INIT fires (A and B next). Scan 1: A and B active; A -> B fires (B is active and
    // not left: unsafe_chart) and then B -> C (B's _X is FALSE again). Scan 2: C active, B not,
    // B's T 0 (it was activated); nothing else fires. Scan 3: the same.
    const seen compiled = run_enter_and_leave<sfc::codesys, sfc::compiled_engine>();
    const seen general = run_enter_and_leave<sfc::codesys, sfc::general_engine>();
    CHECK(compiled == general);
    CHECK(general == seen{false, false, true, 0, 1});
  }

  TEST_CASE("matiec: the same scan leaves the step active (entering comes after leaving)") {
    // Scan 0: INIT fires, A and B active at once. Scan 1: A -> B (unsafe_chart) and B -> C fire
    // on the steps of the scan's start; B is left and entered again: active, T 0, as C.
    // Scan 2: B -> C fires again (C is active and not left: unsafe_chart). Scan 3: the same.
    const seen compiled = run_enter_and_leave<sfc::matiec, sfc::compiled_engine>();
    const seen general = run_enter_and_leave<sfc::matiec, sfc::general_engine>();
    CHECK(compiled == general);
    CHECK(general.b == false);
    CHECK(general.c == true);
  }
}
