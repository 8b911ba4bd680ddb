// EXPECT: iecoop: a TRANSITION's condition is a BOOL; the callable of the transition in none<...> \(named by its FROM
// EXPECT: sfc_condition_lambda_real\.cpp:23:
// and TO steps\) yields a number EXPECT: sfc_condition_lambda_real.cpp:23 EXPECT-ERRORS: 1 A generic lambda that yields
// a REAL: refused where the chart runs (chart(*this)); its result is known only once the POU is complete.
#include <iecoop/iecoop.hpp>

#include "sfc_chart_fixture.hpp"
using namespace iecoop;
struct FB_Count : function_block<FB_Count>, sfc_fixture::tank_variables {
  INT nCount;
  REAL rLevel;
  INT T_Count() { return nCount; }
  using P = FB_Count;
  sfc::chart<P, sfc::INITIAL_STEP<&P::INIT>, sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::FILL>, &P::GO>,
             sfc::STEP<&P::FILL, sfc::N<&P::A_FILL>>,
#ifdef IECOOP_COMPILE_FAIL
             sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::DRAIN>, [](auto& p) { return p.rLevel; }>,
#else
             sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::DRAIN>, [](auto& p) { return p.rLevel >= 80.0; }>,
#endif
             sfc::STEP<&P::DRAIN>, sfc::TRANSITION<sfc::FROM<&P::DRAIN>, sfc::TO<&P::INIT>, true>>
      chart;
  void body() { chart(*this); }
};
int main() {
  FB_Count fb;
  fb();
}
