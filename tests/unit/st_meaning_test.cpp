// A line-by-line port means what the ST means: the places where C++'s own meaning would differ
// (integer promotion, body inheritance, implicit conversions, BOOL results of comparisons,
// variable wrappers) — each with the ST it ports and the result CODESYS gives.
#include "iecoop_test.hpp"

#include <algorithm>
#include <array>
#include <map>

using namespace iecoop;
using iecoop_test::opaque;

namespace {

// --- Bodies along EXTENDS ---------------------------------------------------------------

// FUNCTION_BLOCK fbA  VAR_OUTPUT iCalls : INT; END_VAR   iCalls := iCalls + 1;
struct fbA : function_block<fbA> {
  INT iCalls;
  using VAR_OUTPUT = pins<&fbA::iCalls>;
  virtual void body() { iCalls = iCalls + 1; }
};
// FUNCTION_BLOCK fbEmpty EXTENDS fbA   (its implementation is empty)
struct fbEmpty : extends<fbEmpty, fbA> {
  void body() override {}
};
// FUNCTION_BLOCK fbSuper EXTENDS fbA   SUPER^(); iCalls := iCalls + 10;
struct fbSuper : extends<fbSuper, fbA> {
  void body() override {
    SUPER::body();  // SUPER^();
    iCalls = iCalls + 10;
  }
};

// A base whose body is noexcept: the derived block's override is noexcept as well.
struct fbQuiet : function_block<fbQuiet> {
  var<INT> n;
  virtual void body() noexcept { n = n + 1; }
};
struct fbQuieter : extends<fbQuieter, fbQuiet> {
  void body() noexcept override {
    SUPER::body();
    n = n + 10;
  }
};

// --- VAR written by a derived block, read from outside ------------------------------------

// FUNCTION_BLOCK FB_Motor  VAR nStarts : INT; bOn : BOOL; END_VAR
struct FB_Motor : function_block<FB_Motor> {
  BOOL bStart;
  using VAR_INPUT = pins<&FB_Motor::bStart>;
  var<INT> nStarts;
  var<BOOL> bOn;
  virtual void body() {
    if (bStart & ~bOn) nStarts = nStarts + 1;  // IF bStart AND NOT bOn THEN nStarts := nStarts + 1;
    bOn = bStart;
  }
};
// FUNCTION_BLOCK FB_CountingMotor EXTENDS FB_Motor: writes its base's VAR.
struct FB_CountingMotor : extends<FB_CountingMotor, FB_Motor> {
  void Reset() { nStarts = 0; }  // ACTION Reset: nStarts := 0;
  void body() override {
    SUPER::body();
    if (nStarts == 3) nStarts += 100;  // IF nStarts = 3 THEN nStarts := nStarts + 100; END_IF
  }
};

// --- Variable wrappers take ST's implicit conversions ------------------------------------

struct Widen_vars {
  DINT dIn;
  LREAL lIn;
};
struct FB_Widen : function_block<FB_Widen> {
  INT i = 7;
  REAL r = 1.5f;
  var<INT> vi{3};
  var<REAL> vr{2.5f};
  var<DINT> dOut;
  var<LREAL> lOut;
  var<STRING<>> sLong{"conveyor belt one"};
  var<STRING<12>> sShort;
  DINT Sum(args<Widen_vars> in) { return in.dIn + DINT(1); }
  void body() {
    dOut = i;          // dOut := i;        INT -> DINT
    lOut = r;          // lOut := r;        REAL -> LREAL
    sShort = sLong;    // sShort := sLong;  STRING -> STRING(12), truncating
    dOut = vi;         // dOut := vi;       a VAR INT into a VAR DINT
    lOut = lOut + vr;  // lOut := lOut + vr;
  }
};

// --- Interfaces in VARs --------------------------------------------------------------------

struct I_Lamp : interface_base<I_Lamp> {
  virtual void Switch(args<Widen_vars> in) = 0;
  virtual DINT Count() = 0;
};
struct FB_Lamp : function_block<FB_Lamp, implements<I_Lamp>> {
  DINT dSwitches;
  void Switch(args<Widen_vars> in) override { dSwitches = dSwitches + in.dIn; }
  DINT Count() override { return dSwitches; }
  void body() {}
};
struct FB_Panel : function_block<FB_Panel> {
  var<itf<I_Lamp>> ipLamp;  // VAR ipLamp : I_Lamp; END_VAR
  void Wire(FB_Lamp& lamp) { ipLamp = lamp; }
  void body() {
    if (ipLamp != 0) ipLamp->Switch({"dIn"_ = 2});  // IF ipLamp <> 0 THEN ipLamp.Switch(dIn := 2); END_IF
  }
};

}  // namespace

