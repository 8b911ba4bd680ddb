// SPDX-License-Identifier: MIT
// iecoop/types/array.hpp — ARRAY with IEC bounds: `ARRAY[1..10] OF INT` is ARRAY<INT, 1, 10>,
// `ARRAY[-5..5, 0..2] OF REAL` is ARRAY<REAL, -5, 5, 0, 2>, `ARRAY[*] OF INT` (VAR_IN_OUT only)
// is in_out<ARRAY<INT, '*'>>.
//
// An ARRAY is an aggregate around one built-in array (no std::array: GCC 12 cannot bound a
// loop over one and keeps every loop variable in memory), as large as CODESYS stores it,
// its elements starting at their type's initial value like every PLC variable (0, and an
// enumeration's first component), trivially copyable when its elements are.
// Multi-dimensional arrays are stored row by row (the last index varies fastest), as in
// CODESYS, so `[1, 2, 3, 4]` fills a[1,1], a[1,2], a[2,1], a[2,2] of an ARRAY[1..2, 1..2].
//
// An index outside the bounds is a fault (fault_kind::array_bounds), after which the access
// goes to the nearest bound's element — what CODESYS's implicit CheckBounds function does.
// Define IECOOP_CHECK_BOUNDS=0 for the whole build (CMake: -DIECOOP_CHECK_BOUNDS=OFF) to
// drop the check, as a CODESYS project without CheckBounds does: an index out of range is
// then undefined behaviour. docs/performance.md has the check's cost.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/types/detail/initial_value.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

#if !defined(IECOOP_CHECK_BOUNDS)
#define IECOOP_CHECK_BOUNDS 1
#endif

