// SPDX-License-Identifier: MIT
// iecoop/standard/counters.hpp — the standard counters CTU, CTD and CTUD, and their typed variants
// (CTU_DINT, CTU_LINT, CTU_UDINT, CTU_ULINT, likewise for CTD and CTUD), all made from one
// template per counter: up_counter<T, Dialect>, down_counter<T, Dialect>,
// up_down_counter<T, Dialect>.
//
//     CTU parts;                                            // ST: parts : CTU;
//     parts("CU"_ = bSensor, "RESET"_ = bClear, "PV"_ = 10);  // ST: parts(CU := bSensor, RESET := bClear, PV := 10);
//     if (parts.Q) ...                                      // 10 parts counted
//
// As in MatIEC (and the IEC text): a counter counts on the rising edge of CU (CD), detected on
// every call, also while R or LD is TRUE; R (reset, CV := 0) comes before LD (load, CV := PV),
// and both before counting; CTUD ignores simultaneous edges of CU and CD. Q (CTUD: QU) is
// CV >= PV, CTD's Q (CTUD: QD) is CV <= 0. The dialect (iecoop/standard/dialect.hpp) decides the
// names of the reset and load inputs, the value type of the plain CTU/CTD/CTUD, and where
// counting stops.
//
// Outputs are read-only from outside, as in ST. Each counter is its inputs, outputs and one
// byte of edge memory per counting input, and nothing else: 8 bytes for a WORD or INT CTU.
#pragma once

#include <limits>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/standard/dialect.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

// The reset and load inputs, named as the dialect names them. They are base classes so that
// a member can have either name; `pin` is the member for the block's pins<> list.
template <counter_names Names>
struct counter_reset_input;
template <>
struct counter_reset_input<counter_names::iec> {
  BOOL R;  ///< VAR_INPUT: TRUE resets CV to 0
  static constexpr auto pin = &counter_reset_input::R;

 protected:
  [[nodiscard]] constexpr bool reset_input() const noexcept { return static_cast<bool>(R); }
};
template <>
struct counter_reset_input<counter_names::codesys> {
  BOOL RESET;  ///< VAR_INPUT: TRUE resets CV to 0
  static constexpr auto pin = &counter_reset_input::RESET;

 protected:
  [[nodiscard]] constexpr bool reset_input() const noexcept { return static_cast<bool>(RESET); }
};

template <counter_names Names>
struct counter_load_input;
template <>
struct counter_load_input<counter_names::iec> {
  BOOL LD;  ///< VAR_INPUT: TRUE loads PV into CV
  static constexpr auto pin = &counter_load_input::LD;

 protected:
  [[nodiscard]] constexpr bool load_input() const noexcept { return static_cast<bool>(LD); }
};
template <>
struct counter_load_input<counter_names::codesys> {
  BOOL LOAD;  ///< VAR_INPUT: TRUE loads PV into CV
  static constexpr auto pin = &counter_load_input::LOAD;

 protected:
  [[nodiscard]] constexpr bool load_input() const noexcept { return static_cast<bool>(LOAD); }
};

template <class T>
constexpr bool check_counter_type() {
  static_assert(AnyInteger<T>,
                "iecoop: a counter counts an IEC integer type (INT, DINT, LINT, UDINT, ULINT, WORD, ...); "
                "use CTU, CTU_DINT, ... or up_counter<DINT, dialect>");
  return true;
}

/// Where counting stops in dialect D.
template <class T, Dialect D>
struct counter_limits {
  /// Counting up goes on while CV < upper(PV).
  static constexpr T upper(T pv) noexcept {
    if constexpr (D::counter_limits == counter_limit::preset) {
      return pv;
    } else {
      return std::numeric_limits<T>::max();
    }
  }
  /// Counting down goes on while CV > lower.
  static constexpr T lower() noexcept {
    if constexpr (D::counter_limits == counter_limit::preset) {
      return T();
    } else {
      return std::numeric_limits<T>::min();
    }
  }
};

}  // namespace detail

/// CTU: counts the rising edges of CU up to the limit; Q once CV >= PV; R (RESET) clears CV.
template <class T, Dialect D>
class up_counter : public function_block<up_counter<T, D>>, public detail::counter_reset_input<D::counter_pin_names> {
  static_assert(detail::check_counter_type<T>());
  using reset_base = detail::counter_reset_input<D::counter_pin_names>;

