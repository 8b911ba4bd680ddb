// SPDX-License-Identifier: MIT
// iecoop/types/enumeration.hpp — ST's enumerations, `TYPE E_State : (Idle, Run := 10, Fault) INT;
// END_TYPE`, as C++ enums with an IEC integer base type, and CODESYS's attributes
// 'qualified_only', 'strict' and 'to_string'.
//
// clang-format off
//     TYPE E_State : (Idle, Run := 10, Fault);   enum E_State : INT::rep { Idle, Run = 10, Fault };
//     END_TYPE                                   (Run and E_State::Run both name the component)
//     {attribute 'qualified_only'}               enum class E_Mode : INT::rep { Off, Manual, Auto };
//     TYPE E_Mode : (Off, Manual, Auto);         (only E_Mode::Manual)
//     END_TYPE
//     {attribute 'strict'}                       template <> inline constexpr bool iecoop::enum_strict<E_Mode> = true;
//     {attribute 'to_string'}                    template <> inline constexpr bool iecoop::enum_to_string<E_Mode> = true;
//     TYPE E_Valve : (Open, Closed) := Closed;   template <> inline constexpr E_Valve iecoop::enum_initial<E_Valve> = Closed;
//     (the names, for TO_STRING, printing,       template <> inline constexpr auto iecoop::enum_components<E_Mode> =
//      is_component and parse_enum)                  iecoop::components<E_Mode::Off, E_Mode::Manual, E_Mode::Auto>{};
// clang-format on
//
// * The C++ base type is the IEC base type's representation (`INT::rep`, `BYTE::rep`); an enum
//   without a base type, or with a `char` or `bool` one, is no IEC enumeration. An unsigned base
//   type is read as USINT..ULINT; `enum_base` names BYTE..LWORD instead.
// * A component reads as its base type's value (`INT i = E_State::Run;`, as CODESYS allows with
//   'strict' too); a number becomes an enumeration only through to_enum<E>(x), which 'strict'
//   rejects. Without 'strict', arithmetic on components computes in the base type, as in ST;
//   with 'strict' it does not compile.
// * A variable without an initial value starts at the type's initial value (enum_initial), else
//   at the first component, whatever its value (`(a := 5, b)` starts at 5): iecoop's variables
//   (var<E>, temp<E>, ARRAY elements, ...: detail/initial_value.hpp) read it from enum_components,
//   whose first listed component is the first declared; a plain `E e;` needs `= E::A` written.
// * The component names are not reflected over a range of values: `components<...>` lists the
//   components, each listed value's name is read from the compiler's spelling of it, and the
//   list is checked against the enumerators next to it (docs/design.md, "Enumeration names are
//   listed, and spelled by the compiler").
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/parse_result.hpp>
#include <iecoop/detail/reflect.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/types/detail/type_hash.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/literal_text.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// An enum declared with a base type (`enum E : std::int16_t`): only those can be
/// list-initialised from their base type's value (C++17).
template <class E>
concept enum_with_base = std::is_enum_v<E> && requires { E{std::underlying_type_t<E>{}}; };

template <std::size_t Bytes, bool Signed>
struct fixed_width {};
template <>
struct fixed_width<1, true> {
  using type = std::int8_t;
};
template <>
struct fixed_width<2, true> {
  using type = std::int16_t;
};
template <>
struct fixed_width<4, true> {
  using type = std::int32_t;
};
template <>
struct fixed_width<8, true> {
  using type = std::int64_t;
};
template <>
struct fixed_width<1, false> {
  using type = std::uint8_t;
};
template <>
struct fixed_width<2, false> {
  using type = std::uint16_t;
};
template <>
struct fixed_width<4, false> {
  using type = std::uint32_t;
};
template <>
struct fixed_width<8, false> {
  using type = std::uint64_t;
};

/// The IEC integer type over the C++ integer U: SINT..LINT for a signed one, USINT..ULINT for
/// an unsigned one.
template <class U>
using iec_integer_over = integer<typename fixed_width<sizeof(U), std::is_signed_v<U>>::type,
                                 std::is_signed_v<U> ? integer_kind::signed_int : integer_kind::unsigned_int>;