namespace iecoop {

/// Whether an ARRAY checks its indices (CODESYS: whether the project has CheckBounds).
enum class array_check : bool {
  none,    ///< no check: an index out of range is undefined behaviour, as in C
  bounds,  ///< an index out of range is a fault, then the nearest bound's element is used
};

/// The check every ARRAY<> makes: set for the whole build with IECOOP_CHECK_BOUNDS.
inline constexpr array_check default_array_check = IECOOP_CHECK_BOUNDS ? array_check::bounds : array_check::none;

template <array_check Check, class T, auto... Bounds>
struct basic_array;

/// ST's `ARRAY[l1..u1, l2..u2, ...] OF T`: the bounds as pairs, lower then upper.
///
///     ARRAY<INT, 1, 10> aiValues;               // aiValues : ARRAY[1..10] OF INT;
///     ARRAY<REAL, -5, 5, 0, 2> arGrid;          // arGrid : ARRAY[-5..5, 0..2] OF REAL;
///     ARRAY<TON, 1, 8> aTimers;                 // aTimers : ARRAY[1..8] OF TON;
///     ARRAY<INT, 1, 5> aiInit{1, 2, 3};         // := [1, 2, 3] (the rest 0)
///     aiValues[i] = aiValues[i - 1] + 1;        // an element; arGrid(i, j) for arGrid[i, j]
template <class T, auto... Bounds>
using ARRAY = basic_array<default_array_check, T, Bounds...>;

namespace detail {

/// The type of ARRAY bounds: CODESYS allows the range of DINT.
using array_bound = std::int32_t;
/// An index converted for comparing it with the bounds.
using array_index = std::int64_t;

template <class B>
inline constexpr bool is_bound_type = cpp_integer<B> && !std::is_same_v<B, char>;

template <auto... B>
struct array_shape {
  static constexpr std::size_t rank = sizeof...(B) / 2;
  static constexpr bool star = sizeof...(B) > 0 && (std::is_same_v<decltype(B), char> && ...) && ((B == '*') && ...);
  static constexpr bool integers = (is_bound_type<decltype(B)> && ...);
  static constexpr bool in_dint = [] {
    if constexpr (integers) {
      return (std::in_range<array_bound>(B) && ...);
    } else {
      return false;
    }
  }();
  static constexpr array_index all[sizeof...(B) + 1] = {static_cast<array_index>(B)..., 0};
  static constexpr bool ordered = [] {
    for (std::size_t d = 0; d < rank; ++d) {
      if (all[2 * d] > all[2 * d + 1]) return false;
    }
    return true;
  }();
  static constexpr array_index lower(std::size_t d) noexcept { return all[2 * d]; }
  static constexpr array_index upper(std::size_t d) noexcept { return all[2 * d + 1]; }
  static constexpr array_index extent(std::size_t d) noexcept { return upper(d) - lower(d) + 1; }
  static constexpr std::size_t size = [] {
    std::size_t n = 1;
    for (std::size_t d = 0; d < rank; ++d) n *= static_cast<std::size_t>(extent(d));
    return n;
  }();
};

/// The type an index must have: an IEC or C++ integer, an intermediate result, an
/// enumeration, or a variable wrapper of one.
template <class I>
concept array_index_value = cpp_integer<unwrapped_t<I>> || is_integer<unwrapped_t<I>>::value ||
                            is_intermediate<unwrapped_t<I>>::value || std::is_enum_v<unwrapped_t<I>>;

/// An index's value, wide enough to compare with any bound (a ULINT beyond LINT's range
/// saturates: it is out of every ARRAY's range anyway).
template <class I>
constexpr array_index index_value(const I& index) {
  const auto& v = value_of(index);
  using V = std::remove_cvref_t<decltype(v)>;
  if constexpr (std::is_enum_v<V>) {
    return static_cast<array_index>(static_cast<std::underlying_type_t<V>>(v));
  } else if constexpr (cpp_integer<V>) {
    if constexpr (std::is_unsigned_v<V> && sizeof(V) >= sizeof(array_index)) {
      return v > static_cast<V>(std::numeric_limits<array_index>::max()) ? std::numeric_limits<array_index>::max()
                                                                         : static_cast<array_index>(v);
    } else {
      return static_cast<array_index>(v);
    }
  } else {
    return index_value(v.value());
  }
}

template <class I>
constexpr void check_index_type() {
  static_assert(array_index_value<I>,
                "iecoop: an ARRAY index is an integer (ANY_INT, an enumeration or a C++ integer); convert it, "
                "e.g. REAL_TO_DINT(r)");
}

/// CODESYS's CheckBounds: reports an index outside [lower, upper] and returns the nearest
/// bound, else the index.
inline array_index out_of_bounds(array_index index, array_index lower, array_index upper) {
  fault(fault_kind::array_bounds, "ARRAY index outside its bounds; the nearest bound's element is used");
  return index < lower ? lower : upper;
}

/// The offset of `index` in a dimension from `lower` with `extent` elements.
template <array_check Check>
constexpr std::size_t offset_in(array_index index, array_index lower, array_index extent) {
  if constexpr (Check == array_check::bounds) {
    // One comparison for both bounds: below `lower` the difference wraps to a large number.
    if (static_cast<std::uint64_t>(index - lower) >= static_cast<std::uint64_t>(extent)) [[unlikely]] {
      index = out_of_bounds(index, lower, lower + extent - 1);
    }
  }
  return static_cast<std::size_t>(index - lower);
}

/// The elements of an ARRAY of an enumeration whose initial value is not 0: each starts at it
/// (C++ would value-initialise them to 0). As large as the built-in array it holds.
template <class T, std::size_t N, class = std::make_index_sequence<N>>
struct started_elements;
template <class T, std::size_t N, std::size_t... I>
struct started_elements<T, N, std::index_sequence<I...>> {
  T values[N] = {((void)I, enum_start<T>())...};
  constexpr T& operator[](std::size_t i) noexcept { return values[i]; }
  constexpr const T& operator[](std::size_t i) const noexcept { return values[i]; }
};
/// starts_nonzero<T>(), but FALSE for an enumeration whose start iecoop does not know (which
/// the ARRAY refuses itself, at its declaration).
template <class T>
constexpr bool array_starts_nonzero() noexcept {
  if constexpr (std::is_enum_v<T> && !knows_enum_start<T>) {
    return false;
  } else {
    return starts_nonzero<T>();
  }
}
/// An ARRAY's element storage: a built-in array, value-initialised (0, and the IEC types' own
/// initial values), or started_elements where that is not ST's initial value.
template <class T, std::size_t N>
using array_elements = std::conditional_t<array_starts_nonzero<T>(), started_elements<T, N>, T[N]>;

/// `N(value)` of an ST initialiser: the value N times.
template <std::size_t N, class V>
struct repeated {
  V value;
};

template <class... X>
struct init_values {};
template <class X, class... Rest>
struct init_values<X, Rest...> {
  X first;
  init_values<Rest...> rest;
};

template <class X>
inline constexpr std::size_t initial_count = 1;
template <std::size_t N, class V>
inline constexpr std::size_t initial_count<repeated<N, V>> = N;

/// An initial value as an element: a C++ integer constant checked against the element's
/// range as `INT x = 5;` checks it (a compile error where the ARRAY is a constant, else a
/// fault at start-up: see detail::compile_error).
template <class T, class V>
constexpr T initial_element(const V& value) {
  if constexpr (cpp_integer<V> && is_integer<T>::value) {
    if (!std::in_range<typename T::rep>(value)) {
      // clang-format off
      compile_error("iecoop: an ARRAY's initial value is out of range for its element type; use a wider type or convert it");
      // clang-format on
    }
    return T(static_cast<typename T::rep>(value));
  } else {
    return value;
  }
}

template <class T, class V>
constexpr void put_initial(T* elements, std::size_t& at, const V& value) {
  elements[at++] = initial_element<T>(value);
}
template <class T, std::size_t N, class V>
constexpr void put_initial(T* elements, std::size_t& at, const repeated<N, V>& r) {
  const T element = initial_element<T>(r.value);
  for (std::size_t i = 0; i < N; ++i) elements[at++] = element;
}
template <class T>
constexpr void put_initials(T*, std::size_t&, const init_values<>&) {}
template <class T, class X, class... Rest>
constexpr void put_initials(T* elements, std::size_t& at, const init_values<X, Rest...>& values) {
  put_initial(elements, at, values.first);
  put_initials(elements, at, values.rest);
}

constexpr init_values<> make_init_values() { return {}; }
template <class X, class... Rest>
constexpr init_values<X, Rest...> make_init_values(const X& first, const Rest&... rest) {
  return {first, make_init_values(rest...)};
}

/// ST's initial values of an ARRAY, repetitions included: converts to any ARRAY with at least
/// as many elements. (Not consteval: Clang 14 crashes on a function that holds this and
/// another immediate call, such as LOWER_BOUND's dimension.)
template <class... X>
struct array_initialiser {
  static constexpr std::size_t count = (std::size_t{0} + ... + initial_count<X>);
  init_values<X...> values;

