// The conversions (TO_<type>, <A>_TO_<B>, convert<>) and the generic standard functions on every
// form a variable takes in a port — a block's var<>, retain<>, a standard block's output, a
// PROPERTY, a located variable, a REFERENCE, a method's inputs, outputs, in-outs and temps, an
// intermediate result, an ARRAY's element, a STRUCT's member, an enumeration, a subrange, a bit
// `x.N` — each with ST's meaning: the value's own conversion, as on a plain IEC value.
#include "iecoop_test.hpp"

#include <type_traits>

using namespace iecoop;

// (A named namespace: Clang warns about a variable template specialised for a type of an
// anonymous one.)
namespace conversion_forms {

// TYPE E_State : (Idle, Run := 10, Fault); END_TYPE
enum E_State : INT::rep { Idle, Run = 10, Fault };
// {attribute 'qualified_only'} {attribute 'strict'} {attribute 'to_string'} TYPE E_Mode : (Off, Manual, Auto); END_TYPE
enum class E_Mode : INT::rep { Off, Manual, Auto };

}  // namespace conversion_forms

using conversion_forms::E_Mode;
using conversion_forms::E_State;
using conversion_forms::Run;

template <>
inline constexpr bool iecoop::enum_strict<E_Mode> = true;
template <>
inline constexpr bool iecoop::enum_to_string<E_Mode> = true;
template <>
inline constexpr auto iecoop::enum_components<E_Mode> = components<E_Mode::Off, E_Mode::Manual, E_Mode::Auto>{};

namespace {

struct forms_tag;
using forms_image = process_image<8, 8, 8, addressing::codesys, forms_tag>;

struct ST_Pos {
  REAL x;
  INT n;
};

using T_Percent = subrange<INT, -100, 100>;

// A block with a variable of each kind, and properties that count their Get calls.
struct FB_Forms : function_block<FB_Forms> {
  var<INT> iVar{5};
  var<REAL> rVar{2.5f};
  var<BOOL> bVar{TRUE};
  var<TIME> tVar{"T#1s500ms"_iec};
  var<DINT> dVar{-1};
  var<STRING<>> sVar{"42"};
  var<T_Percent> iPercent;
  T_Percent iLevel;
  var<ARRAY<INT, 1, 3>> aVar{ARRAY<INT, 1, 3>{7, -8, 9}};
  var<ST_Pos> stVar{ST_Pos{.x = -1.5f, .n = 300}};
  var<E_State> eState{Run};
  var<E_Mode> eMode{E_Mode::Manual};
  retain<DINT> diRetained{-1};
  TON tmr;
  int gets = 0;

  INT Count_Get() {
    ++gets;
    return iVar;
  }
  [[no_unique_address]] property<INT, &FB_Forms::Count_Get> Count{this};
  REAL Ratio_Get() {
    ++gets;
    return rVar;
  }
  [[no_unique_address]] property<REAL, &FB_Forms::Ratio_Get> Ratio{this};
  REAL Gain_Get() const { return 1.5f; }
  // PROPERTY Gain with a PRIVATE Get: read inside the block only, there with .get()
  [[no_unique_address]] property<REAL, &FB_Forms::Gain_Get, nullptr, owner_only_get> Gain{this};

  LREAL GainTwice() { return TO_LREAL(Gain.get()) * 2.0; }
  INT GainRounded() { return REAL_TO_INT(Gain); }  // the named conversion reads it as before