TEST_SUITE("ST meaning: integer expressions compute in the register width") {
  TEST_CASE("CODESYS's operator examples: the temporary result is not cut to WORD") {
    // VAR wVar : WORD; dwVar : DWORD; END_VAR   wVar := 65535; dwVar := wVar + 1;
    WORD wVar = 65535;
    DWORD dwVar = wVar + 1;
    CHECK(dwVar == 65536);
    // wVar1 := 65535; wVar2 := 0; bVar1 := (wVar1 + 1) = wVar2; bVar2 := (wVar2 - 1) = wVar1;
    WORD wVar1 = 65535;
    WORD wVar2 = 0;
    BOOL bVar1 = (wVar1 + 1) == wVar2;
    BOOL bVar2 = (wVar2 - 1) == wVar1;
    CHECK(bVar1 == FALSE);
    CHECK(bVar2 == FALSE);
    // wVar3 := (wVar1 + 1); bVar1 := wVar3 = wVar2;   (the assignment cuts to WORD)
    WORD wVar3 = wVar1 + 1;
    bVar1 = wVar3 == wVar2;
    CHECK(bVar1 == TRUE);
    // bVar1 := TO_WORD(wVar1 + 1) = wVar2; bVar2 := TO_WORD(wVar2 - 1) = wVar1;
    bVar1 = TO_WORD(wVar1 + 1) == wVar2;
    bVar2 = TO_WORD(wVar2 - 1) == wVar1;
    CHECK(bVar1 == TRUE);
    CHECK(bVar2 == TRUE);
  }

  TEST_CASE("SA0063: (iVar + 10) / 2 does not wrap for iVar = 32767") {
    INT iVar = opaque(INT(32767));
    iVar = (iVar + 10) / 2;  // iVar := (iVar + 10) / 2;
    CHECK(iVar == 16388);
  }

  TEST_CASE("SA0066: usintTest - 1 <> 255 is TRUE, TO_USINT makes it FALSE") {
    USINT usintTest = 0;
    BOOL xError = usintTest - 1 != 255;  // xError := usintTest - 1 <> 255;
    CHECK(xError == TRUE);
    xError = TO_USINT(usintTest - 1) != 255;
    CHECK(xError == FALSE);
    // IF (liTest - 1) <> -1 THEN ... : LINT fills the register, no surprise.
    LINT liTest = 0;
    CHECK((liTest - 1) == -1);
  }

  TEST_CASE("a widening conversion of a temporary result keeps it whole, a narrowing one cuts") {
    const INT i = opaque(INT(32767));
    CHECK(INT_TO_DINT(i + 1) == 32768);
    CHECK(TO_DINT(i + 1) == 32768);
    const DINT d = i + 1;  // d := i + 1;  (ST computes in 32 bits at least)
    CHECK(d == 32768);
    const INT back = i + 1;
    CHECK(back == -32768);
    const REAL r = i + 1;  // r := i + 1;
    CHECK(r == 32768.0f);
  }

  TEST_CASE("an expression assigned to a variable that exists is cut as one it initialises") {
    // (Assignment stores the register's low bits directly, integer<>::operator=(intermediate).)
    INT i = opaque(INT(32767));
    DINT d = 0;
    d = i + 1;  // d := i + 1;   the register's 32768
    CHECK(d == 32768);
    i = i + 1;  // i := i + 1;   the INT's 16 bits
    CHECK(i == -32768);
    const SINT s = opaque(SINT(127));
    INT j = 0;
    j = s + 1;  // j := s + 1;   128 in the register, and in the INT
    CHECK(j == 128);
    UINT u = 0;
    u = opaque(USINT(255)) + 1;  // u := usi + 1;   256
    CHECK(u == 256);
    u = u - 257;  // u := u - 257;   -1 in the register, 65535 in the UINT
    CHECK(u == 65535);
  }

  TEST_CASE("mixed types meet in the wider type, and the result is a BOOL in comparisons") {
    const SINT s = -1;
    const INT i = 300;
    const DINT d = s + i;
    CHECK(d == 299);
    CHECK((s + i) * 1000 == 299000);  // INT * INT in a register: 299000, not cut to 16 bits
    CHECK(((i * 200) / 100) == 600);  // 60000 fits the register, not an INT
  }

  TEST_CASE("a signed and an unsigned type meet in the signed type that holds both") {
    const INT i = opaque(INT(-1));
    const UINT u = opaque(UINT(65535));
    const DINT d = i + u;  // d := i + u;   (INT and UINT both widen to DINT)
    CHECK(d == 65534);
    CHECK((i < u) == TRUE);  // C++ would compare converted bits; ST compares the values
    const SINT s = opaque(SINT(-1));
    const USINT us = opaque(USINT(255));
    const INT sum = s + us;  // SINT and USINT meet as INT
    CHECK(sum == 254);
    const DINT dd = opaque(DINT(-1));
    const UDINT ud = opaque(UDINT(4000000000U));
    const LINT wide = dd + ud;  // DINT and UDINT meet as LINT
    CHECK(wide == 3999999999LL);
  }

  TEST_CASE("a compound assignment is x := x <op> v, with v computed whole") {
    INT i = opaque(INT(30000));
    const INT a = opaque(INT(300));
    i /= a * a;  // i := i / (a * a);   the divisor is 90000, not 90000 cut to 16 bits
    CHECK(i == 0);
    i = 30000;
    i -= a * a / 10;  // i := i - a * a / 10;
    CHECK(i == 21000);
    const SINT s = opaque(SINT(-3));
    i += s;  // a narrower variable
    CHECK(i == 20997);
    i %= (s + 10);
    CHECK(i == 20997 % 7);
    REAL r = 1.5f;
    r += a;  // r := r + a;   (INT into REAL)
    CHECK(r == 301.5f);
    r -= a + 1;
    CHECK(r == 0.5f);
    LREAL l = 1.0;
    l += r;
    l *= DINT(4);
    CHECK(l == 6.0);
    TIME t = "T#10ms"_iec;
    t = t * (a / 100 + 1);  // t := t * (a / 100 + 1);   an intermediate factor
    CHECK(t == "T#40ms"_iec);
  }

  TEST_CASE("assignment still wraps, and nothing is undefined behaviour") {
    INT i = opaque(INT(-32768));
    i = -i;
    CHECK(i == -32768);
    LINT l = opaque(LINT(std::numeric_limits<std::int64_t>::min()));
    l = l - 1;
    CHECK(l == std::numeric_limits<std::int64_t>::max());
  }
}

