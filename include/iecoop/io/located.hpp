// SPDX-License-Identifier: MIT
// iecoop/io/located.hpp — located variables, ST's `AT %IX0.5`.
//
//     // VAR_GLOBAL  bStart AT %IX0.5 : BOOL;  bMotor AT %QX0.0 : BOOL;  iSpeed AT %IW2 : INT;  END_VAR
//     struct GVL_IO {
//       [[no_unique_address]] located<BOOL, "%IX0.5"> bStart;
//       [[no_unique_address]] located<BOOL, "%QX0.0"> bMotor;
//       [[no_unique_address]] located<INT, "%IW2"> iSpeed;
//       using LOCATED = pins<&GVL_IO::bStart, &GVL_IO::bMotor, &GVL_IO::iSpeed>;
//     };
//     ...
//     io.bMotor = io.bStart & (io.iSpeed > 100);
//
// A located variable is an empty object that reads and writes its bytes of the process image
// (<iecoop/io/process_image.hpp>), whose address is a link-time constant; `at<"%IX5">` is a
// directly represented variable used as it stands; check_located<...>() rejects two located
// variables that share a bit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/fixed_string.hpp>
#include <iecoop/io/access_checks.hpp>
#include <iecoop/io/address.hpp>
#include <iecoop/io/image_codec.hpp>
#include <iecoop/io/process_image.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>
namespace iecoop {

/**
 * A located variable, ST's `AT %IX0.5`: `bStart AT %IX0.5 : BOOL;` is
 * `located<BOOL, "%IX0.5"> bStart;`.
 *
 * It is an empty object: its value lives in the process image `Image`, at the address
 * given (checked at compile time: the type must fit the address's size and the address must
 * lie inside the image). Declare members `[[no_unique_address]]` so that they take no room
 * in their block, program or global variable list.
 *
 * In expressions it is its value (`bStart & !bStop`, `iSpeed + 1`, `if (bStart)`); %Q and
 * %M variables are assigned like variables (`bMotor = TRUE;`). A %I variable is read only:
 * the I/O driver writes it at the start of each task cycle.
 *
 * Sizes: %IX/%QX/%MX hold a BOOL; %IB a BYTE, SINT, USINT (or a BOOL, stored byte-wise as
 * CODESYS does); %IW a WORD, INT, UINT; %ID a DWORD, DINT, UDINT, REAL, TIME; %IL an LWORD,
 * LINT, ULINT, LREAL, LTIME.
 *
 * List located members in `using LOCATED = pins<&GVL::bStart, ...>;` so that
 * check_located<> rejects two of them that share a bit. Two located variables of the same
 * type are the same variable (the same bytes); copying a block copies no I/O.
 */
template <class T, detail::fixed_string Address, class Image = default_process_image>
class located : public detail::condition_conversion<located<T, Address, Image>, T>,
                public detail::widening_conversion<located<T, Address, Image>, T> {
 public:
  using value_type = T;
  using image_type = Image;
  using iecoop_value_wrapper = void;  // in expressions, its value (detail/value_operators.hpp)

  /// The variable's direct address.
  static constexpr io_address address = address_of<Address>;

 private:
  using check = detail::access_check_t<T, Address, Image>;
  static_assert(sizeof(check) > 0);  // instantiates the checks, whose own static_asserts say what is wrong
  static constexpr bool checked = detail::access_valid<T, Address, Image>;

 public:
  constexpr located() noexcept = default;
  constexpr located(const located&) noexcept = default;
  /// Copying a located variable to one of the same type (that is, at the same address) has
  /// nothing to do; a located variable at another address converts to its value first.
  constexpr located& operator=(const located&) noexcept = default;

  /// The value, read from the process image.
  [[nodiscard]] T get() const noexcept {
    if constexpr (checked) {
      return detail::image_load<T, address, Image::mode>(Image::area_data(address.area));
    } else {
      return T{};
    }
  }
  operator T() const noexcept { return get(); }  // implicit: reads as the variable

  /// Writes the value to the process image (%Q and %M only). A non-template operand, so that
  /// constants convert as in any assignment (`iCount = 5;`).
  located& operator=(const T& value) noexcept {
    static_assert(
        address.area != io_area::input,
        "iecoop: a %I... located variable is an input, written by the I/O driver at the start of each task "
        "cycle; the program only reads it. Give the variable a %Q (output) or %M (memory) address, or set the "
        "field value through simulated_io::set<\"%I...\">() or Image::write<T, \"%I...\">()");
    if constexpr (checked && address.area != io_area::input) {
      detail::image_store<T, address, Image::mode>(Image::area_data(address.area), value);
    }
    return *this;
  }

  /// From another variable wrapper whose value converts implicitly. Compound assignments
  /// (`iCount += 1;`) are those of every variable wrapper (detail/value_operators.hpp).
  template <class V>
    requires detail::converts_through_wrapper<T, V>
  located& operator=(const V& other) noexcept {
    const T value = detail::value_of(other);
    return *this = value;
  }
  /// A value of a type that ST converts only explicitly: rejected, naming the conversion.
  template <class V>
    requires detail::rejected_value<T, V>
  constexpr void operator=(const V&) {
    detail::reject_value<T, V>();
  }
};

/**
 * A directly represented variable used as it stands in ST: `%IX5` in an expression is
 * `at<"%IX5">`, `%QX1.0 := TRUE;` is `at<"%QX1.0"> = TRUE;`. Its type follows the size:
 * BOOL (X), BYTE, WORD, DWORD, LWORD; use located<T, "..."> for another type.
 *
 *     CMD_TMR("IN"_ = at<"%IX5">, "PT"_ = 300);   // ST: CMD_TMR(IN := %IX5, PT := 300);
 */
template <detail::fixed_string Address, class Image = default_process_image>
inline located<detail::default_type_t<address_of<Address>.width>, Address, Image> at{};

// ---------------------------------------------------------------------------------------
// The overlap check of a set of located variables

namespace detail {

template <class T>
struct is_located : std::false_type {};
template <class T, fixed_string A, class Image>
struct is_located<located<T, A, Image>> : std::true_type {};

template <class M>
struct member_pointer_parts;
template <class C, class V>
struct member_pointer_parts<V C::*> {
  using owner = C;
  using type = std::remove_cv_t<V>;
};

/// The located<> type a LOCATED entry designates.
template <auto Member>
using located_type_of = typename member_pointer_parts<decltype(Member)>::type;

/// A block's or list's `using LOCATED = pins<...>;`, as pou/call_interface.hpp reads VAR_INPUT: along the
/// EXTENDS chain, the base's first, so a derived block's own list does not hide its base's.
struct located_section {
  template <class B>
  using declared = typename B::LOCATED;
  static constexpr std::string_view keyword = "LOCATED";
};

template <class... Lists>
struct concat_all {
  using type = pins<>;
};
template <class First, class... Rest>
struct concat_all<First, Rest...> {
  using type = typename concat_pins<First, typename concat_all<Rest...>::type>::type;
};

/// Where one located variable lies: its image (as the index of the first entry with the same
/// image), its identity (the index of the first entry naming the same member) and its bits.
struct located_extent {
  std::size_t image;
  std::size_t identity;
  io_area area;
  std::uint64_t first_bit;
  std::uint64_t bit_count;
};

template <auto A, auto B>
constexpr bool same_member() noexcept {
  if constexpr (std::is_same_v<decltype(A), decltype(B)>) {
    return A == B;
  } else {
    return false;
  }
}

template <auto Member, auto... All>
constexpr located_extent extent_of() noexcept {
  using L = located_type_of<Member>;
  using image = typename L::image_type;
  constexpr bool same_image[] = {std::is_same_v<image, typename located_type_of<All>::image_type>...};
  constexpr bool same[] = {same_member<Member, All>()...};
  located_extent e{};
  e.image = 0;
  while (!same_image[e.image]) ++e.image;
  e.identity = 0;
  while (!same[e.identity]) ++e.identity;
  e.area = L::address.area;
  e.first_bit = L::address.first_bit(image::mode);
  e.bit_count = L::address.bit_count();
  return e;
}

struct overlap_pair {
  std::size_t first;
  std::size_t second;
};

/// The first two entries of the list that share a bit, or {size, size}.
template <auto... Members>
constexpr overlap_pair first_overlap(pins<Members...>) noexcept {
  constexpr std::size_t n = sizeof...(Members);
  if constexpr (n < 2) {
    return {n, n};
  } else {
    constexpr located_extent extents[] = {extent_of<Members, Members...>()...};
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        const located_extent& a = extents[i];
        const located_extent& b = extents[j];
        if (a.identity == b.identity || a.image != b.image || a.area != b.area) continue;
        if (a.first_bit < b.first_bit + b.bit_count && b.first_bit < a.first_bit + a.bit_count) return {i, j};
      }
    }
    return {n, n};
  }
}

