// SPDX-License-Identifier: MIT
// iecoop/standard/string_functions.hpp — the IEC string functions LEN, LEFT, RIGHT, MID, CONCAT,
// INSERT, DELETE, REPLACE and FIND, with IEC's 1-based positions.
//
// Each function takes STRING/WSTRING of any capacity or string literals, and returns a
// string big enough for every possible result (LEFT of a STRING(20) is a STRING(20),
// CONCAT of STRING(20) and STRING(30) a STRING(50)); assigning the result to a smaller
// variable truncates as any STRING assignment does. (CODESYS's Standard library works on
// STRING(255) instead, so it truncates longer strings; iecoop never does.)
//
// Arguments outside the string never cause undefined behaviour; each function documents
// its result for them (mostly: the input unchanged, or the empty string).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/string.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

template <class S>
struct string_arg {};
template <class C, std::size_t N>
struct string_arg<iec_string<C, N>> {
  using char_type = C;
  static constexpr std::size_t capacity = N;
};
template <class C, std::size_t M>
  requires(is_char_v<C> && M >= 1)
struct string_arg<C[M]> {
  using char_type = C;
  static constexpr std::size_t capacity = M - 1;
};

/// A variable wrapper of a STRING/WSTRING that holds its string (a block's var<STRING>, a
/// retain<STRING>, an in-out...): that string. (A property's Get returns a copy, which a view
/// must not outlive: pass `fb.p.get()`, which lives as long as the call.)
template <class W>
  requires(value_wrapper<W> && is_iec_string<unwrapped_t<W>>::value &&
           std::is_lvalue_reference_v<decltype(std::declval<const W&>().get())>)
struct string_arg<W> : string_arg<unwrapped_t<W>> {};

/// A STRING/WSTRING of any capacity (or a variable of one), or a string literal.
template <class S>
concept string_argument = requires { typename string_arg<std::remove_cvref_t<S>>::char_type; };

template <class S>
using char_of = typename string_arg<std::remove_cvref_t<S>>::char_type;
template <class S>
inline constexpr std::size_t capacity_of = string_arg<std::remove_cvref_t<S>>::capacity;

/// The capacity of a result: at least 1, the smallest STRING there is (a result built
/// from empty literals only is still a STRING(1)).
constexpr std::size_t result_capacity(std::size_t capacity) noexcept { return capacity == 0 ? 1 : capacity; }

template <class S>
constexpr std::basic_string_view<char_of<S>> view_of(const S& s) noexcept {
  if constexpr (std::is_array_v<std::remove_cvref_t<S>>) {
    std::size_t n = 0;
    while (n < capacity_of<S> && s[n] != char_of<S>{}) ++n;
    return {s, n};
  } else if constexpr (value_wrapper<S>) {
    return value_of(s).view();
  } else {
    return s.view();
  }
}

/// A length or position argument: any IEC integer (a variable, a variable wrapper such as a
/// var<INT>, or an intermediate result such as `iAt - 1`), or a C++ integer.
template <class T>
concept position_argument = AnyInt<T> || cpp_integer<T> || (Intermediate<T> && AnyInt<typename T::nominal_type>) ||
                            (value_wrapper<T> && AnyInt<argument_t<T>>);

/// The value of a length or position; unsigned values beyond the int64 range saturate
/// (they are beyond any string anyway).
template <position_argument T>
constexpr std::int64_t as_i64(const T& v) noexcept {
  if constexpr (value_wrapper<T>) {
    return as_i64(v.get());
  } else if constexpr (AnyInt<T> || Intermediate<T>) {
    return as_i64(v.value());
  } else if constexpr (std::is_unsigned_v<T>) {
    constexpr auto max = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
    return static_cast<std::uint64_t>(v) > max ? std::numeric_limits<std::int64_t>::max()
                                               : static_cast<std::int64_t>(v);
  } else {
    return static_cast<std::int64_t>(v);
  }
}

template <class C>
constexpr std::size_t append_part(C* buffer, std::size_t n, std::size_t cap, std::basic_string_view<C> part) noexcept {
  for (std::size_t i = 0; i < part.size() && n < cap; ++i) buffer[n++] = part[i];
  return n;
}

/// The string made of `parts`, in a string of capacity Cap (which the callers choose big
/// enough for every part together).
template <class C, std::size_t Cap, class... Views>
constexpr iec_string<C, result_capacity(Cap)> join(Views... parts) noexcept {
  constexpr std::size_t cap = result_capacity(Cap);
  C buffer[cap + 1]{};
  std::size_t n = 0;
  ((n = append_part(buffer, n, cap, parts)), ...);
  return iec_string<C, cap>(std::basic_string_view<C>(buffer, n));
}

template <class S>
using result_string = iec_string<char_of<S>, result_capacity(capacity_of<S>)>;

template <class S1, class S2>
concept same_char = std::is_same_v<char_of<S1>, char_of<S2>>;

}  // namespace detail

/// LEN(IN): the number of characters (as INT, like CODESYS).
template <detail::string_argument S>
[[nodiscard]] constexpr INT LEN(const S& in) noexcept {
  return static_cast<INT>(ULINT(detail::view_of(in).size()));
}

/// LEFT(IN, L): the first L characters; all of IN if L >= LEN(IN), '' if L <= 0.
template <detail::string_argument S, detail::position_argument L>
[[nodiscard]] constexpr detail::result_string<S> LEFT(const S& in, const L& l) noexcept {
  const auto v = detail::view_of(in);
  const std::int64_t n = detail::as_i64(l);
  if (n <= 0) return {};
  return detail::result_string<S>(v.substr(0, static_cast<std::size_t>(n)));
}