  template <array_check Check, class T, auto... Bounds>
  constexpr operator basic_array<Check, T, Bounds...>() const {  // implicit: `ARRAY<...> a = array_init(...)`
    using A = basic_array<Check, T, Bounds...>;
    static_assert(count <= A::element_count,
                  "iecoop: more initial values than the ARRAY has elements; drop some or enlarge the ARRAY");
    A a{};
    std::size_t at = 0;
    put_initials(a.data(), at, values);
    return a;
  }
};

/// Whether two ARRAY shapes have the same bounds, dimension by dimension (whatever the C++
/// types of the bound constants).
template <class A, class B>
constexpr bool same_bounds() noexcept {
  if constexpr (A::rank != B::rank) {
    return false;
  } else {
    for (std::size_t d = 0; d < A::rank; ++d) {
      if (A::lower(d) != B::lower(d) || A::upper(d) != B::upper(d)) return false;
    }
    return true;
  }
}

/// An ARRAY's elements compare with `=`: IEC values, enumerations, ARRAYs of them, STRUCTs with
/// an operator== of their own.
template <class T>
concept comparable_element = requires(const T& x) { static_cast<bool>(x == x); };

/// The elements of two ARRAYs of one shape, in memory order: TRUE if all are equal.
template <class T>
constexpr bool equal_elements(const T* a, const T* b, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    if (!static_cast<bool>(a[i] == b[i])) return false;
  }
  return true;
}

}  // namespace detail

