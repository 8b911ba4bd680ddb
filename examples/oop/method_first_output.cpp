// Seed: CODESYS "Objekt: Methode" (German page), declaration and call — "Hinweis: Bei Methoden,
// die keinen expliziten Rückgabetyp haben, wird die erste deklarierte Ausgabe als Rückgabewert
// verwendet. Nur wenn weder Rückgabetyp noch Ausgabe deklariert sind, liefert eine Methode
// keinen Wert zurück. Ein Compilerfehler wird aber in keinem der beiden Fälle erzeugt."
// (For methods without an explicit return type, the first declared output is used as the
// return value. Only if neither a return type nor an output is declared does a method return
// no value. Neither case is a compiler error.) The call is
// `<return value variable> := <POU name>.<method name>(<argument passing>);`.
//
// The seed states the rule without an example. We complete it minimally with the seed's DoIt,
// its return type dropped and two outputs declared (dwSum, the first, is DoIt's value);
// Limit, whose first output follows an in-out and an input and is left at its initial value
// by an early RETURN; and Reset, with neither return type nor output. FB_DoIt counts DoIt's
// calls in iCalls so that Reset has something to do.
//
// C++: the return type of a method without one is first_output_t<Vars> (the type of the first
// output<>), and every way out of it is `return in.first_output();` — the line ST leaves
// implicit. A method with neither return type nor output is `void`.
//
// Limit's variables have an initial value (iMax := 100), and C++ reads the initial values of a
// struct nested in a block only after the block: in the method's declaration the nested struct
// would not be complete yet (first_output_t says so, and asks for the struct outside the block).
// So Limit_vars is declared before FB_DoIt — the one place the port differs in layout from ST,
// where the method's declaration sits below the block.
#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

#include <type_traits>

namespace seed_method_first_output {

using namespace iecoop;

// METHOD PUBLIC Limit (of FB_DoIt)   (no return type: Limit's value is bLimited)
// VAR_IN_OUT
//     iValue : INT;
// END_VAR
// VAR_INPUT
//     iMax : INT := 100;
// END_VAR
// VAR_OUTPUT
//     bLimited : BOOL;               (the first declared output)
//     iExcess : INT;
// END_VAR
struct Limit_vars {
  in_out<INT> iValue;
  INT iMax = 100;
  output<BOOL> bLimited;
  output<INT> iExcess;
};

// FUNCTION_BLOCK FB_DoIt
struct FB_DoIt : function_block<FB_DoIt> {
  // VAR
  var<UDINT> iCalls;  // iCalls : UDINT;
  // END_VAR

  // METHOD PUBLIC DoIt                 (no return type: DoIt's value is dwSum)
  // VAR_INPUT
  //     iInput_1 : DWORD;
  //     iInput_2 : DWORD;
  // END_VAR
  // VAR_OUTPUT
  //     dwSum : DWORD;                 (the first declared output)
  //     bEqual : BOOL;
  // END_VAR
  struct DoIt_vars {
    DWORD iInput_1;
    DWORD iInput_2;
    output<DWORD> dwSum;
    output<BOOL> bEqual;
  };
  first_output_t<DoIt_vars> DoIt(args<DoIt_vars> in) {
    iCalls = iCalls + 1;                          // iCalls := iCalls + 1;
    in.dwSum = in.iInput_1 + in.iInput_2;         // dwSum := iInput_1 + iInput_2;
    in.bEqual = in.iInput_1 == in.iInput_2;       // bEqual := iInput_1 = iInput_2;
    return in.first_output();                     // (implicit: DoIt's value is dwSum)
  }

  // METHOD PUBLIC Limit                (its variables: Limit_vars, above the block)
  first_output_t<Limit_vars> Limit(args<Limit_vars> in) {
    if (in.iValue <= in.iMax) {           // IF iValue <= iMax THEN
      return in.first_output();           //     RETURN;           (bLimited: its initial value, FALSE)
    }                                     // END_IF
    in.iExcess = in.iValue - in.iMax;     // iExcess := iValue - iMax;
    in.iValue = in.iMax;                  // iValue := iMax;
    in.bLimited = TRUE;                   // bLimited := TRUE;
    return in.first_output();             // (implicit: Limit's value is bLimited)
  }

