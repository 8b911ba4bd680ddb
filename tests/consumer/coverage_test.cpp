// The tests of FB_Level (coverage_pou.hpp) that a coverage report must find incomplete: no
// case has a level below 10.
#include <iecoop/testing.hpp>

#include "coverage_pou.hpp"

using namespace iecoop;
using plant::FB_Level;

TEST_CASE("FB_Level reports a high level") {
  FB_Level fb;
  fb("rLevel"_ = REAL(95.0F));
  CHECK(fb.bHigh);
  CHECK_FALSE(fb.bLow);
}

TEST_CASE("FB_Level reports neither in the band") {
  FB_Level fb;
  fb("rLevel"_ = REAL(50.0F));
  CHECK_FALSE(fb.bHigh);
  CHECK_FALSE(fb.bLow);
}