/// Every entry of a LOCATED list is a located<> member.
template <auto... Members>
constexpr bool all_located(pins<Members...>) noexcept {
  return (is_located<located_type_of<Members>>::value && ...);
}

/// Instantiated for two listed located variables that overlap: the compiler prints the two
/// members (the template arguments) with the message.
template <auto First, auto Second, bool Disjoint = false>
struct located_overlap {
  static_assert(
      Disjoint,
      "iecoop: two located variables overlap (their names are in the template arguments above); give each its "
      "own address, or read the other width through the process image (Image::read<...>)");
  static constexpr bool value = false;
};

template <class... Objects>
using all_located_t = typename concat_all<typename section_pins<located_section, Objects>::type...>::type;

}  // namespace detail

namespace detail {
template <class... Objects>
constexpr bool located_disjoint_impl() noexcept {
  using list = all_located_t<Objects...>;
  static_assert(
      all_located(list{}),
      "iecoop: LOCATED lists located<> members only, e.g. using LOCATED = pins<&GVL_IO::bStart, &GVL_IO::bMotor>;");
  if constexpr (all_located(list{})) {
    return first_overlap(list{}).first == list::size;
  } else {
    return false;
  }
}
}  // namespace detail

/// TRUE if no two located variables listed in the LOCATED lists of Objects share a bit
/// (types without LOCATED list none). Does not stop compilation; check_located<> does.
template <class... Objects>
inline constexpr bool located_disjoint = detail::located_disjoint_impl<Objects...>();

