// SPDX-License-Identifier: MIT
// iecoop/pou/global_variables.hpp — a global variable list (GVL): VAR_GLOBAL ... END_VAR in an
// object of its own, with one instance that every POU reaches by the list's name.
//
//     // GVL_Plant:  VAR_GLOBAL  iMode : INT := 1;  END_VAR
//     //             VAR_GLOBAL RETAIN  udiParts : UDINT;  END_VAR
//     struct GVL_Plant : iecoop::global_variables<GVL_Plant> {
//       INT iMode = 1;
//       retain<UDINT> udiParts;
//     };
//     GVL_Plant::instance().udiParts += 1;   // ST: GVL_Plant.udiParts := GVL_Plant.udiParts + 1;
//
// Give the list to an application (`globals<GVL_Plant>{}`), which constructs it at start(),
// resets it with the programs and keeps its RETAIN and PERSISTENT values, or declare its one
// instance yourself. A program that names the lists it uses (ST's VAR_EXTERNAL:
// `using VAR_EXTERNAL = iecoop::globals<GVL_Plant>;`) does not compile in an application
// that lacks one of them; GVL_Plant::instance() without an instance reports a fault that
// names the list and the fix.
#pragma once

#include <iecoop/config.hpp>
#include <iecoop/detail/single_instance.hpp>
#include <iecoop/fault.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * The base of a global variable list `Self` (CRTP). One instance lives at a time and is
 * `Self::instance()` (`Self::exists()` tells whether it lives); a second one reports
 * fault_kind::duplicate_globals, and instance() without one reports
 * fault_kind::invalid_value and returns a scratch instance.
 */
template <class Self>
class global_variables : public detail::single_instance<Self, fault_kind::duplicate_globals> {
 public:
  /// Marks a global variable list (for diagnostics that say "global variable list").
  using iecoop_global_variables = void;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