template <class T, class...>
struct first_type {
  using type = T;
};

}  // namespace detail

/**
 * An IEC enumeration: a C++ enum whose base type is an IEC integer type's representation
 * (`enum E_State : INT::rep { ... }`, `enum class E_Flags : BYTE::rep { ... }`). An enum without
 * a base type (C++ picks one), or with `char`, `wchar_t` or `bool`, is none.
 */
template <class E>
concept Enumeration = detail::enum_with_base<E> && detail::cpp_integer<std::underlying_type_t<E>>;

namespace detail {

template <class E>
constexpr bool require_enumeration() {
  static_assert(Enumeration<E>,
                "iecoop: an IEC enumeration is a C++ enum with an IEC integer base type; declare it with one, "
                "`enum E_State : INT::rep { ... }` (not char, wchar_t or bool, and not without a base type)");
  return Enumeration<E>;
}

template <class E, bool = Enumeration<E>>
struct default_enum_base {
  using type = void;
};
template <class E>
struct default_enum_base<E, true> {
  using type = iec_integer_over<std::underlying_type_t<E>>;
};

}  // namespace detail

/**
 * The IEC base type of the enumeration E: by default the IEC integer type of E's C++ base type
 * (`std::int16_t` is INT, `std::uint8_t` is USINT). Specialise it to name a bit string, as
 * `TYPE E_Flags : (...) BYTE; END_TYPE` does:
 *
 *     template <> struct iecoop::enum_base<E_Flags> { using type = BYTE; };
 */
template <class E>
struct enum_base {
  using type = typename detail::default_enum_base<E>::type;
};

namespace detail {
template <class E, class B = typename enum_base<E>::type>
struct checked_enum_base {
  static_assert(!Enumeration<E> ||
                    (is_integer<B>::value && sizeof(typename B::rep) == sizeof(std::underlying_type_t<E>) &&
                     std::is_signed_v<typename B::rep> == std::is_signed_v<std::underlying_type_t<E>>),
                "iecoop: enum_base<E>::type must be the IEC integer type over the enumeration's C++ base type (BYTE or "
                "USINT for std::uint8_t, WORD or UINT for std::uint16_t, ...)");
  using type = B;
};
}  // namespace detail

/// The IEC base type of the enumeration E (INT for `enum E : INT::rep`).
template <class E>
using enum_base_t = typename detail::checked_enum_base<E>::type;

/// {attribute 'strict'}: arithmetic on E and making an E of a number (to_enum) do not compile.
///
///     template <> inline constexpr bool iecoop::enum_strict<E_Mode> = true;
template <class E>
inline constexpr bool enum_strict = false;

/// {attribute 'to_string'}: TO_STRING(e) is the component's name ('Run'), not its value ('10').
/// Needs the component names (enum_components).
template <class E>
inline constexpr bool enum_to_string = false;

// ---------------------------------------------------------------------------------------
// Component names

