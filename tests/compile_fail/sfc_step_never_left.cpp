// EXPECT: iecoop: no TRANSITION leaves the step
// EXPECT-WITHIN: 40
// DRAIN is a dead end: nothing leaves it, and it is not marked sfc::final_step.
#include <iecoop/iecoop.hpp>

#include "sfc_chart_fixture.hpp"
using namespace iecoop;
struct FB_Chart : function_block<FB_Chart>, sfc_fixture::tank_variables {
  using P = FB_Chart;
#ifdef IECOOP_COMPILE_FAIL
  sfc::chart<P, sfc::INITIAL_STEP<&P::INIT>, sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::FILL>, &P::GO>,
             sfc::STEP<&P::FILL, sfc::N<&P::A_FILL>>, sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::DRAIN>, &P::GO>,
             sfc::STEP<&P::DRAIN>>
      chart;
#else
  sfc_fixture::tank_chart<P> chart;
#endif
  void body() { chart(*this); }
};
int main() {
  FB_Chart fb;
  fb();
}
