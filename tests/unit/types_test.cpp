// The IEC elementary types: sizes, ranges, zero-initialisation, wrap-around arithmetic
// without undefined behaviour, and IEC's implicit-conversion rules.
#include "iecoop_test.hpp"

#include <cstdint>
#include <limits>
#include <type_traits>

using namespace iecoop;
using iecoop_test::fault_recorder;
using iecoop_test::opaque;

namespace {

// Size and range of every IEC integer type (IEC 61131-3; CDS-INT).
template <class T, std::size_t Bytes>
constexpr bool has_size() {
  return sizeof(T) == Bytes && alignof(T) == alignof(typename T::rep) && std::is_trivially_copyable_v<T> &&
         std::is_standard_layout_v<T>;
}
template <class T>
constexpr bool has_range(auto min, auto max) {
  return std::numeric_limits<T>::min() == min && std::numeric_limits<T>::max() == max;
}
static_assert(has_size<SINT, 1>() && has_range<SINT>(-128, 127));
static_assert(has_size<INT, 2>() && has_range<INT>(-32768, 32767));
static_assert(has_size<DINT, 4>() && has_range<DINT>(-2147483647 - 1, 2147483647));
static_assert(has_size<LINT, 8>() && has_range<LINT>(-9223372036854775807LL - 1, 9223372036854775807LL));
static_assert(has_size<USINT, 1>() && has_range<USINT>(0, 255));
static_assert(has_size<UINT, 2>() && has_range<UINT>(0, 65535));
static_assert(has_size<UDINT, 4>() && has_range<UDINT>(0, 4294967295U));
static_assert(has_size<ULINT, 8>() && has_range<ULINT>(0, 18446744073709551615ULL));
static_assert(has_size<BYTE, 1>() && has_range<BYTE>(0, 255));
static_assert(has_size<WORD, 2>() && has_range<WORD>(0, 65535));
static_assert(has_size<DWORD, 4>() && has_range<DWORD>(0, 4294967295U));
static_assert(has_size<LWORD, 8>() && has_range<LWORD>(0, 18446744073709551615ULL));

static_assert(sizeof(BOOL) == 1 && std::is_trivially_copyable_v<BOOL>);
static_assert(sizeof(REAL) == 4 && std::numeric_limits<float>::is_iec559 && std::is_trivially_copyable_v<REAL>);
static_assert(sizeof(LREAL) == 8 && std::numeric_limits<double>::is_iec559 && std::is_trivially_copyable_v<LREAL>);

// The IEC families (ANY_INT, ANY_BIT, ANY_REAL).
static_assert(AnyInt<SINT> && AnyInt<ULINT> && !AnyInt<WORD> && !AnyInt<BOOL> && !AnyInt<int>);
static_assert(AnyBit<BOOL> && AnyBit<BYTE> && AnyBit<LWORD> && !AnyBit<INT>);
static_assert(AnyReal<REAL> && AnyReal<LREAL> && !AnyReal<float>);
static_assert(AnyNum<DINT> && AnyNum<LREAL> && !AnyNum<DWORD>);

// IEC's implicit widening: within a family, and unsigned -> wider signed.
static_assert(std::is_convertible_v<SINT, INT> && std::is_convertible_v<INT, DINT> &&
              std::is_convertible_v<DINT, LINT>);
static_assert(std::is_convertible_v<USINT, UINT> && std::is_convertible_v<UDINT, ULINT>);
static_assert(std::is_convertible_v<USINT, INT> && std::is_convertible_v<UINT, DINT> &&
              std::is_convertible_v<UDINT, LINT>);
static_assert(std::is_convertible_v<BYTE, WORD> && std::is_convertible_v<DWORD, LWORD>);
// ... and nothing else: narrowing, sign changes and family changes need a conversion.
static_assert(!std::is_convertible_v<DINT, INT> && !std::is_convertible_v<LINT, DINT>);
static_assert(!std::is_convertible_v<INT, UINT> && !std::is_convertible_v<UINT, INT> &&
              !std::is_convertible_v<UDINT, DINT>);
static_assert(!std::is_convertible_v<BYTE, USINT> && !std::is_convertible_v<USINT, BYTE> &&
              !std::is_convertible_v<WORD, INT>);
static_assert(std::is_constructible_v<INT, DINT> && std::is_constructible_v<UINT, INT>);  // explicitly: yes
// C++ integers: implicit where every value fits (at run time too).
static_assert(std::is_convertible_v<std::int16_t, INT> && std::is_convertible_v<int, DINT> &&
              std::is_convertible_v<std::uint32_t, UDINT>);
// BOOL comes from bool only; INT is no condition.
static_assert(!std::is_convertible_v<int, BOOL> && !std::is_constructible_v<BOOL, int> &&
              std::is_convertible_v<bool, BOOL>);
static_assert(!std::is_convertible_v<INT, bool> && !std::is_constructible_v<bool, INT>);
// A BOOL is a condition wherever C++ wants one (`bool ok = b;`, std algorithms, doctest).
static_assert(std::is_convertible_v<BOOL, bool>);
// REAL: exact integers convert implicitly, LREAL and DINT do not (C0197 in CODESYS).
static_assert(std::is_convertible_v<INT, REAL> && std::is_convertible_v<UINT, REAL> &&
              !std::is_convertible_v<DINT, REAL>);
static_assert(std::is_convertible_v<DINT, LREAL> && !std::is_convertible_v<LINT, LREAL> &&
              !std::is_convertible_v<WORD, REAL>);
static_assert(std::is_convertible_v<REAL, LREAL> && !std::is_convertible_v<LREAL, REAL> &&
              std::is_constructible_v<REAL, LREAL>);

// Arithmetic yields an intermediate result of the wider type, as IEC's implicit widening
// does; bitwise operations stay in the type.
static_assert(std::is_same_v<decltype(INT() + DINT()), intermediate<DINT>>);
static_assert(std::is_same_v<decltype(USINT() * INT()), intermediate<INT>>);
static_assert(std::is_same_v<decltype(BYTE() | WORD()), WORD>);
static_assert(std::is_same_v<decltype(INT() + 1), intermediate<INT>>);
static_assert(std::is_same_v<decltype((INT() + 1) + DINT()), intermediate<DINT>>);
static_assert(std::is_same_v<decltype(INT() == INT()), BOOL> && std::is_same_v<decltype(INT() < 1), BOOL>);
static_assert(std::is_same_v<decltype(1 >= INT()), BOOL> && std::is_same_v<decltype((INT() + 1) != 2), BOOL>);

// a + b yields an intermediate result (unrelated types get a poisoned operator returning
// void, whose body explains the rule when it is instantiated: a compile-fail test checks that).
template <class A, class B>
concept addable = requires(A a, B b) {
  { a + b } -> Intermediate;
};

}  // namespace