/// RIGHT(IN, L): the last L characters; all of IN if L >= LEN(IN), '' if L <= 0.
template <detail::string_argument S, detail::position_argument L>
[[nodiscard]] constexpr detail::result_string<S> RIGHT(const S& in, const L& l) noexcept {
  const auto v = detail::view_of(in);
  const std::int64_t n = detail::as_i64(l);
  if (n <= 0) return {};
  const std::size_t count = static_cast<std::uint64_t>(n) < v.size() ? static_cast<std::size_t>(n) : v.size();
  return detail::result_string<S>(v.substr(v.size() - count));
}

/// MID(IN, L, P): L characters starting at position P (1 = first character); fewer if IN
/// ends first; '' if P < 1, P > LEN(IN) or L <= 0.
template <detail::string_argument S, detail::position_argument L, detail::position_argument P>
[[nodiscard]] constexpr detail::result_string<S> MID(const S& in, const L& l, const P& p) noexcept {
  const auto v = detail::view_of(in);
  const std::int64_t n = detail::as_i64(l);
  const std::int64_t pos = detail::as_i64(p);
  if (n <= 0 || pos < 1 || static_cast<std::uint64_t>(pos) > v.size()) return {};
  return detail::result_string<S>(v.substr(static_cast<std::size_t>(pos - 1), static_cast<std::size_t>(n)));
}

/// CONCAT(IN1, IN2, ...): the strings one after the other (IEC's CONCAT is extensible).
template <detail::string_argument S1, detail::string_argument... Sn>
  requires(detail::same_char<S1, Sn> && ...)
[[nodiscard]] constexpr auto CONCAT(const S1& in1, const Sn&... rest) noexcept {
  constexpr std::size_t cap = (detail::capacity_of<S1> + ... + detail::capacity_of<Sn>);
  return detail::join<detail::char_of<S1>, cap>(detail::view_of(in1), detail::view_of(rest)...);
}

/// INSERT(IN1, IN2, P): IN2 inserted after position P of IN1 (P = 0: in front); IN1
/// unchanged if P < 0 or P > LEN(IN1) (CODESYS: "if POS > 255 or < 0, the result equals
/// STR1").
template <detail::string_argument S1, detail::string_argument S2, detail::position_argument P>
  requires detail::same_char<S1, S2>
[[nodiscard]] constexpr auto INSERT(const S1& in1, const S2& in2, const P& p) noexcept {
  constexpr std::size_t cap = detail::capacity_of<S1> + detail::capacity_of<S2>;
  using C = detail::char_of<S1>;
  const auto a = detail::view_of(in1);
  const std::int64_t pos = detail::as_i64(p);
  if (pos < 0 || static_cast<std::uint64_t>(pos) > a.size()) return detail::join<C, cap>(a);
  const auto at = static_cast<std::size_t>(pos);
  return detail::join<C, cap>(a.substr(0, at), detail::view_of(in2), a.substr(at));
}

/// DELETE(IN, L, P): IN without the L characters starting at position P (fewer if IN ends
/// first); IN unchanged if L <= 0, P < 1 or P > LEN(IN).
template <detail::string_argument S, detail::position_argument L, detail::position_argument P>
[[nodiscard]] constexpr detail::result_string<S> DELETE(const S& in, const L& l, const P& p) noexcept {
  using C = detail::char_of<S>;
  const auto v = detail::view_of(in);
  const std::int64_t n = detail::as_i64(l);
  const std::int64_t pos = detail::as_i64(p);
  if (n <= 0 || pos < 1 || static_cast<std::uint64_t>(pos) > v.size()) return detail::result_string<S>(v);
  const auto at = static_cast<std::size_t>(pos - 1);
  const std::size_t count = static_cast<std::uint64_t>(n) < v.size() - at ? static_cast<std::size_t>(n) : v.size() - at;
  return detail::join<C, detail::capacity_of<S>>(v.substr(0, at), v.substr(at + count));
}

/// REPLACE(IN1, IN2, L, P): IN1 with the L characters starting at position P replaced by
/// IN2 (fewer if IN1 ends first; P = LEN(IN1) + 1 appends); IN1 unchanged if L < 0,
/// P < 1 or P > LEN(IN1) + 1.
template <detail::string_argument S1, detail::string_argument S2, detail::position_argument L,
          detail::position_argument P>
  requires detail::same_char<S1, S2>
[[nodiscard]] constexpr auto REPLACE(const S1& in1, const S2& in2, const L& l, const P& p) noexcept {
  constexpr std::size_t cap = detail::capacity_of<S1> + detail::capacity_of<S2>;
  using C = detail::char_of<S1>;
  const auto a = detail::view_of(in1);
  const std::int64_t n = detail::as_i64(l);
  const std::int64_t pos = detail::as_i64(p);
  if (n < 0 || pos < 1 || static_cast<std::uint64_t>(pos) > a.size() + 1) return detail::join<C, cap>(a);
  const auto at = static_cast<std::size_t>(pos - 1);
  const std::size_t count = static_cast<std::uint64_t>(n) < a.size() - at ? static_cast<std::size_t>(n) : a.size() - at;
  return detail::join<C, cap>(a.substr(0, at), detail::view_of(in2), a.substr(at + count));
}

/// FIND(IN1, IN2): the position (1 = first character) of the first occurrence of IN2 in
/// IN1; 0 if there is none or IN2 is empty.
template <detail::string_argument S1, detail::string_argument S2>
  requires detail::same_char<S1, S2>
[[nodiscard]] constexpr INT FIND(const S1& in1, const S2& in2) noexcept {
  const auto needle = detail::view_of(in2);
  if (needle.empty()) return 0;
  const std::size_t at = detail::view_of(in1).find(needle);
  if (at == std::string_view::npos) return 0;
  return static_cast<INT>(ULINT(at + 1));
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