/// ST's repetition `N(value)` inside an ARRAY's initial values: `repeat<3>(0)` for `3(0)`.
/// Only inside array_init(...).
template <std::size_t N, class V>
constexpr detail::repeated<N, V> repeat(const V& value) {
  static_assert(N > 0, "iecoop: a repetition repeats its value at least once; repeat<N>(value) with N >= 1");
  return {value};
}

/// ST's ARRAY initial values with repetitions: `[1, 2, 3(0)]` is `array_init(1, 2, repeat<3>(0))`.
/// It converts to any ARRAY with at least as many elements (the rest start at 0, as in ST):
///
///     ARRAY<INT, 1, 10> aiData = array_init(1, 2, repeat<3>(7));   // [1, 2, 3(7)]
///
/// Without repetitions, braces do the same: `ARRAY<INT, 1, 10> aiData{1, 2, 7, 7, 7};`. A C++
/// integer out of the elements' range does not compile where the ARRAY is a constant
/// (constexpr, constinit) and is a fault (invalid_value) where it is initialised at run time.
template <class... X>
constexpr detail::array_initialiser<X...> array_init(const X&... values) {
  return {detail::make_init_values(values...)};
}

/**
 * An IEC ARRAY with the bounds `Bounds` (pairs: lower, upper per dimension) and the index
 * check `Check`. Write ARRAY<T, Bounds...>; basic_array names the check explicitly (the
 * benchmark compares both in one program).
 *
 * An aggregate, so that braces initialise it as ST's `[...]` does, struct elements included
 * (`{{.p1 = 1}, {.p1 = 2}}`); its one member is public only for that reason — use the
 * indexing operators, data() or the range-for.
 */
template <array_check Check, class T, auto... Bounds>
struct basic_array {
 private:
  using shape = detail::array_shape<Bounds...>;
  static_assert(sizeof...(Bounds) > 0, "iecoop: an ARRAY needs its bounds; ARRAY<INT, 1, 10> is ARRAY[1..10] OF INT");
  static_assert(sizeof...(Bounds) % 2 == 0,
                "iecoop: ARRAY bounds come in pairs, lower then upper; ARRAY<REAL, -5, 5, 0, 2> is "
                "ARRAY[-5..5, 0..2] OF REAL");
  static_assert(shape::integers, "iecoop: ARRAY bounds are integer constants; write ARRAY<T, 1, 10>");
  static_assert(shape::in_dint, "iecoop: ARRAY bounds lie in DINT's range, as in CODESYS");
  static_assert(shape::ordered,
                "iecoop: an ARRAY's lower bound must not exceed its upper bound; write ARRAY[lower..upper]");
  static_assert(!std::is_reference_v<T> && !std::is_const_v<T> && !std::is_array_v<T>,
                "iecoop: an ARRAY's elements are variables; for ARRAY OF ARRAY write ARRAY<ARRAY<T, 1, 3>, 1, 2>");
  // Here, not where the elements start: the error's context is the ARRAY's declaration.
  static_assert(!std::is_enum_v<T> || detail::knows_enum_start<T>,
                "iecoop: a variable of an enumeration starts at its first component in ST, which iecoop knows only "
                "from the enumeration's declared components (the enumeration is the ARRAY's element type); declare "
                "them, first component first: template <> inline constexpr auto iecoop::enum_components<E> = "
                "iecoop::components<E::A, E::B>{}; (or the type's initial value, enum_initial<E>)");
  static_assert((detail::require_st_start<T>(), true));  // its own static_assert says what is wrong

 public:
  using value_type = T;
  using iecoop_array = void;
  /// The number of dimensions.
  static constexpr std::size_t rank = shape::rank;
  /// The number of elements.
  static constexpr std::size_t element_count = shape::size;
  static constexpr array_check check = Check;

  /// The lower bound of dimension `d` (from 1, as LOWER_BOUND counts).
  [[nodiscard]] static constexpr detail::array_index lower(std::size_t d) noexcept { return shape::lower(d - 1); }
  /// The upper bound of dimension `d` (from 1).
  [[nodiscard]] static constexpr detail::array_index upper(std::size_t d) noexcept { return shape::upper(d - 1); }