  // METHOD PUBLIC Reset                (neither return type nor output: no value)
  void Reset() {
    iCalls = 0;  // iCalls := 0;
  }
};

}  // namespace seed_method_first_output

using namespace iecoop;
using seed_method_first_output::FB_DoIt;

static_assert(std::is_same_v<decltype(std::declval<FB_DoIt&>().DoIt({})), DWORD>);
static_assert(std::is_same_v<decltype(std::declval<FB_DoIt&>().Limit({})), BOOL>);
static_assert(std::is_void_v<decltype(std::declval<FB_DoIt&>().Reset())>);

TEST_SUITE("seed: a METHOD without return type returns its first declared output") {
  TEST_CASE("DoIt's value is dwSum, the first output, bEqual, the second, only through =>") {
    FB_DoIt fbInstance;
    DWORD dwResult;
    BOOL bSame = TRUE;
    // dwResult := fbInstance.DoIt(iInput_1 := 16, iInput_2 := 16#FFFF, bEqual => bSame);
    dwResult = fbInstance.DoIt({"iInput_1"_ = 16, "iInput_2"_ = 0xFFFF, "bEqual"_ >> bSame});
    CHECK(dwResult == 0x1000F);
    CHECK(bSame == FALSE);
    // dwResult := fbInstance.DoIt(16, 16#0010);
    dwResult = fbInstance.DoIt({16, 0x0010});
    CHECK(dwResult == 32);
    CHECK(fbInstance.iCalls == 2);
  }

  TEST_CASE("the value returned and the first output read with => are the same") {
    FB_DoIt fbInstance;
    DWORD dwAlso;
    // dwResult := fbInstance.DoIt(iInput_2 := 5, iInput_1 := 7, dwSum => dwAlso);
    const DWORD dwResult = fbInstance.DoIt({"iInput_2"_ = 5, "iInput_1"_ = 7, "dwSum"_ >> dwAlso});
    CHECK(dwResult == 12);
    CHECK(dwAlso == 12);
    // DWORD arithmetic wraps: 16#FFFFFFFF + 1 = 0.
    CHECK(fbInstance.DoIt({0xFFFFFFFF, 1}) == 0);
  }

  TEST_CASE("an early RETURN returns the first output as it stands: its initial value") {
    FB_DoIt fbInstance;
    INT iSpeed = 80;
    INT iOver = -1;
    // bLim := fbInstance.Limit(iValue := iSpeed, iExcess => iOver);      (iMax: 100)
    BOOL bLim = fbInstance.Limit({"iValue"_ = iSpeed, "iExcess"_ >> iOver});
    CHECK(bLim == FALSE);
    CHECK(iSpeed == 80);
    CHECK(iOver == 0);  // the second output, at its initial value too
    // bLim := fbInstance.Limit(iValue := iSpeed, iMax := 50, iExcess => iOver);
    bLim = fbInstance.Limit({"iValue"_ = iSpeed, "iMax"_ = 50, "iExcess"_ >> iOver});
    CHECK(bLim == TRUE);
    CHECK(iSpeed == 50);  // the in-out was written through
    CHECK(iOver == 30);
    // A method's variables start afresh on every call: the next call returns FALSE again.
    CHECK(fbInstance.Limit({"iValue"_ = iSpeed, "iMax"_ = 50}) == FALSE);
  }

  TEST_CASE("a method with neither return type nor output returns nothing, and is called as a statement") {
    FB_DoIt fbInstance;
    fbInstance.DoIt({1, 1});
    fbInstance.DoIt({2, 2});  // a value not used: a call as a statement, as in ST
    CHECK(fbInstance.iCalls == 2);
    fbInstance.Reset();  // fbInstance.Reset();
    CHECK(fbInstance.iCalls == 0);
  }
}