TEST_SUITE("ST meaning: REAL meets integers as ST converts them") {
  TEST_CASE("r := r * i: the integer converts to REAL where REAL holds it exactly") {
    REAL r = 1.5f;
    const INT i = 3;
    r = r * i;  // r := r * i;
    CHECK(r == 4.5f);
    r = i * 2.5f;  // r := i * 2.5;   (INT * REAL: a REAL)
    CHECK(r == 7.5f);
    LREAL l = 0.5;
    const DINT d = 100000;
    l = l + d;  // l := l + d;   (DINT with LREAL: exact)
    CHECK(l == 100000.5);
    l = d / 3.0;  // not an integer division: a REAL operand makes the division REAL
    CHECK(l > 33333.33);
    r = (i + 1) * 0.5f;  // an intermediate result too
    CHECK(r == 2.0f);
    const BOOL b = (i > 2.5) & (r < i) & (d == 100000.0);
    CHECK(b == TRUE);
  }
}

TEST_SUITE("ST meaning: comparisons yield BOOL") {
  TEST_CASE("b := x = 1 OR x = 3") {
    INT x = 3;
    BOOL b = (x == 1) | (x == 3);
    CHECK(b == TRUE);
    x = 2;
    b = (x == 1) | (x == 3);
    CHECK(b == FALSE);
    // AND, XOR and NOT combine comparisons too, with every IEC type on either side.
    REAL r = 2.0f;
    TIME t = "T#2s"_iec;
    STRING<> s = "abc";
    b = ((r > 1.5f) & (t >= "T#1s"_iec) & ~(s != "abc")) ^ (x < 0);
    CHECK(b == TRUE);
    b = ("abc" == s) & (0 < x) & (1.0f < r) & (x + 1 > 2);
    CHECK(b == TRUE);
  }

  TEST_CASE("a BOOL is a condition wherever C++ wants one") {
    const BOOL b = TRUE;
    const bool plain = b;
    CHECK(plain);
    std::array<INT, 3> values{INT(3), INT(1), INT(2)};
    std::sort(values.begin(), values.end());  // INT's < yields BOOL, which std::sort takes
    CHECK(values[0] == 1);
    CHECK(std::ranges::is_sorted(values));
    std::map<INT, int> by_id{{INT(2), 20}, {INT(1), 10}};
    CHECK(by_id.begin()->second == 10);
  }
}