namespace detail {

/// The compiler's spelling of the enumeration value V (from reflect.hpp's signature_of):
/// `app::E_State::Run`, `app::Run`, or `(app::E_State)12` for a value that is no enumerator.
template <auto V>
constexpr std::string_view enum_value_spelling() noexcept {
  return argument_spelling(signature_of<V>(), "Entity = ");
}

constexpr bool is_identifier(std::string_view s) noexcept {
  if (s.empty() || (s.front() >= '0' && s.front() <= '9')) return false;
  for (const char c : s) {
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
  }
  return true;
}

/// The name of the enumerator V (`Run`), or empty where V is no enumerator: the spelling's last
/// part, where it is an identifier (a cast, `(app::E_State)12`, ends in `E_State)12`).
template <auto V>
constexpr std::string_view enum_value_name() noexcept {
  constexpr std::string_view spelling = enum_value_spelling<V>();
  const std::size_t colons = spelling.rfind("::");
  const std::string_view last = colons == std::string_view::npos ? spelling : spelling.substr(colons + 2);
  return is_identifier(last) ? last : std::string_view{};
}

template <auto V, std::size_t... I>
auto spell_enum_value(std::index_sequence<I...>) -> spelled<enum_value_name<V>()[I]...>;
/// The name of the enumerator V as a spelled<> type, for diagnostics.
template <auto V>
using spelled_enum_value_t = decltype(spell_enum_value<V>(std::make_index_sequence<enum_value_name<V>().size()>{}));

/// How far beyond the listed components components<> looks for one that is not listed.
inline constexpr long long component_margin = 16;
/// The widest span between the smallest and the largest listed component that components<>
/// checks value by value; beyond it only the margins are checked.
inline constexpr long long component_span_checked = 1024;

template <class Missing>
constexpr void component_missing() {
  static_assert(dependent_false<Missing>,
                "iecoop: components<...> misses a component of the enumeration (spelled in `Missing`); list every "
                "component, in declaration order");
}

/// The arithmetic of a window of values of E's base type: in the widest C++ integer of its
/// signedness.
template <class E>
using wide_of = std::conditional_t<std::is_signed_v<std::underlying_type_t<E>>, long long, unsigned long long>;

}  // namespace detail

namespace detail {

template <auto... V>
using listed_enum_t = std::remove_cv_t<typename first_type<decltype(V)...>::type>;

template <auto... V>
inline constexpr listed_enum_t<V...> listed_values[sizeof...(V)] = {V...};

/// V... as numbers of their base type, in the widest integer of its signedness.
template <auto... V>
constexpr wide_of<listed_enum_t<V...>> listed_number(std::size_t i) noexcept {
  using U = std::underlying_type_t<listed_enum_t<V...>>;
  return static_cast<wide_of<listed_enum_t<V...>>>(static_cast<U>(listed_values<V...>[i]));
}

template <auto... V>
constexpr bool listed_once() noexcept {
  for (std::size_t i = 0; i < sizeof...(V); ++i) {
    for (std::size_t j = i + 1; j < sizeof...(V); ++j) {
      if (listed_values<V...>[i] == listed_values<V...>[j]) return false;
    }
  }
  return true;
}

template <auto... V>
constexpr bool is_listed(wide_of<listed_enum_t<V...>> v) noexcept {
  for (std::size_t i = 0; i < sizeof...(V); ++i) {
    if (listed_number<V...>(i) == v) return true;
  }
  return false;
}

template <auto... V>
constexpr wide_of<listed_enum_t<V...>> smallest_listed() noexcept {
  auto m = listed_number<V...>(0);
  for (std::size_t i = 1; i < sizeof...(V); ++i) m = listed_number<V...>(i) < m ? listed_number<V...>(i) : m;
  return m;
}
template <auto... V>
constexpr wide_of<listed_enum_t<V...>> largest_listed() noexcept {
  auto m = listed_number<V...>(0);
  for (std::size_t i = 1; i < sizeof...(V); ++i) m = listed_number<V...>(i) > m ? listed_number<V...>(i) : m;
  return m;
}

/// The first of the Count values from From on that is an enumerator but not listed, as an
/// offset, or -1.
template <class Listed, auto From, std::size_t... I>
constexpr long long first_unlisted(std::index_sequence<I...>) noexcept {
  using E = typename Listed::enum_type;
  using U = std::underlying_type_t<E>;
  using W = decltype(From);
  const bool unlisted[] = {false,
                           (!Listed::holds(From + static_cast<W>(I)) &&
                            !enum_value_name<static_cast<E>(static_cast<U>(From + static_cast<W>(I)))>().empty())...};
  for (std::size_t i = 1; i < sizeof(unlisted) / sizeof(unlisted[0]); ++i) {
    if (unlisted[i]) return static_cast<long long>(i - 1);
  }
  return -1;
}

template <class Listed, auto From, std::size_t Count>
constexpr bool no_enumerator_unlisted() noexcept {
  using E = typename Listed::enum_type;
  using U = std::underlying_type_t<E>;
  using W = decltype(From);
  constexpr long long at = first_unlisted<Listed, From>(std::make_index_sequence<Count>{});
  if constexpr (at >= 0) {
    component_missing<spelled_enum_value_t<static_cast<E>(static_cast<U>(From + static_cast<W>(at)))>>();
  }
  return at < 0;
}

/// Checks that no enumerator near the listed ones is left out: within component_margin below
/// and above them, and between them where they span at most component_span_checked values.
template <auto... V>
struct listed_components {
  using enum_type = listed_enum_t<V...>;
  using U = std::underlying_type_t<enum_type>;
  using W = wide_of<enum_type>;
  static constexpr bool holds(W v) noexcept { return is_listed<V...>(v); }