/**
 * Rejects, at compile time, two located variables that share a bit: gathers the LOCATED
 * lists of all Objects (a block, program or global variable list lists its located
 * members, `using LOCATED = pins<&GVL_IO::bStart, ...>;`) and fails to compile, naming the
 * two members, if two of the same image and area overlap. Two BOOLs in the same byte do not
 * overlap. The scheduler calls it for the programs it runs; call it yourself for others:
 *
 *     iecoop::check_located<GVL_IO, PLC_PRG>();
 *
 * Deliberate aliasing (an input read as bits and as a byte) reads through the image,
 * `Image::read<BYTE, "%IB0">()`, or uses a located variable that is not listed.
 */
template <class... Objects>
constexpr void check_located() noexcept {
  using list = detail::all_located_t<Objects...>;
  static_assert(
      detail::all_located(list{}),
      "iecoop: LOCATED lists located<> members only, e.g. using LOCATED = pins<&GVL_IO::bStart, &GVL_IO::bMotor>;");
  if constexpr (detail::all_located(list{})) {
    constexpr detail::overlap_pair hit = detail::first_overlap(list{});
    if constexpr (hit.first < list::size) {
      static_assert(sizeof(detail::located_overlap<pin<list, hit.first>, pin<list, hit.second>>) > 0);  // reports
    }
  }
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
