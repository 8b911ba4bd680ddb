// POINTER TO (ADR, ^, byte arithmetic, CheckPointer's fault path), SIZEOF/XSIZEOF and
// REFERENCE TO (REF=, __ISVALIDREF).
#include <cstdint>
#include <type_traits>

#include "iecoop_test.hpp"

using namespace iecoop;
using iecoop_test::fault_recorder;

namespace {

struct ST_Recipe {
  INT iSpeed;
  REAL rTemp;
  STRING<10> sName;
};

struct FB_Base : function_block<FB_Base> {
  var<INT> iCalls;
  virtual INT M_Kind() { return 1; }
  virtual void body() { iCalls = iCalls + 1; }
};
struct FB_Derived : extends<FB_Derived, FB_Base> {
  INT M_Kind() override { return 2; }
  void body() override { SUPER::body(); }
};

// A block that keeps a REFERENCE TO its counter, set in a method (REF=).
struct FB_Counter : function_block<FB_Counter> {
  REFERENCE_TO<DINT> refTotal;
  void M_Attach(DINT& diTarget) { refTotal.bind(diTarget); }
  void body() {
    if (is_valid_ref(refTotal)) refTotal = refTotal + 1;
  }
};

}  // namespace

TEST_SUITE("POINTER TO and REFERENCE TO") {
  TEST_CASE("ADR and ^ read and write the variable") {
    INT iCount = 5;
    POINTER_TO<INT> pCount;
    CHECK(pCount == nullptr);
    pCount = ADR(iCount);
    CHECK(pCount != nullptr);
    *pCount = *pCount + 1;  // pCount^ := pCount^ + 1;
    CHECK(iCount == 6);
    static_assert(sizeof(POINTER_TO<INT>) == sizeof(void*));
    static_assert(std::is_trivially_copyable_v<POINTER_TO<INT>>);
  }

  TEST_CASE("p^.member and p^.Method() are p->member and p->Method()") {
    ST_Recipe stRecipe;
    POINTER_TO<ST_Recipe> pRecipe = ADR(stRecipe);
    pRecipe->iSpeed = 1200;
    CHECK(stRecipe.iSpeed == 1200);
    FB_Derived fbDerived;
    POINTER_TO<FB_Base> pBase = ADR(fbDerived);  // a pointer to a derived block is one to its base
    CHECK(pBase->M_Kind() == 2);
    (*pBase)();
    CHECK(fbDerived.iCalls == 1);
  }

  TEST_CASE("pointer arithmetic counts bytes, as in CODESYS") {
    ARRAY<DINT, 1, 4> aValues{10, 20, 30, 40};
    POINTER_TO<DINT> p = ADR(aValues[1]);
    p = p + SIZEOF(*p);  // p := p + SIZEOF(p^);  the next element
    CHECK(*p == 20);
    p += 8;
    CHECK(*p == 40);
    p = p - 4;
    CHECK(*p == 30);
    POINTER_TO<DINT> q = ADR(aValues[1]);
    CHECK(q[2] == 30);  // q[2]: two elements on
  }

  TEST_CASE("CheckPointer: a null pointer dereferenced is a fault, with a stand-in variable") {
    fault_recorder faults;
    POINTER_TO<INT> pNone;
    *pNone = 7;
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::null_pointer);
    CHECK(*pNone == 0);  // a fresh stand-in each time: nothing carries over
    CHECK(faults.count == 2);
    POINTER_TO<ST_Recipe> pRecipe = nullptr;
    pRecipe->iSpeed = 3;
    CHECK(faults.count == 3);
    CHECK(pRecipe[4].iSpeed == 0);
    CHECK(faults.count == 4);
  }

  TEST_CASE("ADR of a block's variable points at the variable inside its wrapper") {
    FB_Base fb;
    POINTER_TO<INT> p = ADR(fb.iCalls.ref());
    fb();
    CHECK(*p == 1);
  }

  TEST_CASE("SIZEOF gives the smallest unsigned type that holds the size") {
    ARRAY<INT, 0, 4> aData;
    static_assert(std::is_same_v<decltype(SIZEOF(aData)), USINT>);
    CHECK(SIZEOF(aData) == 10);
    ARRAY<LREAL, 1, 100> aBig;
    static_assert(std::is_same_v<decltype(SIZEOF(aBig)), UINT>);
    CHECK(SIZEOF(aBig) == 800);
    ARRAY<BYTE, 1, 70000> aHuge;
    static_assert(std::is_same_v<decltype(SIZEOF(aHuge)), UDINT>);
    CHECK(SIZEOF<ST_Recipe>() == sizeof(ST_Recipe));
    CHECK(SIZEOF(STRING<10>{}) == 11);
    static_assert(std::is_same_v<decltype(XSIZEOF(aData)), std::conditional_t<sizeof(void*) >= 8, ULINT, UDINT>>);
    CHECK(XSIZEOF(aData) == 10);
    const INT iReturnValue = SIZEOF(aData);  // USINT into INT, as in ST
    CHECK(iReturnValue == 10);
  }

  TEST_CASE("a REFERENCE TO is bound with REF= and reads and writes through") {
    DINT diTotal = 40;
    REFERENCE_TO<DINT> refTotal;
    CHECK_FALSE(is_valid_ref(refTotal));
    refTotal.bind(diTotal);  // refTotal REF= diTotal;
    CHECK(is_valid_ref(refTotal));
    refTotal = 41;  // writes diTotal
    CHECK(diTotal == 41);
    const DINT diCopy = refTotal;
    CHECK(diCopy == 41);
    FB_Counter fbCounter;
    fbCounter();  // not bound: the body checks __ISVALIDREF
    CHECK(diTotal == 41);
    fbCounter.M_Attach(diTotal);
    fbCounter();
    CHECK(diTotal == 42);
  }

  TEST_CASE("an unbound REFERENCE TO used is a fault, never an access to address 0") {
    fault_recorder faults;
    REFERENCE_TO<INT> refNone;
    refNone = 5;
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::unbound_in_out);
  }
}