  static constexpr W low = smallest_listed<V...>();
  static constexpr W high = largest_listed<V...>();
  static constexpr W margin = static_cast<W>(component_margin);
  static constexpr W lowest = low >= static_cast<W>(std::numeric_limits<U>::min()) + margin
                                  ? low - margin
                                  : static_cast<W>(std::numeric_limits<U>::min());
  static constexpr W highest = high <= static_cast<W>(std::numeric_limits<U>::max()) - margin
                                   ? high + margin
                                   : static_cast<W>(std::numeric_limits<U>::max());
  // high - low <= component_span_checked, without computing high - low (it may not fit W).
  static constexpr bool whole_span = low > std::numeric_limits<W>::max() - static_cast<W>(component_span_checked) ||
                                     high <= low + static_cast<W>(component_span_checked);
  static constexpr std::size_t between() noexcept {
    if constexpr (whole_span) {
      return static_cast<std::size_t>(high - low);
    } else {
      return 0;
    }
  }
};

template <auto... V>
constexpr bool none_left_out() noexcept {
  using L = listed_components<V...>;
  using W = typename L::W;
  constexpr std::size_t below = static_cast<std::size_t>(L::low - L::lowest);
  constexpr std::size_t between = L::between();
  constexpr std::size_t above = static_cast<std::size_t>(L::highest - L::high);
  return no_enumerator_unlisted<L, L::lowest, below>() && no_enumerator_unlisted<L, L::low, between>() &&
         no_enumerator_unlisted<L, L::high + (above > 0 ? W{1} : W{0}), above>();
}

}  // namespace detail

/**
 * The components of an enumeration, listed in declaration order: `components<Idle, Run, Fault>`.
 * What iecoop knows of an enumeration's names comes from this list (declare it as
 * `enum_components<E>`): each listed value's name is the compiler's spelling of it, so a name
 * cannot be misspelt. Checked while compiling: every value is an enumerator of one
 * enumeration, none is listed twice, and no enumerator within 16 values of the listed ones
 * (or between them, where they span at most 1024 values) is left out.
 */
template <auto... V>
struct components {
  static_assert(sizeof...(V) > 0, "iecoop: components<...> lists at least one component");
  using enum_type = detail::listed_enum_t<V...>;
  static_assert((std::is_same_v<std::remove_cv_t<decltype(V)>, enum_type> && ...),
                "iecoop: components<...> lists the components of one enumeration; list only values of that type");
  static_assert(detail::require_enumeration<enum_type>());
  static_assert((!detail::enum_value_name<V>().empty() && ...),
                "iecoop: components<...> lists a value that is no component of the enumeration (a number cast to "
                "it); list its enumerators only");
  static_assert(detail::listed_once<V...>(),
                "iecoop: components<...> lists a component twice (or two components of one value); list each value "
                "once");
  static_assert(detail::none_left_out<V...>());

  static constexpr std::size_t size = sizeof...(V);
  static constexpr enum_type values[sizeof...(V)] = {V...};
  static constexpr std::string_view names[sizeof...(V)] = {detail::enum_value_name<V>()...};
};

/// No components declared (what enum_components<E> is unless it is specialised).
struct no_components {};

/**
 * The components of the enumeration E, for its names (printing, TO_STRING with 'to_string'),
 * is_component and parse_enum. Declare them once, after the enumeration:
 *
 *     template <> inline constexpr auto iecoop::enum_components<E_State> = iecoop::components<Idle, Run, Fault>{};
 */