  void body() {}
};

// METHOD M : LREAL
//   VAR_INPUT iIn : INT; END_VAR  VAR_OUTPUT rOut : REAL; END_VAR  VAR_IN_OUT diIo : DINT; END_VAR
//   VAR iTmp : INT := -3; END_VAR
struct M_vars {
  INT iIn;
  output<REAL> rOut{2.5f};
  in_out<DINT> diIo;
  temp<INT> iTmp{INT(-3)};
};
struct FB_Method : function_block<FB_Method> {
  void body() {}
  LREAL M(args<M_vars> in) {
    // M := TO_LREAL(iIn) + TO_LREAL(iTmp) + INT_TO_LREAL(REAL_TO_INT(rOut)) + DINT_TO_LREAL(diIo);
    static_assert(std::is_same_v<decltype(TO_LREAL(in.rOut)), LREAL> && std::is_same_v<decltype(TO_INT(in.iTmp)), INT>);
    return TO_LREAL(in.iIn) + TO_LREAL(in.iTmp) + INT_TO_LREAL(REAL_TO_INT(in.rOut)) + DINT_TO_LREAL(in.diIo);
  }
};

struct GVL_IO {
  [[no_unique_address]] located<INT, "%IW1", forms_image> iSpeed;   // iSpeed AT %IW1 : INT;
  [[no_unique_address]] located<WORD, "%IW1", forms_image> wSpeed;  // the same bits as a WORD (not listed)
  [[no_unique_address]] located<BYTE, "%MB0", forms_image> byFlags;
  [[no_unique_address]] located<BOOL, "%QX0.3", forms_image> bLamp;
  [[no_unique_address]] located<DINT, "%MD1", forms_image> diCount;
};

}  // namespace

