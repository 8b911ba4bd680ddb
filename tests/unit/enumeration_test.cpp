// ST's enumerations as C++ enums with an IEC base type: component values, base types, the
// attributes 'qualified_only', 'strict' and 'to_string', names, text, conversions, the generic
// standard functions, CASE, and enumerations as block variables and RETAIN.
#include <cstdint>
#include <sstream>
#include <string>
#include <type_traits>

#include <fmt/format.h>
#include <iecoop/fmt.hpp>

#include "iecoop_test.hpp"

using namespace iecoop;
using iecoop_test::fault_recorder;
using iecoop_test::opaque;

namespace enum_test {

// TYPE E_State : (Idle, Run := 10, Fault); END_TYPE
enum E_State : INT::rep { Idle, Run = 10, Fault };

// {attribute 'qualified_only'} {attribute 'strict'} {attribute 'to_string'}
// TYPE E_Mode : (Off, Manual, Auto); END_TYPE
enum class E_Mode : INT::rep { Off, Manual, Auto };

// TYPE E_Temp : (Cold := -20, Cool := -1, Warm := 1, Hot := 60) SINT; END_TYPE  (no 0)
enum class E_Temp : SINT::rep { Cold = -20, Cool = -1, Warm = 1, Hot = 60 };

// TYPE E_Flags : (None, A := 16#01, B := 16#80) BYTE; END_TYPE
enum E_Flags : BYTE::rep { FlagNone, FlagA = 0x01, FlagB = 0x80 };

// TYPE E_Code : (Ok := 0, Big := 4000000000) UDINT; END_TYPE  (no names declared)
enum class E_Code : UDINT::rep { Ok = 0, Big = 4000000000U };

// TYPE E_Step : (S0 := 0, S10 := 10, ..., S1000 := 1000) -- a step chain with wide gaps
enum class E_Step : INT::rep { S0 = 0, S10 = 10, S20 = 20, S500 = 500, S1000 = 1000 };

// TYPE E_Wide : (Low := LINT#-9223372036854775808, High := 9223372036854775807) LINT; END_TYPE
enum class E_Wide : LINT::rep { Low = INT64_MIN, High = INT64_MAX };

// Not declared to iecoop (no components, not strict): C++ computes with it as an int.
enum E_Plain : INT::rep { PlainA, PlainB };

}  // namespace enum_test

using namespace enum_test;

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
inline constexpr bool iecoop::enum_to_string<E_Temp> = true;
template <>
struct iecoop::enum_base<E_Flags> {
  using type = BYTE;
};
template <>
inline constexpr auto iecoop::enum_components<E_Flags> = components<FlagNone, FlagA, FlagB>{};
template <>
inline constexpr auto iecoop::enum_components<E_Step> =
    components<E_Step::S0, E_Step::S10, E_Step::S20, E_Step::S500, E_Step::S1000>{};
template <>
inline constexpr auto iecoop::enum_components<E_Wide> = components<E_Wide::Low, E_Wide::High>{};
template <>
inline constexpr bool iecoop::enum_to_string<E_Wide> = true;

namespace other_ns {
enum class E_State : INT::rep { Idle };
}

namespace {

template <class T>
std::string printed(const T& value) {
  std::ostringstream os;
  os << value;
  return os.str();
}

template <class E>
std::string text_of(E e) {
  char text[max_text_length<E>];
  const char* end = to_text(text, e);
  return std::string(text, static_cast<std::size_t>(end - text));
}

template <class E>
constexpr bool adds_a_number = requires(E e) { e + 1; };
template <class E>
constexpr bool negates = requires(E e) { -e; };
template <class E>
constexpr bool ors = requires(E e) { e | e; };

// A block's VAR of each kind of enumeration, default-initialised.
struct FB_Vars : function_block<FB_Vars> {
  var<E_Temp> eTemp;
  var<E_State> eState{Run};
  var<E_Mode> eMode{E_Mode::Auto};
  void body() {}
};

// FUNCTION_BLOCK FB_Cycle -- a state machine over E_State
struct FB_Cycle : function_block<FB_Cycle> {
  BOOL bStart;                           // VAR_INPUT bStart : BOOL;
  BOOL bError;                           //           bError : BOOL; END_VAR
  var<E_State> eState{Idle};             // VAR eState : E_State; END_VAR
  retain<E_Mode> eMode{E_Mode::Manual};  // VAR RETAIN eMode : E_Mode := E_Mode.Manual; END_VAR
  INT iState;                            // VAR_OUTPUT iState : INT; END_VAR
  using VAR_INPUT = pins<&FB_Cycle::bStart, &FB_Cycle::bError>;
  void body() {
    switch (eState) {  // CASE eState OF
      case Idle:
        if (bStart) eState = Run;
        break;
      case Run:
        if (bError) eState = Fault;
        break;
      case Fault:
        if (!bError) eState = Idle;
        break;
    }
    iState = eState;  // iState := eState;  (a VAR of an enumeration reads as its base type)
  }
};

// Enumerations as pins: VAR_INPUT eCmd : E_Mode; VAR_OUTPUT eOut : E_State; iOut : INT;
struct FB_Pins : function_block<FB_Pins> {
  E_Mode eCmd = E_Mode::Off;
  E_State eOut = Idle;
  INT iOut;
  using VAR_INPUT = pins<&FB_Pins::eCmd>;
  using VAR_OUTPUT = pins<&FB_Pins::eOut, &FB_Pins::iOut>;
  void body() {
    eOut = eCmd == E_Mode::Auto ? Run : Idle;
    iOut = eOut;  // iOut := eOut;
  }
};

}  // namespace