 public:
  BOOL CU;                        ///< VAR_INPUT: counts up on its rising edge
  read_only<BOOL, up_counter> Q;  ///< VAR_OUTPUT: CV >= PV

 private:
  BOOL cu_memory_;

 public:
  T PV;                         ///< VAR_INPUT: the preset
  read_only<T, up_counter> CV;  ///< VAR_OUTPUT: the count

  using VAR_INPUT = pins<&up_counter::CU, reset_base::pin, &up_counter::PV>;
  using VAR_OUTPUT = pins<&up_counter::Q, &up_counter::CV>;

 private:
  friend struct block_access;
  using limits = detail::counter_limits<T, D>;

  void body() noexcept {
    const bool up = CU && !cu_memory_;
    detail::copy_value(cu_memory_, CU);
    if (this->reset_input()) {
      CV = T();
    } else if (up && CV.get() < limits::upper(PV)) {
      ++CV;
    }
    Q = CV.get() >= PV;
  }
};

/// CTD: counts the rising edges of CD down to the limit; Q once CV <= 0; LD (LOAD) loads PV.
template <class T, Dialect D>
class down_counter : public function_block<down_counter<T, D>>,
                     public detail::counter_load_input<D::counter_pin_names> {
  static_assert(detail::check_counter_type<T>());
  using load_base = detail::counter_load_input<D::counter_pin_names>;

 public:
  BOOL CD;                          ///< VAR_INPUT: counts down on its rising edge
  read_only<BOOL, down_counter> Q;  ///< VAR_OUTPUT: CV <= 0

 private:
  BOOL cd_memory_;

 public:
  T PV;                           ///< VAR_INPUT: the value LD loads
  read_only<T, down_counter> CV;  ///< VAR_OUTPUT: the count

  using VAR_INPUT = pins<&down_counter::CD, load_base::pin, &down_counter::PV>;
  using VAR_OUTPUT = pins<&down_counter::Q, &down_counter::CV>;

 private:
  friend struct block_access;
  using limits = detail::counter_limits<T, D>;

  void body() noexcept {
    const bool down = CD && !cd_memory_;
    detail::copy_value(cd_memory_, CD);
    if (this->load_input()) {
      CV = PV;
    } else if (down && CV.get() > limits::lower()) {
      --CV;
    }
    Q = CV.get() <= T();
  }
};

/// CTUD: counts CU's rising edges up and CD's down; QU once CV >= PV, QD once CV <= 0.
template <class T, Dialect D>
class up_down_counter : public function_block<up_down_counter<T, D>>,
                        public detail::counter_reset_input<D::counter_pin_names>,
                        public detail::counter_load_input<D::counter_pin_names> {
  static_assert(detail::check_counter_type<T>());
  using reset_base = detail::counter_reset_input<D::counter_pin_names>;
  using load_base = detail::counter_load_input<D::counter_pin_names>;

 public:
  BOOL CU;                              ///< VAR_INPUT: counts up on its rising edge
  BOOL CD;                              ///< VAR_INPUT: counts down on its rising edge
  read_only<BOOL, up_down_counter> QU;  ///< VAR_OUTPUT: CV >= PV
  read_only<BOOL, up_down_counter> QD;  ///< VAR_OUTPUT: CV <= 0

 private:
  BOOL cu_memory_;
  BOOL cd_memory_;

 public:
  T PV;                              ///< VAR_INPUT: the preset, and the value LD loads
  read_only<T, up_down_counter> CV;  ///< VAR_OUTPUT: the count

  using VAR_INPUT =
      pins<&up_down_counter::CU, &up_down_counter::CD, reset_base::pin, load_base::pin, &up_down_counter::PV>;
  using VAR_OUTPUT = pins<&up_down_counter::QU, &up_down_counter::QD, &up_down_counter::CV>;

 private:
  friend struct block_access;
  using limits = detail::counter_limits<T, D>;

  void body() noexcept {
    const bool up = CU && !cu_memory_;
    const bool down = CD && !cd_memory_;
    detail::copy_value(cu_memory_, CU);
    detail::copy_value(cd_memory_, CD);
    if (this->reset_input()) {
      CV = T();
    } else if (this->load_input()) {
      CV = PV;
    } else if (up != down) {  // both edges at once cancel out
      if (up) {
        if (CV.get() < limits::upper(PV)) ++CV;
      } else if (CV.get() > limits::lower()) {
        --CV;
      }
    }
    QU = CV.get() >= PV;
    QD = CV.get() <= T();
  }
};

