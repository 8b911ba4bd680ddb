// EXPECT: iecoop: an IEC literal needs a type prefix
// EXPECT-WITHIN: 40
// A timed qualifier with a duration that is no TIME literal: A_FILL(L, T#30ms) is "T#30ms".
#include <iecoop/iecoop.hpp>

#include "sfc_chart_fixture.hpp"
using namespace iecoop;
struct FB_Chart : function_block<FB_Chart>, sfc_fixture::tank_variables {
  using P = FB_Chart;
#ifdef IECOOP_COMPILE_FAIL
  sfc::chart<P, sfc::INITIAL_STEP<&P::INIT>, sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::FILL>, &P::GO>,
             sfc::STEP<&P::FILL, sfc::L<&P::A_FILL, "30ms">>,
             sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::DRAIN>, &P::GO>, sfc::STEP<&P::DRAIN>,
             sfc::TRANSITION<sfc::FROM<&P::DRAIN>, sfc::TO<&P::INIT>, true>>
      chart;
#else
  sfc::chart<P, sfc::INITIAL_STEP<&P::INIT>, sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::FILL>, &P::GO>,
             sfc::STEP<&P::FILL, sfc::L<&P::A_FILL, "T#30ms">>,
             sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::DRAIN>, &P::GO>, sfc::STEP<&P::DRAIN>,
             sfc::TRANSITION<sfc::FROM<&P::DRAIN>, sfc::TO<&P::INIT>, true>>
      chart;
#endif
  void body() { chart(*this); }
};
int main() {
  FB_Chart fb;
  fb();
}