  /// A one-dimensional ARRAY's element `a[i]`.
  template <class I>
    requires(rank == 1)
  [[nodiscard]] constexpr T& operator[](const I& index) noexcept(Check == array_check::none) {
    detail::check_index_type<I>();
    return elements_[detail::offset_in<Check>(detail::index_value(index), shape::lower(0), shape::extent(0))];
  }
  template <class I>
    requires(rank == 1)
  [[nodiscard]] constexpr const T& operator[](const I& index) const noexcept(Check == array_check::none) {
    detail::check_index_type<I>();
    return elements_[detail::offset_in<Check>(detail::index_value(index), shape::lower(0), shape::extent(0))];
  }
  /// C++20 has no `a[i, j]`: a multi-dimensional ARRAY is indexed a(i, j).
  template <class I>
    requires(rank > 1)
  auto operator[](const I&) const {
    static_assert(
        detail::dependent_false<I>,
        "iecoop: a multi-dimensional ARRAY is indexed a(i, j) for ST's a[i, j] (a[i][j] indexes an ARRAY OF ARRAY)");
  }

  /// The element `a[i, j, ...]` of ST: one index per dimension.
  template <class... I>
  [[nodiscard]] constexpr T& operator()(const I&... index) noexcept(Check == array_check::none) {
    return elements_[offset(index...)];
  }
  template <class... I>
  [[nodiscard]] constexpr const T& operator()(const I&... index) const noexcept(Check == array_check::none) {
    return elements_[offset(index...)];
  }

  /// The elements in memory order (row by row), for C APIs and range-for.
  [[nodiscard]] constexpr T* data() noexcept { return &elements_[0]; }
  [[nodiscard]] constexpr const T* data() const noexcept { return &elements_[0]; }
  [[nodiscard]] static constexpr std::size_t size() noexcept { return element_count; }
  [[nodiscard]] constexpr T* begin() noexcept { return data(); }
  [[nodiscard]] constexpr T* end() noexcept { return data() + element_count; }
  [[nodiscard]] constexpr const T* begin() const noexcept { return data(); }
  [[nodiscard]] constexpr const T* end() const noexcept { return data() + element_count; }

  // Each check is in the operator itself, so that the caller's line comes early in the
  // compiler's report (every function between adds a note).

  /// `a = b` as the test libraries of ST compare ARRAYs (TcUnit's AssertArrayEquals): TRUE if
  /// each element equals the one at the same index. Only ARRAYs of one element type and the
  /// same bounds compare; the elements compare with their own `=`.
  [[nodiscard]] friend constexpr BOOL operator==(const basic_array& a, const basic_array& b) {
    static_assert(detail::comparable_element<T>,
                  "iecoop: ARRAYs compare element by element, and these elements have no = (a function block, or a "
                  "STRUCT without operator==); compare the members you mean, or give the STRUCT "
                  "`bool operator==(const ST_X&) const = default;`");
    if constexpr (detail::comparable_element<T>) {
      return BOOL(detail::equal_elements(a.data(), b.data(), element_count));
    } else {
      return FALSE;
    }
  }
  [[nodiscard]] friend constexpr BOOL operator!=(const basic_array& a, const basic_array& b) {
    static_assert(detail::comparable_element<T>,
                  "iecoop: ARRAYs compare element by element, and these elements have no = (a function block, or a "
                  "STRUCT without operator==); compare the members you mean, or give the STRUCT "
                  "`bool operator==(const ST_X&) const = default;`");
    if constexpr (detail::comparable_element<T>) {
      return BOOL(!detail::equal_elements(a.data(), b.data(), element_count));
    } else {
      return TRUE;
    }
  }
  /// An ARRAY of other bounds or another element type: refused, as ST would not compare them.
  /// One that differs only in its index check compares as one of this type (yielding a C++
  /// bool, so that C++ rewrites `a != b` as `!(a == b)` with this one function).
  template <array_check C, class U, auto... B>
    requires(!std::is_same_v<basic_array<C, U, B...>, basic_array>)
  [[nodiscard]] friend constexpr bool operator==(const basic_array& a, const basic_array<C, U, B...>& b) {
    if constexpr (!std::is_same_v<U, T>) {
      static_assert(detail::dependent_false<U>,
                    "iecoop: an ARRAY compares only with an ARRAY of the same element type (ST assigns no ARRAY OF INT "
                    "to an ARRAY OF DINT either); declare both with one element type");
      return false;
    } else if constexpr (!detail::same_bounds<shape, detail::array_shape<B...>>()) {
      static_assert(detail::dependent_false<U>,
                    "iecoop: an ARRAY compares only with an ARRAY of the same bounds, index by index; declare the "
                    "other with these bounds (ARRAY<INT, 1, 3> for ARRAY[1..3] OF INT), or compare in a FOR loop");
      return false;
    } else {
      static_assert(detail::comparable_element<T>,
                    "iecoop: ARRAYs compare element by element, and these elements have no = (a function block, or a "
                    "STRUCT without operator==); compare the members you mean, or give the STRUCT "
                    "`bool operator==(const ST_X&) const = default;`");
      if constexpr (detail::comparable_element<T>) {
        return detail::equal_elements(a.data(), b.data(), element_count);
      } else {
        return false;
      }
    }
  }