TEST_SUITE("elementary types") {
  TEST_CASE_TEMPLATE("every variable starts at zero", T, SINT, INT, DINT, LINT, USINT, UINT, UDINT, ULINT, BYTE, WORD,
                     DWORD, LWORD) {
    T value;
    CHECK(value == 0);
    CHECK(T{} == T(typename T::rep{0}));
  }

  TEST_CASE("BOOL, REAL and LREAL start at FALSE and 0.0") {
    BOOL b;
    REAL r;
    LREAL l;
    CHECK(b == FALSE);
    CHECK(r == 0.0f);
    CHECK(l == 0.0);
  }

  TEST_CASE_TEMPLATE("integer arithmetic wraps around at the type's limits when assigned", T, SINT, INT, DINT, LINT,
                     USINT, UINT, UDINT, ULINT, BYTE, WORD, DWORD, LWORD) {
    // opaque() keeps the compiler from folding: the operations really run, under UBSan
    // in CI, and none of them may be undefined behaviour.
    const T max = opaque(std::numeric_limits<T>::max());
    const T min = opaque(std::numeric_limits<T>::min());
    const T one = opaque(T(typename T::rep{1}));
    T x = max + one;
    CHECK(x == min);
    x = min - one;
    CHECK(x == max);
    const T two = opaque(T(typename T::rep{2}));
    x = max * two + two;
    CHECK(x == T());  // 2 * max + 2 is 2^bits for unsigned types, 0 for signed ones
    x = -min;
    CHECK(x == (std::is_signed_v<typename T::rep> ? min : T()));
    T counter = max;
    ++counter;
    CHECK(counter == min);
    counter--;
    CHECK(counter == max);
    counter += one;
    CHECK(counter == min);
    counter -= one;
    CHECK(counter == max);
    counter *= max;
    CHECK(counter == one);  // max * max is 1 modulo 2^bits, signed or not
    // The conversion functions cut an intermediate result to the type, as assignment does.
    CHECK(static_cast<T>(max + one) == min);
  }

  TEST_CASE_TEMPLATE("an intermediate result is not cut to its type's width", T, SINT, INT, USINT, UINT, BYTE, WORD) {
    // Narrower than every register: the sum keeps its carry, as on any CODESYS target.
    const T max = opaque(std::numeric_limits<T>::max());
    const T one = opaque(T(typename T::rep{1}));
    CHECK((max + one) != std::numeric_limits<T>::min());
    CHECK((max + one) > max);
    CHECK((max + one) == static_cast<long long>(max.value()) + 1);
    CHECK((max + one) / 2 == (static_cast<long long>(max.value()) + 1) / 2);
    // and a variable of a type T widens to keeps it all (dwVar := wVar + 1 is 65536).
    using wide_t = std::conditional_t<T::kind == integer_kind::bit_string, LWORD, LINT>;
    const wide_t wide = max + one;
    CHECK(wide == static_cast<long long>(max.value()) + 1);
  }

  TEST_CASE("the register width decides what a 32- or 64-bit sum keeps") {
    // DINT and UDINT fill a 32-bit register exactly: there they wrap at once; on a 64-bit
    // target (x64, CODESYS's 64 bits) the carry stays until the result is assigned.
    const DINT max = opaque(DINT(2147483647));
    const DINT sum = max + 1;
    CHECK(sum == -2147483647 - 1);
    if constexpr (register_bits == 64) {
      CHECK((max + 1) == 2147483648LL);
      CHECK(((max + 1) > max));
    } else {
      CHECK((max + 1) == -2147483647 - 1);
    }
    // LINT is 64 bits everywhere: wraps in the expression too.
    CHECK(opaque(LINT(std::numeric_limits<std::int64_t>::max())) + 1 == std::numeric_limits<std::int64_t>::min());
    static_assert(intermediate<INT>::bits == register_bits && intermediate<LINT>::bits == 64);
  }

  TEST_CASE("DINT and LINT overflow wraps like a PLC, never undefined behaviour") {
    DINT d = opaque(DINT(2147483647)) + 1;
    CHECK(d == DINT(-2147483647 - 1));
    d = opaque(DINT(-2147483647 - 1)) - 1;
    CHECK(d == 2147483647);
    d = opaque(DINT(65536)) * opaque(DINT(65536));
    CHECK(d == 0);
    d = opaque(DINT(46341)) * opaque(DINT(46341));
    CHECK(d == -2147479015);
    LINT l = opaque(LINT(std::numeric_limits<std::int64_t>::max())) + 1;
    CHECK(l == std::numeric_limits<std::int64_t>::min());
    l = opaque(LINT(3037000500)) * opaque(LINT(3037000500));
    CHECK(l == LINT(-9223372036709301616));
    CHECK(-opaque(LINT(std::numeric_limits<std::int64_t>::min())) == std::numeric_limits<std::int64_t>::min());
  }

  TEST_CASE("UINT and USINT multiply without the int promotion trap of C++") {
    // In C++, uint16_t * uint16_t is computed in int: 65535 * 65535 overflows it (UB). Here the
    // register is unsigned: 4294836225, and the low 16 bits are 1.
    CHECK(opaque(UINT(65535)) * opaque(UINT(65535)) == 4294836225u);
    UINT u = opaque(UINT(65535)) * opaque(UINT(65535));
    CHECK(u == 1);
    USINT us = opaque(USINT(255)) * opaque(USINT(255));
    CHECK(us == 1);
    WORD w = opaque(WORD(0x8000)) * opaque(WORD(2));
    CHECK(w == 0);
  }

  TEST_CASE("INT wraps as in the PLC_PRG property example") {
    INT i = 32767;
    i = i + 1;
    CHECK(i == -32768);
    i = i - 1;
    CHECK(i == 32767);
  }

  TEST_CASE("division truncates toward zero, MOD takes the sign of the dividend") {
    CHECK(DINT(-7) / DINT(2) == -3);
    CHECK(DINT(7) / DINT(-2) == -3);
    CHECK(DINT(-7) % DINT(2) == -1);
    CHECK(DINT(7) % DINT(-2) == 1);
    CHECK(UDINT(7) / UDINT(2) == 3u);
    CHECK(UDINT(7) % UDINT(2) == 1u);
    CHECK(INT(100) / 7 == 14);
    CHECK(INT(100) % 7 == 2);
  }

  TEST_CASE("the most negative value divided by -1 wraps, and its MOD -1 is 0") {
    fault_recorder faults;
    // In a register as wide as the type, the quotient wraps at once.
    CHECK(opaque(LINT(std::numeric_limits<std::int64_t>::min())) / opaque(LINT(-1)) ==
          std::numeric_limits<std::int64_t>::min());
    const DINT d = opaque(DINT(-2147483647 - 1)) / opaque(DINT(-1));
    CHECK(d == -2147483647 - 1);
    CHECK(opaque(DINT(-2147483647 - 1)) % opaque(DINT(-1)) == 0);
    // In a wider register, -(-128) is 128 until it is assigned to a SINT.
    CHECK(opaque(SINT(-128)) / opaque(SINT(-1)) == 128);
    const SINT s = opaque(SINT(-128)) / opaque(SINT(-1));
    CHECK(s == -128);
    CHECK(faults.count == 0);
  }

  TEST_CASE("division and MOD by zero report a fault and yield 0") {
    fault_recorder faults;
    CHECK(opaque(DINT(7)) / opaque(DINT(0)) == 0);
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::division_by_zero);
    CHECK(opaque(UINT(7)) % opaque(UINT(0)) == 0u);
    CHECK(faults.count == 2);
    INT x = 5;
    x /= opaque(INT(0));
    CHECK(x == 0);
    CHECK(faults.count == 3);
    CHECK(faults.last_message.find("by zero") != std::string::npos);
  }

  TEST_CASE("bitwise operators are ST's AND, OR, XOR and NOT") {
    const WORD w = 0xF0F0;
    CHECK((w & WORD(0xFF00)) == 0xF000);
    CHECK((w | WORD(0x0F00)) == 0xFFF0);
    CHECK((w ^ WORD(0xFFFF)) == 0x0F0F);
    CHECK(~w == 0x0F0F);
    CHECK(~BYTE(0) == 255);
    CHECK(~SINT(0) == -1);
    WORD v = 0x00FF;
    v &= WORD(0x0F0F);
    v |= WORD(0x1000);
    v ^= WORD(0x0001);
    CHECK(v == 0x100E);
  }

  TEST_CASE("narrowing is explicit and keeps the low bytes") {
    CHECK(static_cast<SINT>(INT(4223)) == 127);  // 16#107F -> 16#7F (TC-INTCONV example)
    CHECK(static_cast<UINT>(DINT(-1)) == 65535u);
    CHECK(static_cast<INT>(UINT(65535)) == -1);
    CHECK(static_cast<BYTE>(WORD(0x1234)) == 0x34);
    CHECK(static_cast<USINT>(BYTE(200)) == 200u);
  }

  TEST_CASE("widening is implicit and exact") {
    const SINT s = -5;
    const INT i = s;
    const DINT d = i;
    const LINT l = d;
    const USINT u = 200;
    const INT from_unsigned = u;
    CHECK(l == -5);
    CHECK(from_unsigned == 200);
    const DINT sum = i + d;  // INT + DINT is DINT
    CHECK(sum == -10);
  }

  TEST_CASE("a C++ integer converts where every value fits, even at run time") {
    const int n = opaque(DINT(123456)).value();
    DINT d = n;  // int -> DINT cannot lose anything
    d += n;
    CHECK(d == 246912);
    const std::int16_t small = 300;
    INT i = small;
    CHECK(i == 300);
    INT constant = -32768;  // an int constant: checked at compile time
    CHECK(constant == std::numeric_limits<INT>::min());
  }

  TEST_CASE("comparison with C++ integers compares mathematical values") {
    CHECK(INT(-1) < 4000000000u);
    CHECK(UDINT(4000000000u) > -1);
    CHECK(ULINT(18446744073709551615u) == 18446744073709551615u);
    CHECK(SINT(-1) != 255);
    CHECK(DINT(5) >= 5);
    CHECK(5 <= DINT(5));
  }

  TEST_CASE("value() and explicit casts give the C++ integer") {
    const INT i = -7;
    CHECK(i.value() == -7);
    CHECK(static_cast<long>(i) == -7L);
    CHECK(static_cast<double>(UINT(40000)) == 40000.0);
  }

  TEST_CASE("BOOL: TRUE and FALSE, ST's operators, conditions") {
    BOOL a = TRUE;
    const BOOL b = FALSE;
    CHECK((a & b) == FALSE);
    CHECK((a | b) == TRUE);
    CHECK((a ^ a) == FALSE);
    CHECK(!b == TRUE);
    CHECK((a && !b));
    CHECK(a == true);
    a &= b;
    CHECK(a == FALSE);
    a |= TRUE;
    a ^= TRUE;
    CHECK(a == FALSE);
    int branch = 0;
    if (a)
      branch = 1;
    else if (!a)
      branch = 2;
    CHECK(branch == 2);
    const BOOL comparison = INT(5) > 3;
    CHECK(comparison == TRUE);
    CHECK(FALSE < TRUE);  // IEC orders BOOL: FALSE < TRUE
    CHECK(TRUE >= TRUE);
  }

  TEST_CASE("REAL and LREAL behave as their floating type with IEC's conversions") {
    REAL r = 1.5;
    r = r * 2.0f;
    CHECK(r == 3.0f);
    r += 1.0f;
    r -= 0.5f;
    r *= 2.0f;
    r /= 7.0f;
    CHECK(r == doctest::Approx(1.0));
    const INT i = -300;
    r = i;  // INT -> REAL is exact, hence implicit
    CHECK(r == -300.0f);
    LREAL l = r;  // REAL -> LREAL is exact
    l = DINT(2147483647);
    CHECK(l == 2147483647.0);
    const REAL back = REAL(LREAL(0.1));  // LREAL -> REAL only explicitly
    CHECK(back == 0.1f);
    static_assert(std::is_same_v<decltype(r + 1.0f), float>);
  }

  TEST_CASE("signed and unsigned meet in a signed type, a bit string and an integer need a conversion") {
    static_assert(std::is_same_v<decltype(INT() + UINT()), intermediate<DINT>>);
    static_assert(std::is_same_v<decltype(SINT() + USINT()), intermediate<INT>>);
    static_assert(std::is_same_v<decltype(UDINT() - DINT()), intermediate<LINT>>);
    static_assert(std::is_same_v<decltype(DINT() + UINT()), intermediate<DINT>>);  // UINT widens to DINT
    static_assert(!addable<DINT, WORD>);
    static_assert(!addable<LINT, ULINT>);
    CHECK(INT(-1) + UINT(65535) == 65534);
    CHECK(static_cast<INT>(UINT(65535)) + INT(1) == 0);
  }
}
