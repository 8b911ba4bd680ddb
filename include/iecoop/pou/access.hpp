// SPDX-License-Identifier: MIT
// iecoop/pou/access.hpp — the access modifiers of METHODs, PROPERTYs and ACTIONs.
//
//   PUBLIC     C++ public:     callable from anywhere
//   PRIVATE    C++ private:    only inside the block
//   PROTECTED  C++ protected:  inside the block and blocks derived from it
//   INTERNAL   an internal_access<Library> parameter: only inside the library
//
// C++ has no "visible in this namespace only", so INTERNAL is a pass key: a library names
// itself with a tag type, its POUs derive from member_of<Tag, Self>, and an INTERNAL method
// takes internal_access<Tag> as its first parameter. Only the library's POUs can make one
// (`internal()`), so code outside the library cannot call the method.
//
//     struct my_lib {};                                       // NAMESPACE my_lib
//     struct FB_Axis : function_block<FB_Axis>, member_of<my_lib, FB_Axis> {
//       void Calibrate(internal_access<my_lib>) { ... }       // METHOD INTERNAL Calibrate
//     };
//     struct FB_Machine : function_block<FB_Machine>, member_of<my_lib, FB_Machine> {
//       FB_Axis axis;
//       void body() { axis.Calibrate(internal()); }           // inside the library: fine
//     };
#pragma once

#include <iecoop/config.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

template <class Library, class Self>
struct member_of;

/// The pass key of an INTERNAL member of `Library`: only the library's POUs can make it.
template <class Library>
class internal_access {
  constexpr internal_access() noexcept = default;
  template <class L, class S>
  friend struct member_of;
};

/// Marks the POU `Self` as part of `Library`. An empty base that costs nothing (Self makes
/// it a distinct type in every POU, so nested library POUs still share no empty base).
/// Inside Self — not in blocks derived from it outside the library — `internal()` makes the
/// key the library's INTERNAL members need.
template <class Library, class Self>
struct member_of {
 private:
  friend Self;
  static constexpr internal_access<Library> internal() noexcept { return {}; }
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
