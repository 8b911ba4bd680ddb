// The two SFC engines (docs/sfc.md, "How a chart is run") on the cases the random charts found
// them to differ in, written out: each is run on the compiled and on the general engine, and the
// expected values are worked out by hand beside the checks. The random charts themselves are
// the test sfc.engines_agree_on_random_charts (tests/sfc_engines).
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

}  // namespace

TEST_SUITE("SFC engines") {
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
