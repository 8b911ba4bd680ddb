// SPDX-License-Identifier: MIT
// iecoop/types/string.hpp — STRING(n) and WSTRING(n): fixed capacity, inline storage, never
// allocates, truncates on the right like CODESYS.
#pragma once

#include <compare>
#include <concepts>
#include <cstddef>
#include <string_view>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/any_field.hpp>
#include <iecoop/detail/iec_value.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

template <class CharT, std::size_t N>
class iec_string;

namespace detail {
template <class T>
struct is_iec_string : std::false_type {};
template <class C, std::size_t N>
struct is_iec_string<iec_string<C, N>> : std::true_type {};
template <class C, std::size_t N>
struct is_iec_value<iec_string<C, N>> : std::true_type {};

/// Text of character type C other than an iec_string: string literals, pointers to
/// NUL-terminated text, std::basic_string, std::basic_string_view.
template <class S, class C>
concept string_like =
    !is_iec_string<std::remove_cvref_t<S>>::value && !std::is_same_v<std::remove_cvref_t<S>, any_field> &&
    std::is_convertible_v<const S&, std::basic_string_view<C>>;

/// Whether the NUL-terminated text `a` is the text `b`, in one pass over both: no length
/// measured first and no memcmp (a firmware image that compares names then links neither
/// strlen nor memcmp; docs/embedded.md, "Sizes"). `b` a NUL-terminated text (nullptr: the
/// empty one) ...
template <class C>
constexpr bool same_text(const C* a, const C* b) noexcept {
  if (b == nullptr) return *a == C{};
  for (; *a == *b; ++a, ++b) {
    if (*a == C{}) return true;
  }
  return false;
}
/// ... or a view, which may hold a NUL (then it is not a NUL-terminated text's).
template <class C>
constexpr bool same_text(const C* a, std::basic_string_view<C> b) noexcept {
  for (const C c : b) {
    if (*a == C{} || *a != c) return false;
    ++a;
  }
  return *a == C{};
}
}  // namespace detail

/**
 * An IEC string of at most N characters, stored inline and NUL-terminated exactly as
 * CODESYS stores STRING(N): N + 1 code units, no length field, no heap. Use the aliases
 * `STRING<N>` (char, Latin-1/UTF-8 bytes; `STRING<>` is STRING(80)) and `WSTRING<N>`
 * (char16_t, UCS-2).
 *
 * Assigning longer text keeps the first N characters, as CODESYS does. Strings of any
 * capacity, literals, std::string and std::string_view assign and compare with each other;
 * comparison is lexicographic by code unit (unsigned).
 *
 *     STRING<12> name = "conveyor belt one";  // "conveyor bel"
 *     if (name == "conveyor bel") ...
 *     std::string_view v = name;              // no copy
 */
template <class CharT, std::size_t N>
class iec_string {
  static_assert(N >= 1, "iecoop: a STRING needs a capacity of at least 1 character; write STRING<1> or more");

 public:
  using char_type = CharT;
  using view_type = std::basic_string_view<CharT>;
  using size_type = std::size_t;
  using iterator = const CharT*;
  using const_iterator = const CharT*;

  /// The capacity N: the most characters the string holds.
  static constexpr size_type capacity() noexcept { return N; }

  constexpr iec_string() noexcept = default;

  /// From a NUL-terminated string; nullptr gives the empty string.
  constexpr iec_string(const CharT* text) noexcept { assign(text); }  // implicit: like ST's assignment
  /// From literals, std::basic_string, std::basic_string_view: keeps the first N characters.
  template <detail::string_like<CharT> S>
    requires(!std::is_pointer_v<S>)
  constexpr iec_string(const S& text) noexcept {  // implicit on purpose
    assign(view_type(text));
  }
  /// From a string of another capacity: keeps the first N characters.
  template <std::size_t M>
    requires(M != N)
  constexpr iec_string(const iec_string<CharT, M>& other) noexcept {  // implicit on purpose
    assign(other.c_str());
  }

  /// Replaces the contents with (the first N characters of) `text`. `text` may point into
  /// this string.
  constexpr iec_string& assign(view_type text) noexcept {
    const size_type n = text.size() < N ? text.size() : N;
    // Forward copy: a view into this string never starts before chars_, so this is safe.
    for (size_type i = 0; i < n; ++i) chars_[i] = text[i];
    chars_[n] = CharT{};
    return *this;
  }
  /// The same from NUL-terminated text (nullptr: the empty string), read once: up to its NUL
  /// or its N-th character, without measuring its length first.
  constexpr iec_string& assign(const CharT* text) noexcept {
    size_type n = 0;
    if (text != nullptr) {
      // (a view into this string is safe here too: each character is read before it is written)
      for (; n < N && text[n] != CharT{}; ++n) chars_[n] = text[n];
    }
    chars_[n] = CharT{};
    return *this;
  }

  [[nodiscard]] constexpr size_type size() const noexcept { return std::char_traits<CharT>::length(chars_); }
  [[nodiscard]] constexpr size_type length() const noexcept { return size(); }
  [[nodiscard]] constexpr bool empty() const noexcept { return chars_[0] == CharT{}; }

  [[nodiscard]] constexpr const CharT* data() const noexcept { return chars_; }
  [[nodiscard]] constexpr const CharT* c_str() const noexcept { return chars_; }
  [[nodiscard]] constexpr view_type view() const noexcept { return view_type(chars_, size()); }
  constexpr operator view_type() const noexcept { return view(); }  // implicit: a string is its text

