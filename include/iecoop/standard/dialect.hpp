// SPDX-License-Identifier: MIT
// iecoop/standard/dialect.hpp — where the standard function blocks of IEC 61131-3's editions, of
// CODESYS and of MatIEC (OpenPLC, Beremiz) differ, as policies you pick.
//
// Three points differ, and only these: whether F_TRIG fires on its first call when CLK is
// FALSE, where counters stop, and whether the counters' reset and load inputs are called
// R/LD (IEC) or RESET/LOAD (CODESYS, TwinCAT). Timers, R_TRIG, SR and RS are the same
// everywhere (MatIEC's state machines of the IEC timing diagrams).
//
//   dialect          F_TRIG first call   counters stop at             CTU/CTD/CTUD    names
//   codesys (default) does not fire      the type's limits            WORD            RESET, LOAD
//   iec              fires (ed. 2+)      the type's limits (ed. 3)    INT             R, LD
//   matiec           fires               PV counting up, 0 down       INT             R, LD
//
// `iecoop::TON`, `iecoop::CTU`, ... are the codesys blocks. The blocks of a dialect are in the
// namespace of its name: `iecoop::iec::CTU`, `iecoop::matiec::F_TRIG`; pick them one by one
// with using-declarations (`using iecoop::iec::CTU;`). A dialect of your own is a struct with
// the members below (see the Dialect concept).
#pragma once

#include <concepts>
#include <cstdint>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// Where a counter stops counting.
enum class counter_limit : std::uint8_t {
  type,    ///< up while CV < the type's maximum, down while CV > its minimum (IEC 61131-3 ed. 3)
  preset,  ///< up while CV < PV, down while CV > 0 (MatIEC, OpenPLC)
};

/// What the counters' reset and load inputs are called.
enum class counter_names : std::uint8_t {
  iec,      ///< R and LD
  codesys,  ///< RESET and LOAD
};

/// A dialect of the standard function blocks: the three points where implementations differ.
template <class D>
concept Dialect = requires {
  { D::name } -> std::convertible_to<std::string_view>;
  { D::f_trig_fires_on_first_call } -> std::convertible_to<bool>;
  { D::counter_limits } -> std::convertible_to<counter_limit>;
  { D::counter_pin_names } -> std::convertible_to<counter_names>;
  typename D::counter_type;  // the value type of CTU, CTD and CTUD
};

namespace codesys {
/// CODESYS's Standard library (and TwinCAT's Tc2_Standard, which documents the same
/// behaviour): IEC edition 1's F_TRIG, WORD counters named RESET/LOAD that stop at 0 and
/// 65535.
struct dialect {
  static constexpr std::string_view name = "codesys";
  static constexpr bool f_trig_fires_on_first_call = false;
  static constexpr counter_limit counter_limits = counter_limit::type;
  static constexpr counter_names counter_pin_names = counter_names::codesys;
  using counter_type = WORD;
};
}  // namespace codesys

namespace iec {
/// IEC 61131-3 edition 3: F_TRIG fires on a first call with CLK FALSE, INT counters that
/// stop at the type's limits (PVmax, PVmin), inputs R and LD.
struct dialect {
  static constexpr std::string_view name = "iec";
  static constexpr bool f_trig_fires_on_first_call = true;
  static constexpr counter_limit counter_limits = counter_limit::type;
  static constexpr counter_names counter_pin_names = counter_names::iec;
  using counter_type = INT;
};
}  // namespace iec

namespace matiec {
/// MatIEC's standard library (OpenPLC, Beremiz): as iec, but counters stop at PV counting up
/// and at 0 counting down.
struct dialect {
  static constexpr std::string_view name = "matiec";
  static constexpr bool f_trig_fires_on_first_call = true;
  static constexpr counter_limit counter_limits = counter_limit::preset;
  static constexpr counter_names counter_pin_names = counter_names::iec;
  using counter_type = INT;
};
}  // namespace matiec

/// The dialect of `iecoop::TON`, `iecoop::CTU`, ...: CODESYS's.
using default_dialect = codesys::dialect;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