  // Public only to make the ARRAY an aggregate; each element starts at its type's initial value.
  detail::array_elements<T, element_count> elements_{};

 private:
  template <class... I>
  constexpr std::size_t offset(const I&... index) const {
    static_assert(sizeof...(I) == rank, "iecoop: index an ARRAY with one index per dimension, a(i, j) for a[i, j]");
    (detail::check_index_type<I>(), ...);
    std::size_t result = 0;
    std::size_t d = 0;
    ((result = result * static_cast<std::size_t>(shape::extent(d)) +
               detail::offset_in<Check>(detail::index_value(index), shape::lower(d), shape::extent(d)),
      ++d),
     ...);
    return result;
  }
};

/// `ARRAY[*] OF T`: only the type of a VAR_IN_OUT (in_out<ARRAY<T, '*'>>, in <iecoop/pou/variables.hpp>),
/// never a variable.
template <array_check Check, class T, auto... Stars>
  requires detail::array_shape<Stars...>::star
struct basic_array<Check, T, Stars...> {
  basic_array() {
    static_assert(detail::dependent_false<T>,
                  "iecoop: ARRAY[*] (variable length) exists only as a VAR_IN_OUT; declare in_out<ARRAY<T, '*'>>");
  }
};

/// The dimension argument of LOWER_BOUND and UPPER_BOUND: a constant from 1 to the ARRAY's
/// number of dimensions, checked at compile time.
template <std::size_t Rank>
struct array_dimension {
  template <detail::cpp_integer D>
  consteval array_dimension(D d) : value(static_cast<std::size_t>(d)) {  // implicit: LOWER_BOUND(a, 1)
    if (d < 1 || static_cast<std::size_t>(d) > Rank) {
      // clang-format off
      detail::compile_error("iecoop: LOWER_BOUND/UPPER_BOUND's dimension counts from 1 to the ARRAY's number of dimensions");
      // clang-format on
    }
  }
  std::size_t value;
};

/// ST's `LOWER_BOUND(a, dim)`: the lower bound of dimension `dim` (from 1), a DINT.
template <array_check Check, class T, auto... Bounds>
[[nodiscard]] constexpr DINT LOWER_BOUND(const basic_array<Check, T, Bounds...>&,
                                         std::type_identity_t<array_dimension<sizeof...(Bounds) / 2>> dim) noexcept {
  return DINT(static_cast<std::int32_t>(basic_array<Check, T, Bounds...>::lower(dim.value)));
}
/// ST's `UPPER_BOUND(a, dim)`: the upper bound of dimension `dim` (from 1), a DINT.
template <array_check Check, class T, auto... Bounds>
[[nodiscard]] constexpr DINT UPPER_BOUND(const basic_array<Check, T, Bounds...>&,
                                         std::type_identity_t<array_dimension<sizeof...(Bounds) / 2>> dim) noexcept {
  return DINT(static_cast<std::int32_t>(basic_array<Check, T, Bounds...>::upper(dim.value)));
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