TEST_SUITE("ST meaning: a derived block runs its own body") {
  TEST_CASE("an empty derived implementation runs nothing, also through a base reference") {
    fbEmpty b;
    b();
    fbA& a = b;
    a();
    CHECK(b.iCalls == 0);
  }
  TEST_CASE("a noexcept body is extended like any other") {
    fbQuieter b;
    b();
    fbQuiet& a = b;
    a();
    CHECK(b.n == 22);
  }
  TEST_CASE("SUPER^() runs the base's implementation") {
    fbSuper b;
    b();
    fbA& a = b;
    a("iCalls"_ >> b.iCalls);
    CHECK(b.iCalls == 22);
  }
}

TEST_SUITE("ST meaning: variables") {
  TEST_CASE("a derived block writes its base's VAR, outside code reads it") {
    FB_CountingMotor motor;
    for (int i = 0; i < 3; ++i) {
      motor("bStart"_ = TRUE);
      motor("bStart"_ = FALSE);
    }
    CHECK(motor.nStarts == 103);  // read from outside, as CODESYS allows
    CHECK(motor.bOn == FALSE);
    motor.Reset();
    CHECK(motor.nStarts == 0);
  }

  TEST_CASE("a VAR takes ST's implicit conversions, from values and from other VARs") {
    FB_Widen fb;
    fb();
    CHECK(fb.dOut == 3);
    CHECK(fb.lOut == 4.0);
    CHECK(fb.sShort == "conveyor bel");
    // A VAR passed to a method input of a wider type.
    CHECK(fb.Sum({"dIn"_ = fb.vi}) == 4);
    CHECK(fb.Sum(fb.vi) == 4);
  }

  TEST_CASE("a VAR reads into a variable of a wider type, as ST assigns it") {
    FB_Widen fb;
    fb();
    const DINT wide = fb.vi;  // nWide := fb.vi;   (a var<INT> into a DINT)
    CHECK(wide == 3);
    LREAL l = 0.0;
    l = fb.vi;
    CHECK(l == 3.0);
    TON tmr;
    tmr("IN"_ = TRUE, "PT"_ = "T#1s"_iec);
    LTIME elapsed;
    elapsed = tmr.ET;  // ltElapsed := tmr.ET;   (TIME into LTIME)
    CHECK(elapsed == LTIME(tmr.ET.get()));
  }

  TEST_CASE("compound assignment works alike on every variable form") {
    struct FB_Bits : function_block<FB_Bits> {
      var<WORD> wFlags{0x00F0};
      retain<WORD> wKept{0x000F};
      var<INT> iCount;
      var<REAL> rSum;
      var<TIME> tTotal;
      void body() {
        wFlags |= 0x0100;  // wFlags := wFlags OR 16#100;
        wFlags &= 0x0FF0;  // wFlags := wFlags AND 16#FF0;
        wKept ^= 0x0003;   // wKept := wKept XOR 3;
        iCount += 2;       // iCount := iCount + 2;
        iCount *= 5;
        iCount -= 1;
        ++iCount;
        rSum += 0.5f;
        tTotal += "T#250ms"_iec;
        tTotal *= 2;
      }
    };
    FB_Bits fb;
    fb();
    CHECK(fb.wFlags == 0x01F0);
    CHECK(fb.wKept == 0x000C);
    CHECK(fb.iCount == 10);
    CHECK(fb.rSum == 0.5f);
    CHECK(fb.tTotal == "T#500ms"_iec);
  }

  TEST_CASE("a VAR of an interface type calls through ->, and compares with 0") {
    FB_Lamp lamp;
    FB_Panel panel;
    panel();  // ipLamp = 0: nothing is called
    CHECK(lamp.dSwitches == 0);
    panel.Wire(lamp);
    panel();
    panel();
    CHECK(lamp.dSwitches == 4);
    CHECK(panel.ipLamp->Count() == 4);
  }

  TEST_CASE("the string functions take STRING variables and positions in any variable form") {
    struct FB_Text : function_block<FB_Text> {
      var<STRING<20>> sLine{"Station A: ready"};
      var<INT> iAt;
      var<STRING<20>> sHead;
      void body() {
        iAt = FIND(sLine, ":");        // iAt := FIND(sLine, ':');
        sHead = LEFT(sLine, iAt - 1);  // sHead := LEFT(sLine, iAt - 1);
      }
    };
    FB_Text fb;
    fb();
    CHECK(fb.iAt == 10);
    CHECK(fb.sHead == "Station A");
    CHECK(LEN(fb.sLine) == 16);
    CHECK(MID(fb.sLine, 2, fb.iAt - 1) == "A:");  // MID(sLine, 2, iAt - 1): length, then position
  }

  TEST_CASE("CASE on a VAR or RETAIN of an enumeration, IF on a VAR BOOL") {
    enum class E_Mode { Off, Manual, Auto };
    struct FB_Mode : function_block<FB_Mode> {
      var<E_Mode> eMode{E_Mode::Manual};
      retain<E_Mode> eKept{E_Mode::Auto};
      var<BOOL> bOn;
      INT iSeen;
      void body() {
        switch (eMode) {  // CASE eMode OF
          case E_Mode::Manual: iSeen = 1; break;
          default: iSeen = 0; break;
        }
        switch (eKept) {
          case E_Mode::Auto: iSeen = iSeen + 10; break;
          default: break;
        }
        if (~bOn) bOn = TRUE;  // IF NOT bOn THEN bOn := TRUE; END_IF
      }
    };
    FB_Mode fb;
    fb();
    CHECK(fb.iSeen == 11);
    const bool on = fb.bOn;
    CHECK(on);
  }

  TEST_CASE("TIME(system_time) is ST's TIME(), TIME() is T#0ms") {
    cycle_clock::set("LTIME#1m2s3ms4us"_iec);
    const TIME now = TIME(system_time);  // tNow := TIME();
    const LTIME lnow = LTIME(system_time);
    CHECK(now == "T#1m2s3ms"_iec);
    CHECK(lnow == "LTIME#1m2s3ms4us"_iec);
    CHECK(TIME() == "T#0ms"_iec);
    cycle_clock::set(LTIME());
  }
}