template <class E>
inline constexpr no_components enum_components{};

/// No initial value declared for the type (what enum_initial<E> is unless it is specialised).
struct no_initial {};

/**
 * The type's initial value, ST's `TYPE E_State : (Idle, Run, Fault) := Run; END_TYPE`: what a
 * variable of E starts at where its declaration gives none. Declare it once, after the
 * enumeration:
 *
 *     template <> inline constexpr E_State iecoop::enum_initial<E_State> = Run;
 *
 * Without it such a variable starts at E's first component, the first of enum_components<E>
 * (CODESYS: "initialization is automatically performed with the top member").
 */
template <class E>
inline constexpr no_initial enum_initial{};

namespace detail {

/// The IEC base type of an IEC enumeration, for integer<>'s conversion (types/elementary.hpp).
template <Enumeration E>
struct enum_base_of<E> {
  using type = enum_base_t<E>;
};

/// The name of an enumeration is its own (`E_State`), without namespaces.
template <Enumeration E>
struct iec_name<E> {
  static constexpr std::string_view value = short_type_name<E>();
};

template <class E>
inline constexpr bool has_components = !std::is_same_v<std::remove_cv_t<decltype(enum_components<E>)>, no_components>;

template <class E>
constexpr void require_components() {
  static_assert(has_components<E>,
                "iecoop: the components of this enumeration are not declared, so its names are not known; declare "
                "them: template <> inline constexpr auto iecoop::enum_components<E> = iecoop::components<E::A, "
                "E::B>{};");
}

template <class E>
using components_of = std::remove_cv_t<decltype(enum_components<E>)>;

/// The index of e in E's components, or -1 (E has its components declared).
template <class E>
constexpr long long component_index(E e) noexcept {
  using list = components_of<E>;
  static_assert(std::is_same_v<typename list::enum_type, E>,
                "iecoop: enum_components<E> lists the components of another enumeration; list E's");
  for (std::size_t i = 0; i < list::size; ++i) {
    if (list::values[i] == e) return static_cast<long long>(i);
  }
  return -1;
}

}  // namespace detail

namespace detail {

template <class E>
inline constexpr bool has_initial = !std::is_same_v<std::remove_cv_t<decltype(enum_initial<E>)>, no_initial>;

/// What a variable of E starts at is known: E's initial value or its components are declared.
template <class E>
inline constexpr bool knows_enum_start = has_initial<E> || has_components<E>;

/// A variable of T starts as ST says without an initial value of its own: T is no enumeration,
/// or iecoop knows the enumeration's start (and enum_initial<T>, if declared, is a T).
template <class T>
constexpr bool enum_start_declared() noexcept {
  if constexpr (!std::is_enum_v<T>) {
    return true;
  } else if constexpr (has_initial<T>) {
    return std::is_same_v<std::remove_cv_t<decltype(enum_initial<T>)>, T>;
  } else {
    return has_components<T>;
  }
}

/// E's start where it is declared, else E{} (the refusal is reported where the variable is made).
template <class E>
constexpr E enum_start_or_zero() noexcept;

/// Refuses a variable of Enum declared without an initial value where iecoop does not know
/// Enum's start. Called by each variable's constructor for an enumeration (one step from the
/// user's declaration, so that the report names it), and by enum_start.
template <class Enum>
constexpr void refuse_unknown_enum_start() noexcept {
  if constexpr (!enum_start_declared<Enum>()) {
    static_assert(!has_initial<Enum>,
                  "iecoop: enum_initial<E> is one of E's components; declare it as "
                  "`template <> inline constexpr E iecoop::enum_initial<E> = E::A;`");
    static_assert(has_initial<Enum>,
                  "iecoop: a variable of an enumeration starts at its first component in ST, which iecoop knows only "
                  "from the enumeration's declared components (the enumeration is `Enum`); declare them, first "
                  "component first: template <> inline constexpr auto iecoop::enum_components<E> = "
                  "iecoop::components<E::A, E::B>{}; (or the type's initial value, enum_initial<E>), or give the "
                  "variable its initial value");
  }
}

/// ST's initial value of a variable of the enumeration E declared without one: E's declared
/// initial value (enum_initial<E>), else its first component (enum_components<E>).
template <class E>
constexpr E enum_start() noexcept {
  if constexpr (!enum_start_declared<E>()) {
    refuse_unknown_enum_start<E>();
    return E{};
  } else if constexpr (has_initial<E>) {
    return enum_initial<E>;
  } else {
    static_assert(std::is_same_v<typename components_of<E>::enum_type, E>,
                  "iecoop: enum_components<E> lists the components of another enumeration; list E's");
    return components_of<E>::values[0];
  }
}

template <class E>
constexpr E enum_start_or_zero() noexcept {
  if constexpr (enum_start_declared<E>()) {
    return enum_start<E>();
  } else {
    return E{};
  }
}

}  // namespace detail

