// The block of the compile-fail checks of SFC charts (sfc_*.cpp): its variables and steps, and
// the correct chart over them, the twin each misuse is compared with.
#pragma once

// The headers it needs, not the umbrella: GCC finds the umbrella's precompiled header only where a
// check includes it first.
#include <iecoop/sfc/chart.hpp>
#include <iecoop/types/elementary.hpp>

namespace sfc_fixture {

using namespace iecoop;

struct tank_variables {
  BOOL GO;
  sfc::step INIT, FILL, DRAIN;
  void A_FILL() {}
};

// INIT -> FILL -> DRAIN -> INIT.
template <class P>
using tank_chart =
    sfc::chart<P, sfc::INITIAL_STEP<&P::INIT>, sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::FILL>, &P::GO>,
               sfc::STEP<&P::FILL, sfc::N<&P::A_FILL>>,
               sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::DRAIN>, &P::GO>, sfc::STEP<&P::DRAIN>,
               sfc::TRANSITION<sfc::FROM<&P::DRAIN>, sfc::TO<&P::INIT>, true>>;

}  // namespace sfc_fixture