// The blocks of each dialect under their IEC names.
namespace codesys {
using CTU = up_counter<dialect::counter_type, dialect>;
using CTU_DINT = up_counter<DINT, dialect>;
using CTU_LINT = up_counter<LINT, dialect>;
using CTU_UDINT = up_counter<UDINT, dialect>;
using CTU_ULINT = up_counter<ULINT, dialect>;
using CTD = down_counter<dialect::counter_type, dialect>;
using CTD_DINT = down_counter<DINT, dialect>;
using CTD_LINT = down_counter<LINT, dialect>;
using CTD_UDINT = down_counter<UDINT, dialect>;
using CTD_ULINT = down_counter<ULINT, dialect>;
using CTUD = up_down_counter<dialect::counter_type, dialect>;
using CTUD_DINT = up_down_counter<DINT, dialect>;
using CTUD_LINT = up_down_counter<LINT, dialect>;
using CTUD_UDINT = up_down_counter<UDINT, dialect>;
using CTUD_ULINT = up_down_counter<ULINT, dialect>;
}  // namespace codesys

namespace iec {
using CTU = up_counter<dialect::counter_type, dialect>;
using CTU_DINT = up_counter<DINT, dialect>;
using CTU_LINT = up_counter<LINT, dialect>;
using CTU_UDINT = up_counter<UDINT, dialect>;
using CTU_ULINT = up_counter<ULINT, dialect>;
using CTD = down_counter<dialect::counter_type, dialect>;
using CTD_DINT = down_counter<DINT, dialect>;
using CTD_LINT = down_counter<LINT, dialect>;
using CTD_UDINT = down_counter<UDINT, dialect>;
using CTD_ULINT = down_counter<ULINT, dialect>;
using CTUD = up_down_counter<dialect::counter_type, dialect>;
using CTUD_DINT = up_down_counter<DINT, dialect>;
using CTUD_LINT = up_down_counter<LINT, dialect>;
using CTUD_UDINT = up_down_counter<UDINT, dialect>;
using CTUD_ULINT = up_down_counter<ULINT, dialect>;
}  // namespace iec

namespace matiec {
using CTU = up_counter<dialect::counter_type, dialect>;
using CTU_DINT = up_counter<DINT, dialect>;
using CTU_LINT = up_counter<LINT, dialect>;
using CTU_UDINT = up_counter<UDINT, dialect>;
using CTU_ULINT = up_counter<ULINT, dialect>;
using CTD = down_counter<dialect::counter_type, dialect>;
using CTD_DINT = down_counter<DINT, dialect>;
using CTD_LINT = down_counter<LINT, dialect>;
using CTD_UDINT = down_counter<UDINT, dialect>;
using CTD_ULINT = down_counter<ULINT, dialect>;
using CTUD = up_down_counter<dialect::counter_type, dialect>;
using CTUD_DINT = up_down_counter<DINT, dialect>;
using CTUD_LINT = up_down_counter<LINT, dialect>;
using CTUD_UDINT = up_down_counter<UDINT, dialect>;
using CTUD_ULINT = up_down_counter<ULINT, dialect>;
}  // namespace matiec

// The default dialect's counters (CODESYS: WORD, RESET/LOAD).
using CTU = codesys::CTU;
using CTU_DINT = codesys::CTU_DINT;
using CTU_LINT = codesys::CTU_LINT;
using CTU_UDINT = codesys::CTU_UDINT;
using CTU_ULINT = codesys::CTU_ULINT;
using CTD = codesys::CTD;
using CTD_DINT = codesys::CTD_DINT;
using CTD_LINT = codesys::CTD_LINT;
using CTD_UDINT = codesys::CTD_UDINT;
using CTD_ULINT = codesys::CTD_ULINT;
using CTUD = codesys::CTUD;
using CTUD_DINT = codesys::CTUD_DINT;
using CTUD_LINT = codesys::CTUD_LINT;
using CTUD_UDINT = codesys::CTUD_UDINT;
using CTUD_ULINT = codesys::CTUD_ULINT;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