/// TRUE where e is one of E's declared components (a value made of a number may be none).
template <Enumeration E>
[[nodiscard]] constexpr BOOL is_component(E e) noexcept {
  detail::require_components<E>();
  if constexpr (detail::has_components<E>) {
    return BOOL(detail::component_index(e) >= 0);
  } else {
    return FALSE;
  }
}

/// The name of the component e (`Run`), or empty where e is none.
template <Enumeration E>
[[nodiscard]] constexpr std::string_view component_name(E e) noexcept {
  detail::require_components<E>();
  if constexpr (detail::has_components<E>) {
    const long long i = detail::component_index(e);
    return i < 0 ? std::string_view{} : detail::components_of<E>::names[static_cast<std::size_t>(i)];
  } else {
    return {};
  }
}

// ---------------------------------------------------------------------------------------
// Numbers into enumerations

namespace detail {
template <class E>
constexpr void not_strict_from_number() {
  static_assert(!enum_strict<E>,
                "iecoop: {attribute 'strict'} forbids making an enumeration of a number; assign one of its "
                "components (E_State::Run), or drop enum_strict<E>");
}

/// A C++ integer as a value of the IEC integer type T: out of range it reports
/// fault_kind::invalid_value and keeps the low bytes (as a call's argument does).
template <class T, class C>
constexpr T checked_integer(C c) {
  using rep = typename T::rep;
  if (!std::in_range<rep>(c)) {
    fault(fault_kind::invalid_value,
          "a C++ integer out of range for an enumeration's base type; the low bytes are kept");
  }
  return T(static_cast<rep>(c));
}
}  // namespace detail

/**
 * ST's `eState := iValue;` (without 'strict'): the enumeration E holding the value x, a value
 * of an IEC integer type that converts implicitly to E's base type (or a C++ integer, checked
 * at run time). The value need not be a component (is_component tells). With 'strict' it does
 * not compile.
 */
template <class E, class X>
[[nodiscard]] constexpr E to_enum(const X& x) {
  detail::require_enumeration<E>();
  detail::not_strict_from_number<E>();
  if constexpr (Enumeration<E>) {
    using B = enum_base_t<E>;
    using U = std::underlying_type_t<E>;
    if constexpr (detail::cpp_integer<X>) {
      return static_cast<E>(static_cast<U>(detail::checked_integer<B>(x).value()));
    } else {
      const B value = x;  // only what converts to the base type implicitly (an INT into an INT, a SINT into an INT)
      return static_cast<E>(static_cast<U>(value.value()));
    }
  } else {
    return E{};
  }
}

// ---------------------------------------------------------------------------------------
// Text

namespace detail {
template <class E>
constexpr std::size_t longest_component_name() noexcept {
  std::size_t n = 0;
  if constexpr (has_components<E>) {
    for (const std::string_view name : components_of<E>::names) n = name.size() > n ? name.size() : n;
  }
  return n;
}
}  // namespace detail

template <Enumeration E>
inline constexpr std::size_t max_text_length<E> = detail::longest_component_name<E>() > max_text_length<enum_base_t<E>>
                                                      ? detail::longest_component_name<E>()
                                                      : max_text_length<enum_base_t<E>>;

