// SPDX-License-Identifier: MIT
// iecoop/pou/call_interface.hpp — a block's call interface: which members are its VAR_INPUT, VAR_OUTPUT
// and VAR_IN_OUT, so that calls can name them (`tmr("IN"_ = x, "Q"_ >> q)`) and tools can
// list them (replay, traces).
//
// A block lists its own members, after declaring them, as ST lists them in its sections:
//
//     struct TON : function_block<TON> {
//       BOOL IN;  TIME PT;      // inputs
//       BOOL Q;   TIME ET;      // outputs
//       using VAR_INPUT  = iecoop::pins<&TON::IN, &TON::PT>;
//       using VAR_OUTPUT = iecoop::pins<&TON::Q, &TON::ET>;
//       ...
//
// The names come from the members themselves; a derived block lists only what it adds.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/detail/reflect.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// A list of pointers to data members: one section of a block's interface.
template <auto... Members>
struct pins {
  static_assert((std::is_member_object_pointer_v<decltype(Members)> && ...),
                "iecoop: pins<...> lists pointers to data members, e.g. pins<&TON::IN, &TON::PT>");
  static constexpr std::size_t size = sizeof...(Members);
  static constexpr std::array<std::string_view, sizeof...(Members)> names{member_name<Members>...};

  /// The position of the pin called `name`, or size if there is none.
  static constexpr std::size_t index_of(std::string_view name) noexcept {
    for (std::size_t i = 0; i < size; ++i) {
      if (names[i] == name) return i;
    }
    return size;
  }
};

namespace detail {

template <class A, class B>
struct concat_pins;
template <auto... A, auto... B>
struct concat_pins<pins<A...>, pins<B...>> {
  using type = pins<A..., B...>;
};

template <std::size_t I, auto First, auto... Rest>
constexpr auto pin_at() noexcept {
  if constexpr (I == 0) {
    return First;
  } else {
    return pin_at<I - 1, Rest...>();
  }
}
template <class Pins, std::size_t I>
struct pin_member;
template <auto... Members, std::size_t I>
struct pin_member<pins<Members...>, I> {
  static constexpr auto value = pin_at<I, Members...>();
};

// Each section, as the block itself declares it (possibly inherited from its base).
struct input_section {
  template <class B>
  using declared = typename B::VAR_INPUT;
  static constexpr std::string_view keyword = "VAR_INPUT";
};
struct output_section {
  template <class B>
  using declared = typename B::VAR_OUTPUT;
  static constexpr std::string_view keyword = "VAR_OUTPUT";
};
struct in_out_section {
  template <class B>
  using declared = typename B::VAR_IN_OUT;
  static constexpr std::string_view keyword = "VAR_IN_OUT";
};

template <class Section, class B>
struct declared_pins {
  using type = pins<>;
};
template <class Section, class B>
  requires requires { typename Section::template declared<B>; }
struct declared_pins<Section, B> {
  using type = typename Section::template declared<B>;
};

// All pins of a section along the EXTENDS chain: the base's first, then the block's own
// (a block that declares nothing inherits its base's alias, which is then not counted twice).
template <class Section, class B>
struct section_pins {
  using base = typename base_of<B>::type;
  using own = typename declared_pins<Section, B>::type;
  using type = typename concat_pins<
      typename section_pins<Section, base>::type,
      std::conditional_t<std::is_same_v<own, typename declared_pins<Section, base>::type>, pins<>, own>>::type;
};
template <class Section>
struct section_pins<Section, void> {
  using type = pins<>;
};

template <class Pins>
constexpr bool unique_names() noexcept {
  for (std::size_t i = 0; i < Pins::size; ++i) {
    for (std::size_t j = i + 1; j < Pins::size; ++j) {
      if (Pins::names[i] == Pins::names[j]) return false;
    }
  }
  return true;
}

}  // namespace detail

namespace detail {

template <auto Member, std::size_t... I>
auto spell_member(std::index_sequence<I...>) -> spelled<member_name<Member>[I]...>;
/// The name of a pin as a spelled<> type, for diagnostics.
template <auto Member>
using spelled_member_t = decltype(spell_member<Member>(std::make_index_sequence<member_name<Member>.size()>{}));

/// The names a diagnostic lists: `names_are<spelled<'I', 'N'>, spelled<'P', 'T'>>`.
template <class... Spelled>
struct names_are {};
template <class Pins>
struct spelled_pins;
template <auto... Members>
struct spelled_pins<pins<Members...>> {
  using type = names_are<spelled_member_t<Members>...>;
};

}  // namespace detail

/// Every VAR_INPUT of block B, its bases' first.
template <class B>
using inputs_of = typename detail::section_pins<detail::input_section, B>::type;
/// Every VAR_OUTPUT of block B, its bases' first.
template <class B>
using outputs_of = typename detail::section_pins<detail::output_section, B>::type;
/// Every VAR_IN_OUT of block B, its bases' first.
template <class B>
using in_outs_of = typename detail::section_pins<detail::in_out_section, B>::type;

/// The pointer to member at position I of a pins list.
template <class Pins, std::size_t I>
inline constexpr auto pin = detail::pin_member<Pins, I>::value;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
