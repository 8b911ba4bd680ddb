// The IEC standard functions of the numerical, arithmetic, bit-shift, bitwise, selection and
// comparison tables, at their edges, against IEC's and CODESYS's definitions.
#include <cmath>
#include <numbers>
#include <type_traits>

#include "iecoop_test.hpp"

using namespace iecoop;
using iecoop_test::fault_recorder;
using iecoop_test::opaque;

namespace {

// A block whose VAR the functions read through its wrapper.
struct FB_Holder : function_block<FB_Holder> {
  var<INT> iKept{40};
  var<REAL> rKept{2.5f};
  void body() {}
};

}  // namespace

TEST_SUITE("standard functions: selection") {
  TEST_CASE("SEL picks IN0 for FALSE and IN1 for TRUE") {
    CHECK(SEL(FALSE, INT(1), INT(2)) == 1);
    CHECK(SEL(TRUE, INT(1), INT(2)) == 2);
    CHECK(SEL(opaque(TRUE), "T#2s"_iec, "T#500ms"_iec) == "T#500ms"_iec);
    const bool cpp_condition = false;
    CHECK(SEL(cpp_condition, 1.5, 2.5) == 1.5);
  }

  TEST_CASE("MAX and MIN are extensible and keep the first of equal inputs") {
    CHECK(MAX(INT(3), INT(9), INT(-4), INT(9)) == 9);
    CHECK(MIN(INT(3), INT(9), INT(-4), INT(9)) == -4);
    CHECK(MAX(opaque(UDINT(7)), UDINT(4000000000u)) == 4000000000u);
    CHECK(MIN("T#1s"_iec, "T#999ms"_iec) == "T#999ms"_iec);
  }

  TEST_CASE("inputs take the type ST's a + b would give them") {
    INT i = 300;
    DINT d = 100000;
    REAL r = 2.5f;
    LREAL lr = 7.25;
    static_assert(std::is_same_v<decltype(MAX(i, i)), INT>);
    static_assert(std::is_same_v<decltype(MAX(i, d)), DINT>);
    static_assert(std::is_same_v<decltype(MAX(i, r)), REAL>);
    static_assert(std::is_same_v<decltype(MAX(r, lr)), LREAL>);
    static_assert(std::is_same_v<decltype(MAX(i, 5)), INT>);  // the C++ number takes INT
    static_assert(std::is_same_v<decltype(MAX(1, 2)), int>);  // only C++ numbers: C++'s type
    static_assert(std::is_same_v<decltype(MIN("T#1s"_iec, "LT#1s"_iec)), LTIME>);
    static_assert(std::is_same_v<decltype(MAX(STRING<5>("a"), STRING<12>("b"))), STRING<12>>);
    CHECK(MAX(i, d) == 100000);
    CHECK(MIN(i, r) == 2.5f);
    CHECK(MAX(r, lr, 3) == 7.25);
  }

  TEST_CASE("an intermediate result keeps its register until it is assigned") {
    const INT i = opaque(INT(32767));
    const auto m = MAX(i + 1, INT(0));
    static_assert(std::is_same_v<std::remove_const_t<decltype(m)>, intermediate<INT>>);
    CHECK(m == 32768);                     // as `i + 1 > 0` sees it
    const DINT kept = MAX(i + 1, INT(0));  // widened: the whole register
    CHECK(kept == 32768);
    const INT cut = MAX(i + 1, INT(0));  // assigned to an INT: wraps
    CHECK(cut == -32768);
  }

  TEST_CASE("variables of blocks, properties and the like pass their values") {
    FB_Holder fb;
    CHECK(MAX(fb.iKept, 3) == 40);
    CHECK(LIMIT(0, fb.iKept, 10) == 10);
    CHECK(MIN(fb.rKept, 1.0f) == 1.0f);
    CHECK(SEL(fb.iKept > 30, fb.rKept, 0.0f) == 0.0f);
  }

  TEST_CASE("a C++ integer out of the IEC inputs' range is a fault and keeps the low bytes") {
    fault_recorder faults;
    const int big = opaque(70000);
    const INT m = MAX(INT(1), big);
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(m == INT(static_cast<std::int16_t>(70000 - 65536)));
    CHECK(MAX(INT(1), opaque(300)) == 300);
    CHECK(faults.count == 1);
  }

  TEST_CASE("LIMIT is MIN(MAX(IN, MN), MX): with MN > MX the result is MX, as CODESYS computes") {
    CHECK(LIMIT(30, INT(90), 80) == 80);  // the CODESYS page's example
    CHECK(LIMIT(INT(30), INT(10), INT(80)) == 30);
    CHECK(LIMIT(INT(30), INT(50), INT(80)) == 50);
    CHECK(LIMIT(INT(100), INT(5), INT(0)) == 0);  // MN > MX
    CHECK(LIMIT(INT(100), INT(500), INT(0)) == 0);
    CHECK(LIMIT(0.0f, REAL(123.4f), 100.0f) == 100.0f);
    CHECK(LIMIT("T#1s"_iec, "T#10s"_iec, "T#5s"_iec) == "T#5s"_iec);
  }

  TEST_CASE("MUX counts from 0, and out of range, above or below, it passes the last input (CODESYS)") {
    CHECK(MUX(0, 30, 40, 50, 60, 70, 80) == 30);  // the CODESYS page's example
    CHECK(MUX(INT(2), INT(30), INT(40), INT(50)) == 50);
    CHECK(MUX(BYTE(7), INT(30), INT(40), INT(50)) == 50);
    CHECK(MUX(opaque(INT(-1)), INT(30), INT(40), INT(50)) == 50);
    CHECK(MUX(ULINT(0xFFFF'FFFF'FFFF'FFFFull), INT(30), INT(40)) == 40);
    CHECK(MUX(1, STRING<4>("abc"), STRING<10>("defghij")) == "defghij");
    CHECK(MUX(0, INT(7)) == 7);
  }

  TEST_CASE("the selection functions are constexpr") {
    static_assert(MAX(INT(1), INT(5), INT(3)) == 5);
    static_assert(MIN(DINT(1), DINT(-5)) == -5);
    static_assert(LIMIT(INT(0), INT(50), INT(10)) == 10);
    static_assert(MUX(1, INT(10), INT(20)) == 20);
    static_assert(SEL(TRUE, INT(10), INT(20)) == 20);
  }
}

TEST_SUITE("standard functions: bit shift and bitwise") {
  TEST_CASE("SHL and SHR work in IN's width: the CODESYS pages' examples") {
    const BYTE in_byte = 0x45;
    const WORD in_word = 0x0045;
    const BYTE n = 2;
    CHECK(SHL(in_byte, n) == 0x14);
    CHECK(SHL(in_word, n) == 0x0114);
    CHECK(SHR(in_byte, n) == 0x11);
    CHECK(SHR(in_word, n) == 0x0011);
    static_assert(std::is_same_v<decltype(SHL(in_byte, n)), BYTE>);
  }

  TEST_CASE("a shift by the width or more, or by a negative count, gives 0") {
    CHECK(SHL(BYTE(0xFF), 7) == 0x80);
    CHECK(SHL(BYTE(0xFF), 8) == 0);
    CHECK(SHR(WORD(0xFFFF), 16) == 0);
    CHECK(SHL(DWORD(1), opaque(INT(31))) == 0x8000'0000u);
    CHECK(SHL(DWORD(1), 32) == 0);
    CHECK(SHL(LWORD(1), 63) == 0x8000'0000'0000'0000ull);
    CHECK(SHR(LWORD(0x8000'0000'0000'0000ull), 64) == 0);
    CHECK(SHL(BYTE(1), opaque(INT(-1))) == 0);
    CHECK(SHR(BYTE(0x80), ULINT(1000)) == 0);
    CHECK(SHL(WORD(0x1234), 0) == 0x1234);
  }

  TEST_CASE("ROL and ROR rotate modulo the width, and a negative count turns the other way") {
    CHECK(ROL(BYTE(0x81), 1) == 0x03);
    CHECK(ROL(BYTE(0x81), 9) == 0x03);  // a BYTE by 9 is by 1
    CHECK(ROR(BYTE(0x81), 1) == 0xC0);
    CHECK(ROR(BYTE(0x81), 17) == 0xC0);
    CHECK(ROL(BYTE(0x81), -1) == 0xC0);
    CHECK(ROR(BYTE(0x81), opaque(INT(-1))) == 0x03);
    CHECK(ROL(WORD(0x8001), 4) == 0x0018);
    CHECK(ROL(DWORD(0x8000'0001u), 32) == 0x8000'0001u);
    CHECK(ROR(LWORD(1), 1) == 0x8000'0000'0000'0000ull);
    CHECK(ROL(LWORD(0xC000'0000'0000'0000ull), 65) == 0x8000'0000'0000'0001ull);
  }

  TEST_CASE("an intermediate result is cut to its type before it is shifted") {
    const WORD w = opaque(WORD(0xFFFF));
    CHECK(SHR(w + 1, 1) == 0);  // WORD 16#0000, not the register's 16#10000 / 2
    CHECK(ROL(w + 2, 4) == 0x0010);
  }

  TEST_CASE("AND, OR, XOR and NOT as functions, extensible as IEC defines them") {
    CHECK(AND(TRUE, TRUE, opaque(TRUE)) == TRUE);
    CHECK(AND(TRUE, FALSE, TRUE) == FALSE);
    CHECK(OR(FALSE, FALSE, opaque(TRUE)) == TRUE);
    CHECK(XOR(TRUE, TRUE) == FALSE);
    CHECK(XOR(TRUE, TRUE, TRUE) == TRUE);  // odd parity
    CHECK(AND(WORD(0xFF0F), WORD(0x0FFF), WORD(0x00F3)) == 0x0003);
    CHECK(OR(BYTE(0x01), BYTE(0x10), BYTE(0x80)) == 0x91);
    CHECK(XOR(WORD(0x00FF), 0x0F0F) == 0x0FF0);
    CHECK(NOT(BYTE(0x0F)) == 0xF0);
    CHECK(NOT(WORD(0)) == 0xFFFF);
    CHECK(NOT(opaque(FALSE)) == TRUE);
    static_assert(std::is_same_v<decltype(NOT(BYTE(0))), BYTE>);
  }

  TEST_CASE("the bit functions are constexpr") {
    static_assert(SHL(BYTE(0x45), 2) == 0x14);
    static_assert(ROR(WORD(1), 1) == 0x8000);
    static_assert(XOR(BYTE(0xF0), BYTE(0xFF)) == 0x0F);
  }
}

TEST_SUITE("standard functions: numerical") {
  TEST_CASE("ABS keeps the type, and of the most negative integer it is computed in the register") {
    CHECK(ABS(INT(-5)) == 5);
    CHECK(ABS(opaque(REAL(-2.5f))) == 2.5f);
    CHECK(ABS(LREAL(3.0)) == 3.0);
    const INT most_negative = opaque(INT(-32768));
    const DINT wide = ABS(most_negative);
    CHECK(wide == 32768);
    const INT wrapped = ABS(most_negative);
    CHECK(wrapped == -32768);  // as `-i` assigned to an INT
    static_assert(ABS(DINT(-7)) == 7);
    static_assert(std::is_same_v<decltype(ABS(REAL(1.0f))), REAL>);
  }

  TEST_CASE("the REAL functions return their input's REAL type, and integers as the REAL type they convert to") {
    static_assert(std::is_same_v<decltype(SQRT(REAL(2.0f))), REAL>);
    static_assert(std::is_same_v<decltype(SQRT(LREAL(2.0))), LREAL>);
    static_assert(std::is_same_v<decltype(SQRT(INT(16))), REAL>);
    static_assert(std::is_same_v<decltype(SQRT(DINT(16))), LREAL>);
    static_assert(std::is_same_v<decltype(EXPT(REAL(2.0f), 10)), LREAL>);         // always LREAL, as TwinCAT documents
    static_assert(!std::is_convertible_v<decltype(EXPT(REAL(2.0f), 10)), REAL>);  // into a REAL: LREAL_TO_REAL
    CHECK(SQRT(INT(16)) == 4.0f);
    CHECK(SQRT(opaque(LREAL(2.0))) == doctest::Approx(std::numbers::sqrt2));
    CHECK(LN(LREAL(std::numbers::e)) == doctest::Approx(1.0));
    CHECK(LOG(REAL(1000.0f)) == doctest::Approx(3.0));
    CHECK(EXP(LREAL(0.0)) == 1.0);
    CHECK(SIN(LREAL(std::numbers::pi / 2)) == doctest::Approx(1.0));
    CHECK(COS(LREAL(0.0)) == 1.0);
    CHECK(TAN(LREAL(std::numbers::pi / 4)) == doctest::Approx(1.0));
    CHECK(ASIN(LREAL(1.0)) == doctest::Approx(std::numbers::pi / 2));
    CHECK(ACOS(LREAL(-1.0)) == doctest::Approx(std::numbers::pi));
    CHECK(ATAN(LREAL(1.0)) == doctest::Approx(std::numbers::pi / 4));
  }

  TEST_CASE("ATAN2 takes the quadrant from both signs") {
    CHECK(ATAN2(LREAL(1.0), LREAL(1.0)) == doctest::Approx(std::numbers::pi / 4));
    CHECK(ATAN2(LREAL(1.0), LREAL(-1.0)) == doctest::Approx(3 * std::numbers::pi / 4));
    CHECK(ATAN2(LREAL(-1.0), LREAL(-1.0)) == doctest::Approx(-3 * std::numbers::pi / 4));
    CHECK(ATAN2(REAL(0.0f), REAL(-1.0f)) == doctest::Approx(std::numbers::pi));
    static_assert(std::is_same_v<decltype(ATAN2(REAL(1.0f), LREAL(1.0))), LREAL>);
  }

  TEST_CASE("outside their domain the functions give IEEE 754's NaN and infinities") {
    CHECK(std::isnan(SQRT(opaque(REAL(-1.0f))).value()));
    CHECK(std::isnan(LN(LREAL(-1.0)).value()));
    CHECK(std::isinf(LN(LREAL(0.0)).value()));
    CHECK(LN(LREAL(0.0)) < 0.0);
    CHECK(std::isnan(ASIN(LREAL(2.0)).value()));
    CHECK(std::isnan(ACOS(REAL(-1.5f)).value()));
  }

  TEST_CASE("EXPT: negative bases to whole powers keep their sign, to fractional powers are NaN") {
    CHECK(EXPT(REAL(-2.0f), 3) == -8.0f);
    CHECK(EXPT(REAL(-2.0f), INT(2)) == 4.0f);
    CHECK(EXPT(LREAL(2.0), -2) == 0.25);
    CHECK(EXPT(LREAL(9.0), 0.5) == 3.0);
    CHECK(std::isnan(EXPT(LREAL(-8.0), 1.0 / 3.0).value()));
    CHECK(std::isinf(EXPT(opaque(LREAL(0.0)), -1).value()));
    CHECK(EXPT(LREAL(std::nan("")), 0) == 1.0);
    CHECK(EXPT(INT(3), 2) == 9.0);
    CHECK(EXPT(REAL(1.1f), 10) == std::pow(static_cast<double>(1.1f), 10.0));  // computed in LREAL
  }
}

TEST_SUITE("standard functions: arithmetic and comparison") {
  TEST_CASE("ADD and MUL are extensible and compute as the operators") {
    const INT i = opaque(INT(30000));
    static_assert(std::is_same_v<decltype(ADD(i, i)), intermediate<INT>>);
    const DINT sum = ADD(i, i, INT(10));
    CHECK(sum == 60010);  // in the register, as i + i + 10
    const INT cut = ADD(i, i);
    CHECK(cut == -5536);
    CHECK(MUL(INT(3), INT(4), INT(5)) == 60);
    CHECK(ADD(REAL(1.5f), 2, LREAL(0.25)) == 3.75);
    CHECK(ADD("T#1s"_iec, "T#500ms"_iec) == "T#1s500ms"_iec);
  }

  TEST_CASE("SUB, DIV and MOD take two inputs, and DIV and MOD by zero are faults giving 0") {
    CHECK(SUB(INT(3), INT(5)) == -2);
    CHECK(DIV(DINT(-7), 2) == -3);  // toward zero
    CHECK(MOD(DINT(-7), 2) == -1);  // the dividend's sign
    CHECK(DIV(REAL(1.0f), REAL(4.0f)) == 0.25f);
    fault_recorder faults;
    CHECK(DIV(INT(5), opaque(INT(0))) == 0);
    CHECK(MOD(INT(5), opaque(INT(0))) == 0);
    CHECK(faults.count == 2);
    CHECK(faults.last_kind == fault_kind::division_by_zero);
  }

  TEST_CASE("MOVE is the value") {
    FB_Holder fb;
    const INT copy = MOVE(fb.iKept);
    CHECK(copy == 40);
    static_assert(std::is_same_v<decltype(MOVE(fb.iKept)), INT>);
  }

  TEST_CASE("GT, GE, EQ, LE and LT compare each neighbouring pair, and NE compares two") {
    CHECK(GT(INT(3), INT(2), INT(1)) == TRUE);
    CHECK(GT(INT(3), INT(2), INT(2)) == FALSE);
    CHECK(GE(INT(3), INT(2), INT(2)) == TRUE);
    CHECK(EQ(DINT(7), 7, INT(7)) == TRUE);
    CHECK(EQ(DINT(7), 7, INT(8)) == FALSE);
    CHECK(LE(1, 2, 2, 3) == TRUE);
    CHECK(LT(REAL(1.0f), 2, LREAL(2.5)) == TRUE);
    CHECK(LT(REAL(1.0f), 2, LREAL(2.0)) == FALSE);
    CHECK(NE("T#1s"_iec, "T#1000ms"_iec) == FALSE);
    CHECK(NE(STRING<4>("ab"), STRING<8>("abc")) == TRUE);
    const INT i = opaque(INT(32767));
    CHECK(GT(i + 1, i) == TRUE);  // the register's 32768
    static_assert(LT(INT(1), INT(2), INT(3)));
  }
}