/// The component's name (`Run`) where E's components are declared and e is one, else its value
/// as its base type writes it (`12`).
template <Enumeration E>
constexpr char* to_text(char* out, E e) noexcept {
  if constexpr (detail::has_components<E>) {
    const std::string_view name = component_name(e);
    if (!name.empty()) return detail::write(out, name);
  }
  return to_text(out, enum_base_t<E>(e));
}

/**
 * Parses a value of the enumeration E: a component's name (`Run`, in any case, as ST's names
 * are), qualified as ST (`E_State.Run`) or as an IEC literal (`E_State#Run`), or a number of the
 * base type (`10`, `INT#10`, `16#A`), which need not be a component. A name needs E's declared
 * components; an unknown one gives parse_error::unknown_component.
 */
template <Enumeration E>
[[nodiscard]] constexpr parse_result<E> parse_enum(std::string_view text) noexcept {
  using B = enum_base_t<E>;
  using U = std::underlying_type_t<E>;
  if (text.empty()) return {parse_error::empty, 0};
  const auto number = [&]() -> parse_result<E> {
    const parse_result<B> n = parse_integer<B>(text);
    if (!n) return {n.error(), n.position()};
    return static_cast<E>(static_cast<U>(n.value_or(B{}).value()));
  };
  const char first = text.front();
  if (detail::is_digit(first) || first == '-' || first == '+') return number();
  std::size_t at = 0;
  const std::size_t mark = text.find_first_of("#.");
  if (mark != std::string_view::npos) {
    const std::string_view prefix = text.substr(0, mark);
    if (text[mark] == '#' && detail::iequals(prefix, detail::iec_name<B>::value)) return number();
    if (!detail::iequals(prefix, detail::iec_name<E>::value)) return {parse_error::wrong_prefix, 0};
    at = mark + 1;
  }
  const std::string_view name = text.substr(at);
  if (name.empty()) return {parse_error::no_value, at};
  if constexpr (detail::has_components<E>) {
    using list = detail::components_of<E>;
    for (std::size_t i = 0; i < list::size; ++i) {
      if (detail::iequals(list::names[i], name)) return list::values[i];
    }
  }
  return {parse_error::unknown_component, at};
}

// ---------------------------------------------------------------------------------------
// Arithmetic (without 'strict')

namespace detail {

/// An enumeration declared to iecoop: its components, 'strict' or 'to_string' are declared.
/// Only those take ST's arithmetic: with every C++ enum, `using namespace iecoop;` would reach
/// the flags of other libraries' code (fmt's, the standard library's).
template <class E>
concept declared_enumeration = Enumeration<E> && (has_components<E> || enum_strict<E> || enum_to_string<E>);

template <class X>
concept enum_partner = Enumeration<X> || int_value<X> || cpp_integer<X>;
/// An operation with a declared enumeration's component: ST computes it in the base type,
/// unless the enumeration is 'strict'.
template <class A, class B>
concept enum_arithmetic = (declared_enumeration<A> || declared_enumeration<B>)&&enum_partner<A> && enum_partner<B>;

template <class A, class B = A>
constexpr void not_strict_arithmetic() {
  static_assert(!(enum_strict<A> || enum_strict<B>),
                "iecoop: {attribute 'strict'} forbids arithmetic with an enumeration; compute with its base type's "
                "value, TO_INT(e) or INT(e), or drop enum_strict<E>");
}

/// An operand of an enumeration's arithmetic as an IEC value: a component as its base type's
/// value, a C++ integer as a value of that type (checked at run time), anything else itself.
template <class Other, class X>
constexpr auto enum_operand(const X& x) {
  if constexpr (Enumeration<X>) {
    return enum_base_t<X>(x);
  } else if constexpr (cpp_integer<X>) {
    return checked_integer<enum_base_t<Other>>(x);
  } else {
    return x;
  }
}

}  // namespace detail

