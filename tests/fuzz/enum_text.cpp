// Fuzz target: enumeration text (parse_enum, to_text), for enumerations of several base types,
// with and without declared components. Checks, for any input:
//   - a failed parse names its error at a position within the text;
//   - what parses has a text of at most max_text_length<E> characters, printed alike by to_text,
//     operator<< and fmt (and TO_STRING with 'to_string'), which parses back to the same value;
//   - a text read as a name (not a number) names a component: is_component holds, and
//     component_name is the name read, in any case;
//   - a text that starts with a digit or sign is read as parse_integer reads it in the base type;
//   - the input's first bytes as a value of each enumeration (a component or not) format and
//     parse back.
#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

namespace fuzz_enums {

using namespace iecoop;

enum E_State : INT::rep { Idle, Run = 10, Fault };
enum class E_Mode : INT::rep { Off, Manual, Auto };
enum class E_Temp : SINT::rep { Cold = -20, Cool = -1, Warm = 1, Hot = 60 };
enum E_Flags : BYTE::rep { FlagNone, FlagA = 0x01, FlagB = 0x80 };
enum class E_Wide : LINT::rep {
  Low = std::numeric_limits<std::int64_t>::min(),
  High = std::numeric_limits<std::int64_t>::max()
};
enum class E_Long : SINT::rep { Short, AComponentNameLongerThanAnyNumberOfItsBase };
enum class E_Code : UDINT::rep { Ok = 0, Big = 4000000000U };  // no components declared: numbers only

}  // namespace fuzz_enums

using namespace fuzz_enums;

template <>
inline constexpr auto iecoop::enum_components<E_State> = components<Idle, Run, Fault>{};
template <>
inline constexpr auto iecoop::enum_components<E_Mode> = components<E_Mode::Off, E_Mode::Manual, E_Mode::Auto>{};
template <>
inline constexpr bool iecoop::enum_strict<E_Mode> = true;
template <>
inline constexpr bool iecoop::enum_to_string<E_Mode> = true;
template <>
inline constexpr auto iecoop::enum_components<E_Temp> =
    components<E_Temp::Cold, E_Temp::Cool, E_Temp::Warm, E_Temp::Hot>{};
template <>
inline constexpr auto iecoop::enum_components<E_Flags> = components<FlagNone, FlagA, FlagB>{};
template <>
inline constexpr auto iecoop::enum_components<E_Wide> = components<E_Wide::Low, E_Wide::High>{};
template <>
inline constexpr auto iecoop::enum_components<E_Long> =
    components<E_Long::Short, E_Long::AComponentNameLongerThanAnyNumberOfItsBase>{};

namespace {

using namespace iecoop;
using iecoop_fuzz::require;

template <class E>
void check_value(E value) {
  const std::string text = iecoop_fuzz::text_of(value);
  const auto back = parse_enum<E>(text);
  require(back.has_value() && back.value_or(E{}) == value, "an enumeration's text parses back to it", text);
}

template <class E>
void check_text(std::string_view text) {
  using B = enum_base_t<E>;
  const auto parsed = parse_enum<E>(text);
  iecoop_fuzz::require_error_in_text(parsed, text);
  const bool numeric = !text.empty() && (detail::is_digit(text.front()) || text.front() == '-' || text.front() == '+');
  if (numeric) {
    const auto n = parse_integer<B>(text);
    require(parsed.has_value() == n.has_value(), "a number is an enumeration's value iff its base type's", text);
    require(parsed.error() == n.error() && parsed.position() == n.position(),
            "a number fails as an enumeration as in its base type", text);
    if (n) {
      require(enum_base_t<E>(parsed.value_or(E{})) == n.value_or(B{}), "a number reads as its base type's value", text);
    }
  }
  if (!parsed) return;
  const E value = parsed.value_or(E{});
  check_value(value);
  const std::size_t mark = text.find_first_of("#.");
  const std::string_view prefix = mark == std::string_view::npos ? std::string_view{} : text.substr(0, mark);
  const bool as_name = !numeric && !(mark != std::string_view::npos && text[mark] == '#' &&
                                     detail::iequals(prefix, detail::iec_name<B>::value));
  if (as_name) {
    const std::string_view name = mark == std::string_view::npos ? text : text.substr(mark + 1);
    require(static_cast<bool>(is_component(value)), "a name read is a component's", text);
    require(detail::iequals(component_name(value), name), "a name reads as the component of that name", text);
  }
}

template <class E>
void check(std::string_view text, std::uint64_t bits) {
  check_text<E>(text);
  using U = std::underlying_type_t<E>;
  check_value(static_cast<E>(static_cast<U>(bits)));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = iecoop_fuzz::as_text(data, size);
  const auto bits = iecoop_fuzz::load<std::uint64_t>(data, size);
  check<E_State>(text, bits);
  check<E_Mode>(text, bits);
  check<E_Temp>(text, bits);
  check<E_Flags>(text, bits);
  check<E_Wide>(text, bits);
  check<E_Long>(text, bits);
  // Numbers only: parse_enum reads no name of it.
  const auto code = parse_enum<E_Code>(text);
  iecoop_fuzz::require_error_in_text(code, text);
  if (code) check_value(code.value_or(E_Code{}));
  check_value(static_cast<E_Code>(static_cast<std::uint32_t>(bits)));
  return 0;
}