TEST_SUITE("enumerations") {
  TEST_CASE("components count from 0, or from the previous one + 1 after an explicit value") {
    CHECK(INT(Idle) == 0);
    CHECK(INT(Run) == 10);
    CHECK(INT(Fault) == 11);
    CHECK(INT(E_Mode::Off) == 0);
    CHECK(INT(E_Mode::Auto) == 2);
    // Run and E_State::Run name the same component (no 'qualified_only'); E_Mode's only qualified.
    CHECK(E_State::Run == Run);
  }

  TEST_CASE("the base type is the IEC type over the C++ base type, or the one enum_base names") {
    CHECK(std::is_same_v<enum_base_t<E_State>, INT>);
    CHECK(std::is_same_v<enum_base_t<E_Temp>, SINT>);
    CHECK(std::is_same_v<enum_base_t<E_Flags>, BYTE>);
    CHECK(std::is_same_v<enum_base_t<E_Code>, UDINT>);
    CHECK(std::is_same_v<enum_base_t<E_Wide>, LINT>);
    CHECK(sizeof(E_State) == 2);
    CHECK(sizeof(E_Temp) == 1);
    CHECK(sizeof(E_Code) == 4);
    CHECK(Enumeration<E_State>);
    CHECK(Enumeration<E_Mode>);
    enum Unfixed { U0, U1 };
    enum class OfChar : char { C0 };
    enum class OfBool : bool { B0 };
    CHECK(!Enumeration<Unfixed>);
    CHECK(!Enumeration<OfChar>);
    CHECK(!Enumeration<OfBool>);
    CHECK(!Enumeration<INT>);
    CHECK(!Enumeration<int>);
  }

  TEST_CASE("a component reads as its base type and every type the base type widens to") {
    const INT i = opaque(INT(Run)) + 0;  // through a run-time value
    CHECK(i == 10);
    const E_State e = Fault;
    const INT i2 = e;  // iVar := eState;
    const DINT d = e;  // widening, as INT into DINT
    const LINT l = E_Mode::Auto;
    const BYTE b = FlagB;
    const WORD w = FlagB;  // BYTE widens to WORD
    const SINT s = E_Temp::Cold;
    CHECK(i2 == 11);
    CHECK(d == 11);
    CHECK(l == 2);
    CHECK(b == 0x80);
    CHECK(w == 0x80);
    CHECK(s == -20);
    // Not where the base type does not widen (INT into SINT, BYTE into INT, UDINT into DINT).
    CHECK(!std::is_convertible_v<E_State, SINT>);
    CHECK(!std::is_convertible_v<E_Flags, INT>);
    CHECK(!std::is_convertible_v<E_Code, DINT>);
    CHECK(std::is_convertible_v<E_Code, ULINT>);
    CHECK(!std::is_convertible_v<E_Temp, BYTE>);
    // A comparison with an IEC integer compares the values, and is a BOOL.
    CHECK(std::is_same_v<decltype(e == INT(11)), BOOL>);
    CHECK((e == INT(11)));
    CHECK((E_Temp::Cold < SINT(-19)));
  }

  TEST_CASE("the TO_ conversions take an enumeration as its base type's value") {
    CHECK(TO_INT(Fault) == 11);
    CHECK(TO_DINT(E_Temp::Cold) == -20);
    CHECK(TO_BYTE(E_Temp::Cold) == 236);  // -20 as a BYTE: the low bits
    CHECK(TO_UINT(E_Code::Big) == 0x2800);
    CHECK(TO_REAL(Run) == 10.0f);
    CHECK(TO_BOOL(Idle) == FALSE);
    CHECK(TO_BOOL(Run) == TRUE);
    CHECK(INT_TO_REAL(Run) == 10.0f);
    CHECK(INT_TO_DINT(Fault) == 11);
  }

  TEST_CASE("TO_STRING is the value without 'to_string', the component's name with it") {
    CHECK(TO_STRING(Run) == "10");  // E_State: no 'to_string', even with its names declared
    CHECK(TO_STRING(E_Mode::Auto) == "Auto");
    CHECK(TO_STRING(E_Temp::Cold) == "Cold");
    CHECK(TO_STRING(E_Temp::Cool) == "Cool");
    CHECK(TO_STRING(E_Code::Big) == "4000000000");
    CHECK(TO_WSTRING(E_Mode::Manual) == u"Manual");
    CHECK(TO_STRING(E_Wide::Low) == "Low");
    // A value that is no component: its number, also with 'to_string'.
    CHECK(TO_STRING(static_cast<E_Mode>(7)) == "7");
    CHECK(TO_STRING(static_cast<E_Temp>(0)) == "0");
    CHECK(TO_STRING(static_cast<E_Temp>(-128)) == "-128");
    // Into a shorter STRING: cut at its capacity.
    const STRING<3> s = convert<STRING<3>>(E_Mode::Manual);
    CHECK(s == "Man");
  }

  TEST_CASE("is_component and component_name at the edges of the components") {
    CHECK(is_component(Idle));
    CHECK(is_component(Fault));
    CHECK(!is_component(static_cast<E_State>(1)));   // in the gap after Idle
    CHECK(!is_component(static_cast<E_State>(9)));   // just below Run
    CHECK(!is_component(static_cast<E_State>(12)));  // just above Fault
    CHECK(!is_component(static_cast<E_State>(-1)));
    CHECK(is_component(E_Temp::Cold));
    CHECK(!is_component(static_cast<E_Temp>(0)));  // no component is 0
    CHECK(!is_component(static_cast<E_Temp>(-128)));
    CHECK(!is_component(static_cast<E_Temp>(127)));
    CHECK(is_component(E_Step::S1000));
    CHECK(!is_component(static_cast<E_Step>(30)));
    CHECK(is_component(E_Wide::Low));
    CHECK(is_component(E_Wide::High));
    CHECK(!is_component(static_cast<E_Wide>(0)));
    CHECK(component_name(FlagB) == "FlagB");
    CHECK(component_name(E_Temp::Cool) == "Cool");
    CHECK(component_name(static_cast<E_State>(12)).empty());
    static_assert(component_name(Run) == "Run");  // while compiling, too
    static_assert(is_component(E_Mode::Auto));
  }

  TEST_CASE("a variable of an enumeration starts at its first component, as in CODESYS, where C++ gives E{} 0") {
    // CODESYS starts such a variable at the first component (E_Temp.Cold); iecoop's variables do
    // too (var<E>: docs/porting-guide.md, ENUM). C++ value-initialises a plain enum to 0, which
    // need not be a component: a plain `E e` states its initial value.
    const E_Temp t{};
    CHECK(TO_SINT(t) == 0);
    CHECK(!is_component(t));
    const FB_Vars fb;
    CHECK(fb.eTemp.get() == E_Temp::Cold);  // eTemp : E_Temp;  (CODESYS: Cold, -20)
    CHECK(is_component(fb.eTemp.get()));
    CHECK(std::is_trivially_copyable_v<E_Temp>);
  }

  TEST_CASE("text: the component's name where known, else the number, and parse_enum reads both") {
    CHECK(text_of(Run) == "Run");
    CHECK(text_of(static_cast<E_State>(12)) == "12");
    CHECK(text_of(static_cast<E_State>(-32768)) == "-32768");
    CHECK(text_of(E_Code::Big) == "4000000000");  // no names declared
    CHECK(text_of(E_Wide::High) == "High");
    CHECK(text_of(static_cast<E_Wide>(-1)) == "-1");
    CHECK(max_text_length<E_State> == max_text_length<INT>);  // "-32768" is longer than "Fault"
    CHECK(max_text_length<E_Mode> == max_text_length<INT>);

    CHECK(*parse_enum<E_State>("Run") == Run);
    CHECK(*parse_enum<E_State>("fault") == Fault);  // ST's names ignore case
    CHECK(*parse_enum<E_State>("E_State.Idle") == Idle);
    CHECK(*parse_enum<E_State>("E_STATE#Run") == Run);
    CHECK(*parse_enum<E_State>("11") == Fault);
    CHECK(*parse_enum<E_State>("INT#16#C") == static_cast<E_State>(12));
    CHECK(*parse_enum<E_State>("-5") == static_cast<E_State>(-5));
    CHECK(*parse_enum<E_Temp>("Cold") == E_Temp::Cold);

    const auto unknown = parse_enum<E_State>("Walk");
    CHECK(unknown.error() == parse_error::unknown_component);
    CHECK(unknown.position() == 0);
    const auto qualified_unknown = parse_enum<E_State>("E_State.Walk");
    CHECK(qualified_unknown.error() == parse_error::unknown_component);
    CHECK(qualified_unknown.position() == 8);
    CHECK(parse_enum<E_State>("E_Mode.Run").error() == parse_error::wrong_prefix);
    CHECK(parse_enum<E_State>("E_State.").error() == parse_error::no_value);
    CHECK(parse_enum<E_State>("").error() == parse_error::empty);
    CHECK(parse_enum<E_State>("40000").error() == parse_error::out_of_range);
    CHECK(parse_enum<E_Code>("Big").error() == parse_error::unknown_component);  // no names declared
    CHECK(*parse_enum<E_Code>("4000000000") == E_Code::Big);
  }

  TEST_CASE("parse_enum reads back what to_text writes, for every value of a SINT enumeration") {
    int mismatches = 0;
    for (int v = -128; v <= 127; ++v) {
      const auto e = static_cast<E_Temp>(v);
      const auto back = parse_enum<E_Temp>(text_of(e));
      if (!back || *back != e) ++mismatches;
    }
    CHECK(mismatches == 0);
  }

  TEST_CASE("printing: ostream and fmt show the component's name, or the number") {
    CHECK(printed(Fault) == "Fault");
    CHECK(printed(E_Mode::Manual) == "Manual");
    CHECK(printed(static_cast<E_State>(3)) == "3");
    CHECK(printed(E_Code::Big) == "4000000000");
    CHECK(printed(E_Temp::Cold) == "Cold");  // a SINT base prints as a number, not a character
    CHECK(printed(static_cast<E_Temp>(65)) == "65");
    CHECK(fmt::format("{}|{:>7}|{}", Run, E_Mode::Auto, static_cast<E_Flags>(3)) == "Run|   Auto|3");
    const FB_Vars fb;
    CHECK(printed(fb.eState) == "Run");
    CHECK(fmt::format("{}", fb.eState) == "Run");
  }

  TEST_CASE("IEC names: the enumeration's own name, without namespaces") {
    CHECK(detail::iec_name<E_State>::value == "E_State");
    CHECK(detail::iec_name<E_Mode>::value == "E_Mode");
    // The RETAIN image tells two enumerations of one name apart by their full names.
    CHECK(detail::type_hash<E_State> != detail::type_hash<other_ns::E_State>);
  }

  TEST_CASE("to_enum: a number becomes an enumeration without 'strict', component or not") {
    const INT i = opaque(INT(10));
    CHECK(to_enum<E_State>(i) == Run);
    CHECK(to_enum<E_State>(SINT(11)) == Fault);  // SINT widens to INT
    CHECK(to_enum<E_State>(i + 1) == Fault);     // an intermediate result
    CHECK(to_enum<E_State>(5) == static_cast<E_State>(5));
    CHECK(!is_component(to_enum<E_State>(5)));
    CHECK(to_enum<E_Temp>(SINT(-20)) == E_Temp::Cold);
    fault_recorder faults;
    CHECK(to_enum<E_State>(opaque(70000)) == static_cast<E_State>(70000 - 65536));  // low bytes
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
  }

  TEST_CASE("arithmetic without 'strict' computes in the base type, as ST does") {
    const E_State e = opaque(Run);
    CHECK(std::is_same_v<decltype(e + 1), intermediate<INT>>);
    const INT next = e + 1;  // iNext := eState + 1;
    CHECK(next == 11);
    CHECK(to_enum<E_State>(e + 1) == Fault);  // eState := eState + 1;
    CHECK((Fault - Run) == 1);
    CHECK((2 * Run) == 20);
    CHECK((Fault % 2) == 1);
    CHECK((-Run) == -10);
    // In the register, as INT arithmetic: not cut to 16 bits until assigned.
    const auto big = static_cast<E_State>(32767);
    CHECK((big + 1) == 32768);
    const INT wrapped = big + 1;
    CHECK(wrapped == -32768);
    // A bit string base: AND / OR / XOR / NOT of flags, in BYTE.
    const BYTE both = FlagA | FlagB;
    CHECK(both == 0x81);
    CHECK((both & FlagB) == 0x80);
    CHECK(BYTE(~FlagA) == 0xFE);
    // Division by a component of value 0 is a fault, and 0.
    fault_recorder faults;
    CHECK((Run / opaque(Idle)) == 0);
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::division_by_zero);
    // A C++ integer out of the base type's range is a fault (the low bytes are kept).
    CHECK((Run + opaque(70000)) == 10 + (70000 - 65536));
    CHECK(faults.count == 2);
    CHECK(faults.last_kind == fault_kind::invalid_value);
  }

  TEST_CASE("arithmetic is ST's for the enumerations declared to iecoop only") {
    // Declared (components, 'strict' or 'to_string'): iecoop's operators; with 'strict' they
    // reject the expression while compiling (tests/compile_fail/enum_strict_arithmetic.cpp).
    CHECK(adds_a_number<E_State>);
    CHECK(negates<E_State>);
    CHECK(ors<E_Flags>);
    // Not declared: C++'s own arithmetic, as for any other library's enum (an int for a plain
    // enum, none for an enum class).
    CHECK(std::is_same_v<decltype(PlainA + 1), int>);
    CHECK(std::is_same_v<decltype(fault_kind::user == fault_kind::user), bool>);
    CHECK(!adds_a_number<fault_kind>);
    CHECK(!negates<E_Code>);
  }

  TEST_CASE("the generic standard functions on components of one enumeration") {
    const E_Mode m = opaque(E_Mode::Manual);
    CHECK(std::is_same_v<decltype(SEL(TRUE, E_Mode::Off, m)), E_Mode>);
    CHECK(SEL(FALSE, E_Mode::Off, m) == E_Mode::Off);
    CHECK(SEL(TRUE, E_Mode::Off, m) == E_Mode::Manual);
    CHECK(MUX(2, Idle, Run, Fault) == Fault);
    CHECK(MUX(7, Idle, Run, Fault) == Fault);  // beyond the last input: the last
    CHECK(MAX(Idle, Fault, Run) == Fault);
    CHECK(MIN(E_Temp::Hot, E_Temp::Cold) == E_Temp::Cold);
    CHECK(LIMIT(Run, Idle, Fault) == Run);
    CHECK(EQ(m, E_Mode::Manual));
    CHECK(NE(m, E_Mode::Auto));
    CHECK(GT(E_Mode::Auto, m, E_Mode::Off));
    CHECK(!LT(Fault, Run));
    const FB_Vars fb;
    CHECK(EQ(fb.eMode, E_Mode::Auto));
  }

  TEST_CASE("enumerations as named inputs and outputs of a call") {
    FB_Pins fb;
    E_State eSeen = Fault;
    INT iSeen;
    fb("eCmd"_ = E_Mode::Auto, "eOut"_ >> eSeen, "iOut"_ >> iSeen);
    CHECK(eSeen == Run);
    CHECK(iSeen == 10);
    fb("eCmd"_ = E_Mode::Manual, "eOut"_ >> eSeen);
    CHECK(eSeen == Idle);
  }

  TEST_CASE("CASE on an enumeration: a state machine as a block, its state RETAIN") {
    FB_Cycle fb;
    fb();
    CHECK(fb.eState == Idle);
    fb("bStart"_ = TRUE);
    CHECK(fb.eState == Run);
    fb("bError"_ = TRUE);
    CHECK(fb.eState == Fault);
    CHECK(fb.iState == 11);
    const INT iRead = fb.eState;  // from outside too
    CHECK(iRead == 11);
    fb("bError"_ = FALSE);
    CHECK(fb.eState == Idle);
    CHECK(fb.eMode == E_Mode::Manual);
    CHECK(sizeof(fb.eMode.get()) == 2);
  }
}