  [[nodiscard]] constexpr const CharT* begin() const noexcept { return chars_; }
  [[nodiscard]] constexpr const CharT* end() const noexcept { return chars_ + size(); }
  /// The character at 0-based `index` (which must be below size()).
  [[nodiscard]] constexpr CharT operator[](size_type index) const noexcept { return chars_[index]; }

 private:
  CharT chars_[N + 1]{};
};

/// IEC STRING(N); `STRING<>` is CODESYS's default STRING(80).
template <std::size_t N = 80>
using STRING = iec_string<char, N>;
/// IEC WSTRING(N) (UCS-2); `WSTRING<>` is WSTRING(80).
template <std::size_t N = 80>
using WSTRING = iec_string<char16_t, N>;

/// STRING(N) or WSTRING(N) of any capacity (IEC ANY_STRING).
template <class T>
concept AnyString = detail::is_iec_string<T>::value;

namespace detail {
/// What an iec_string compares with: another of any capacity, a literal or a std string.
template <class S, class C>
concept string_comparand = is_iec_string<S>::value || string_like<S, C>;
/// The same on the left of an iec_string, other than an iec_string (that one is the other
/// operator's left operand). A constant, not a concept built on string_comparand: a
/// constraint that subsumes the other would make C++ prefer the reversed candidate of
/// `s == "abc"`, which must return bool.
template <class S, class C>
inline constexpr bool string_left_comparand_v = string_like<S, C>;

template <class C, std::size_t N, class S>
constexpr int compare_strings(const iec_string<C, N>& a, const S& b) noexcept {
  return a.view().compare(std::basic_string_view<C>(b));
}
/// Whether `a` holds the text `b` (another iec_string, a NUL-terminated text or a view).
template <class C, std::size_t N, class S>
constexpr bool equal_strings(const iec_string<C, N>& a, const S& b) noexcept {
  if constexpr (is_iec_string<S>::value) {
    return same_text(a.c_str(), b.c_str());
  } else if constexpr (std::is_convertible_v<const S&, const C*>) {  // literals, pointers
    return same_text(a.c_str(), static_cast<const C*>(b));
  } else {
    return same_text(a.c_str(), std::basic_string_view<C>(b));
  }
}
}  // namespace detail

// Comparison of an iec_string with another of any capacity, a literal or a std string: a
// BOOL, as in ST.
template <class C, std::size_t N, class S>
  requires detail::string_comparand<S, C>
constexpr BOOL operator==(const iec_string<C, N>& a, const S& b) noexcept {
  return BOOL(detail::equal_strings(a, b));
}
template <class C, std::size_t N, class S>
  requires detail::string_comparand<S, C>
constexpr BOOL operator!=(const iec_string<C, N>& a, const S& b) noexcept {
  return BOOL(!detail::equal_strings(a, b));
}
template <class C, std::size_t N, class S>
  requires detail::string_comparand<S, C>
constexpr BOOL operator<(const iec_string<C, N>& a, const S& b) noexcept {
  return BOOL(detail::compare_strings(a, b) < 0);
}
template <class C, std::size_t N, class S>
  requires detail::string_comparand<S, C>
constexpr BOOL operator<=(const iec_string<C, N>& a, const S& b) noexcept {
  return BOOL(detail::compare_strings(a, b) <= 0);
}
template <class C, std::size_t N, class S>
  requires detail::string_comparand<S, C>
constexpr BOOL operator>(const iec_string<C, N>& a, const S& b) noexcept {
  return BOOL(detail::compare_strings(a, b) > 0);
}
template <class C, std::size_t N, class S>
  requires detail::string_comparand<S, C>
constexpr BOOL operator>=(const iec_string<C, N>& a, const S& b) noexcept {
  return BOOL(detail::compare_strings(a, b) >= 0);
}
template <class C, std::size_t N, class S>
  requires detail::string_comparand<S, C>
constexpr std::strong_ordering operator<=>(const iec_string<C, N>& a, const S& b) noexcept {
  return detail::compare_strings(a, b) <=> 0;
}
// The same with the literal or std string on the left (`'abc' = s`).
template <class S, class C, std::size_t N>
  requires detail::string_left_comparand_v<S, C>
constexpr BOOL operator==(const S& a, const iec_string<C, N>& b) noexcept {
  return BOOL(detail::equal_strings(b, a));
}
template <class S, class C, std::size_t N>
  requires detail::string_left_comparand_v<S, C>
constexpr BOOL operator!=(const S& a, const iec_string<C, N>& b) noexcept {
  return BOOL(!detail::equal_strings(b, a));
}
template <class S, class C, std::size_t N>
  requires detail::string_left_comparand_v<S, C>
constexpr BOOL operator<(const S& a, const iec_string<C, N>& b) noexcept {
  return BOOL(detail::compare_strings(b, a) > 0);
}
template <class S, class C, std::size_t N>
  requires detail::string_left_comparand_v<S, C>
constexpr BOOL operator<=(const S& a, const iec_string<C, N>& b) noexcept {
  return BOOL(detail::compare_strings(b, a) >= 0);
}
template <class S, class C, std::size_t N>
  requires detail::string_left_comparand_v<S, C>
constexpr BOOL operator>(const S& a, const iec_string<C, N>& b) noexcept {
  return BOOL(detail::compare_strings(b, a) < 0);
}
template <class S, class C, std::size_t N>
  requires detail::string_left_comparand_v<S, C>
constexpr BOOL operator>=(const S& a, const iec_string<C, N>& b) noexcept {
  return BOOL(detail::compare_strings(b, a) <= 0);
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