TEST_SUITE("conversions of every variable form") {
  TEST_CASE("a block's var<>, retain<> and a standard block's output convert as their values") {
    FB_Forms fb;
    static_assert(std::is_same_v<decltype(TO_LREAL(fb.iVar)), LREAL>);
    static_assert(std::is_same_v<decltype(INT_TO_REAL(fb.iVar)), REAL>);
    static_assert(std::is_same_v<decltype(DINT_TO_WORD(fb.diRetained)), WORD>);
    static_assert(std::is_same_v<decltype(TIME_TO_DINT(fb.tmr.ET)), DINT>);
    CHECK(TO_LREAL(fb.iVar) == 5.0);
    CHECK(INT_TO_REAL(fb.iVar) == 5.0f);
    CHECK(TO_INT(fb.rVar) == 3);  // 2.5 rounds away from zero
    CHECK(REAL_TO_INT(fb.rVar) == 3);
    fb.rVar = -1.5f;
    CHECK(REAL_TO_INT(fb.rVar) == -2);
    CHECK(BOOL_TO_INT(fb.bVar) == 1);
    CHECK(TO_INT(fb.bVar) == 1);
    CHECK(TIME_TO_DINT(fb.tVar) == 1500);
    CHECK(TO_DINT(fb.tVar) == 1500);
    CHECK(DINT_TO_WORD(fb.dVar) == WORD(0xFFFF));  // keeps the low bytes
    CHECK(DINT_TO_WORD(fb.diRetained) == WORD(0xFFFF));
    CHECK(TO_UDINT(fb.diRetained) == UDINT(0xFFFFFFFFu));
    CHECK(TIME_TO_DINT(fb.tmr.ET) == 0);
    CHECK(TO_STRING(fb.iVar) == "5");
    CHECK(convert<SINT>(fb.iVar) == 5);
    // A narrower variable goes into a named conversion of a wider source type, as its value does.
    CHECK(DINT_TO_LREAL(fb.iVar) == 5.0);
  }

  TEST_CASE("a PROPERTY converts as what its Get returns, read once per conversion") {
    FB_Forms fb;
    static_assert(std::is_same_v<decltype(TO_LREAL(fb.Count)), LREAL>);
    static_assert(std::is_same_v<decltype(REAL_TO_INT(fb.Ratio)), INT>);
    CHECK(TO_LREAL(fb.Count) == 5.0);
    CHECK(fb.gets == 1);
    CHECK(INT_TO_REAL(fb.Count) == 5.0f);
    CHECK(fb.gets == 2);
    CHECK(REAL_TO_INT(fb.Ratio) == 3);
    CHECK(TO_DINT(fb.Ratio) == 3);
    CHECK(convert<LREAL>(fb.Ratio) == 2.5);
    CHECK(fb.gets == 5);
    const FB_Forms& view = fb;  // through a const block the Get is still called
    CHECK(TO_INT(view.Count) == 5);
    CHECK(fb.gets == 6);
    // A Get for the block only: inside the block, .get() (and the named conversion as before).
    CHECK(fb.GainTwice() == 3.0);
    CHECK(fb.GainRounded() == 2);
  }

  TEST_CASE("a located variable converts as its declared type") {
    forms_image::clear();
    GVL_IO io;
    forms_image::write<INT, "%IW1">(INT(-300));
    static_assert(std::is_same_v<decltype(TO_DINT(io.iSpeed)), DINT>);
    CHECK(TO_DINT(io.iSpeed) == -300);  // an INT: signed
    CHECK(INT_TO_REAL(io.iSpeed) == -300.0f);
    CHECK(TO_DINT(io.wSpeed) == 65236);  // the same bits as a WORD
    CHECK(WORD_TO_INT(io.wSpeed) == -300);
    io.byFlags = BYTE(0xFF);
    CHECK(BYTE_TO_SINT(io.byFlags) == -1);  // reinterprets
    CHECK(TO_USINT(io.byFlags) == 255);
    io.bLamp = TRUE;
    CHECK(BOOL_TO_INT(io.bLamp) == 1);
    io.diCount = 70000;
    CHECK(DINT_TO_WORD(io.diCount) == WORD(70000 - 65536));
    CHECK(TO_LREAL(at<"%IW1", forms_image>) == 65236.0);  // a directly represented %IW: a WORD
  }

  TEST_CASE("a REFERENCE and an in-out convert as the variable they are bound to") {
    INT iTarget = 42;
    REFERENCE_TO<INT> refTarget;  // refTarget : REFERENCE TO INT;
    refTarget.bind(iTarget);      // refTarget REF= iTarget;
    static_assert(std::is_same_v<decltype(TO_LREAL(refTarget)), LREAL>);
    CHECK(TO_LREAL(refTarget) == 42.0);
    CHECK(INT_TO_REAL(refTarget) == 42.0f);
    iTarget = -7;
    CHECK(TO_SINT(refTarget) == -7);
    STRING<> sText = "17";
    in_out<STRING<>> ioText{sText};
    CHECK(STRING_TO_INT(ioText) == 17);
    CHECK(TO_DINT(ioText) == 17);
    REFERENCE_TO<INT> refUnbound;
    CHECK_FAULT(TO_LREAL(refUnbound), fault_kind::unbound_in_out);
  }

  TEST_CASE("a method's input, output, in-out and temp convert as their values") {
    FB_Method fb;
    DINT diIo = 100;
    // 4 + -3 + REAL_TO_INT(2.5) = 3 + 100
    CHECK(fb.M({"iIn"_ = 4, "diIo"_ = diIo}) == 104.0);
    output<REAL> rOut{-0.5f};
    temp<INT> iTmp{INT(9)};
    CHECK(REAL_TO_INT(rOut) == -1);  // -0.5 rounds away from zero
    CHECK(TO_WORD(iTmp) == WORD(9));
  }

  TEST_CASE("an intermediate result converts from its whole register") {
    FB_Forms fb;
    const INT a = 32767;
    const INT b = 1;
    static_assert(std::is_same_v<decltype(TO_LREAL(a + b)), LREAL>);
    CHECK(TO_LREAL(a + b) == 32768.0);
    CHECK(INT_TO_DINT(a + b) == 32768);
    CHECK(TO_INT(a + b) == -32768);                   // cut once converted to INT
    CHECK(TO_LREAL(fb.iVar + fb.iLevel) == 5.0);      // wrappers in the expression
    CHECK(INT_TO_REAL(fb.iVar * 10000) == 50000.0f);  // 50000 in the register, not cut to 16 bits
    CHECK(TO_LREAL(fb.Count - 6) == -1.0);
  }

  TEST_CASE("an ARRAY's element and a STRUCT's member convert as values of their type") {
    FB_Forms fb;
    ARRAY<REAL, 0, 1> arValues{1.5f, -2.5f};
    ST_Pos stPos{.x = 2.5f, .n = -4};
    CHECK(TO_LREAL(fb.aVar[2]) == -8.0);
    CHECK(INT_TO_REAL(fb.aVar[3]) == 9.0f);
    CHECK(REAL_TO_INT(arValues[0]) == 2);
    CHECK(TO_INT(arValues[1]) == -3);
    CHECK(REAL_TO_INT(stPos.x) == 3);
    CHECK(TO_LREAL(stPos.n) == -4.0);
    CHECK(REAL_TO_INT(fb.stVar->x) == -2);
    CHECK(INT_TO_BYTE(fb.stVar->n) == BYTE(300 - 256));
  }

  TEST_CASE("an enumeration converts as its base type's value, also from a variable") {
    FB_Forms fb;
    static_assert(std::is_same_v<decltype(TO_INT(fb.eState)), INT>);
    CHECK(TO_INT(fb.eState) == 10);
    CHECK(TO_DINT(fb.eState) == 10);  // into a wider type too, which `DINT d = eState;` is not
    CHECK(INT_TO_REAL(fb.eState) == 10.0f);
    CHECK(TO_INT(fb.eMode) == 1);  // 'strict': an explicit conversion is allowed
    CHECK(TO_STRING(fb.eMode) == "Manual");
    CHECK(TO_STRING(fb.eState) == "10");
  }

  TEST_CASE("a subrange converts as its base type, also inside a var<>") {
    FB_Forms fb;
    fb.iLevel = 50;
    fb.iPercent = -40;
    static_assert(std::is_same_v<decltype(TO_LREAL(fb.iPercent)), LREAL>);
    CHECK(TO_LREAL(fb.iLevel) == 50.0);
    CHECK(TO_LREAL(fb.iPercent) == -40.0);
    CHECK(INT_TO_REAL(fb.iPercent) == -40.0f);
    CHECK(INT_TO_BYTE(fb.iPercent) == BYTE(256 - 40));
    CHECK(TO_WORD(fb.iLevel) == WORD(50));
  }

  TEST_CASE("a bit x.N converts as a BOOL, a STRING variable as its text") {
    FB_Forms fb;
    WORD wFlags = 0x0008;
    CHECK(BOOL_TO_INT(bit<3>(wFlags)) == 1);
    CHECK(TO_INT(bit<2>(wFlags)) == 0);
    CHECK(STRING_TO_INT(fb.sVar) == 42);
    CHECK(TO_LREAL(fb.sVar) == 42.0);
  }

  TEST_CASE("the generic standard functions take the same forms") {
    FB_Forms fb;
    forms_image::clear();
    GVL_IO io;
    fb.iPercent = -40;
    fb.iLevel = 60;
    INT iTarget = 20;
    REFERENCE_TO<INT> refTarget;
    refTarget.bind(iTarget);
    forms_image::write<INT, "%IW1">(INT(30));

    static_assert(std::is_same_v<decltype(MAX(fb.iPercent, fb.iLevel)), INT>);
    CHECK(MAX(fb.iPercent, fb.iLevel) == 60);
    CHECK(MIN(fb.iPercent, fb.Count, io.iSpeed, refTarget) == -40);
    CHECK(LIMIT(0, fb.iPercent, 10) == 0);
    CHECK(LIMIT(fb.iVar, io.iSpeed, refTarget) == 20);
    CHECK(ABS(fb.iPercent) == 40);
    CHECK(SEL(fb.bVar, fb.iPercent, fb.iLevel) == 60);
    CHECK(MUX(fb.iVar - 4, fb.iPercent, fb.iLevel) == 60);
    CHECK(ADD(fb.iPercent, fb.iLevel, io.iSpeed) == 50);
    CHECK(MOVE(fb.iPercent) == -40);
    static_assert(std::is_same_v<decltype(MOVE(fb.iPercent)), INT>);
    CHECK(SQRT(fb.iLevel - 11) == 7.0f);
    CHECK(GT(fb.iLevel, io.iSpeed, fb.iPercent) == TRUE);
    CHECK(SHL(INT_TO_WORD(fb.iPercent), 1) == WORD(0xFFB0));
    CHECK(MUL_TIME(fb.tVar, fb.iVar) == "T#7s500ms"_iec);
    CHECK(LEFT(fb.sVar, fb.iVar - 4) == "4");
  }
}