// `eState + 1`, `E_Flags.A OR eFlags`: without 'strict', ST computes with a component as a value
// of its base type (the result is an intermediate result of that type, as INT arithmetic is);
// with 'strict' these do not compile. For the enumerations declared to iecoop (components,
// 'strict' or 'to_string'; see declared_enumeration). C++ finds these operators where `using namespace iecoop;`
// is in effect (an enum's own namespace is not iecoop); elsewhere an `enum class` has no
// arithmetic at all, and a plain enum computes as a C++ int. (enable_if rather than requires:
// Clang 14 substitutes into the return type before it checks a requires-clause.)
template <class A, class B, std::enable_if_t<detail::enum_arithmetic<A, B>, int> = 0>
constexpr auto operator+(const A& a, const B& b) -> decltype(detail::enum_operand<B>(a) + detail::enum_operand<A>(b)) {
  detail::not_strict_arithmetic<A, B>();
  return detail::enum_operand<B>(a) + detail::enum_operand<A>(b);
}
template <class A, class B, std::enable_if_t<detail::enum_arithmetic<A, B>, int> = 0>
constexpr auto operator-(const A& a, const B& b) -> decltype(detail::enum_operand<B>(a) - detail::enum_operand<A>(b)) {
  detail::not_strict_arithmetic<A, B>();
  return detail::enum_operand<B>(a) - detail::enum_operand<A>(b);
}
template <class A, class B, std::enable_if_t<detail::enum_arithmetic<A, B>, int> = 0>
constexpr auto operator*(const A& a, const B& b) -> decltype(detail::enum_operand<B>(a) * detail::enum_operand<A>(b)) {
  detail::not_strict_arithmetic<A, B>();
  return detail::enum_operand<B>(a) * detail::enum_operand<A>(b);
}
template <class A, class B, std::enable_if_t<detail::enum_arithmetic<A, B>, int> = 0>
constexpr auto operator/(const A& a, const B& b) -> decltype(detail::enum_operand<B>(a) / detail::enum_operand<A>(b)) {
  detail::not_strict_arithmetic<A, B>();
  return detail::enum_operand<B>(a) / detail::enum_operand<A>(b);
}
template <class A, class B, std::enable_if_t<detail::enum_arithmetic<A, B>, int> = 0>
constexpr auto operator%(const A& a, const B& b) -> decltype(detail::enum_operand<B>(a) % detail::enum_operand<A>(b)) {
  detail::not_strict_arithmetic<A, B>();
  return detail::enum_operand<B>(a) % detail::enum_operand<A>(b);
}
template <class A, class B, std::enable_if_t<detail::enum_arithmetic<A, B>, int> = 0>
constexpr auto operator&(const A& a, const B& b) -> decltype(detail::enum_operand<B>(a) & detail::enum_operand<A>(b)) {
  detail::not_strict_arithmetic<A, B>();
  return detail::enum_operand<B>(a) & detail::enum_operand<A>(b);
}
template <class A, class B, std::enable_if_t<detail::enum_arithmetic<A, B>, int> = 0>
constexpr auto operator|(const A& a, const B& b) -> decltype(detail::enum_operand<B>(a) | detail::enum_operand<A>(b)) {
  detail::not_strict_arithmetic<A, B>();
  return detail::enum_operand<B>(a) | detail::enum_operand<A>(b);
}
template <class A, class B, std::enable_if_t<detail::enum_arithmetic<A, B>, int> = 0>
constexpr auto operator^(const A& a, const B& b) -> decltype(detail::enum_operand<B>(a) ^ detail::enum_operand<A>(b)) {
  detail::not_strict_arithmetic<A, B>();
  return detail::enum_operand<B>(a) ^ detail::enum_operand<A>(b);
}
template <class E, std::enable_if_t<detail::declared_enumeration<E>, int> = 0>
constexpr auto operator-(E e) -> decltype(-enum_base_t<E>(e)) {
  detail::not_strict_arithmetic<E>();
  return -enum_base_t<E>(e);
}
template <class E, std::enable_if_t<detail::declared_enumeration<E>, int> = 0>
constexpr auto operator~(E e) -> decltype(~enum_base_t<E>(e)) {
  detail::not_strict_arithmetic<E>();
  return ~enum_base_t<E>(e);
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
