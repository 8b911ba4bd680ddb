// An ABSTRACT block without a body of its own is extended (issue 35, point 8), and the attribute
// pragmas no_explicit_call and no_assign. In ST a block whose implementation is empty — TwinCAT
// marks such a base {attribute 'no_explicit_call'} — is extended by blocks with a body of their
// own; calling one of them runs its body (it replaces the base's), SUPER^() runs the base's empty
// one, and every method call runs the most derived override.
#include "iecoop_test.hpp"

#include <string>
#include <utility>

using namespace iecoop;
using iecoop_test::fault_recorder;

namespace {

std::string calls;

void log(const char* what) {
  calls += what;
  calls += ' ';
}

// INTERFACE I_Limit  METHOD Limit : REAL  VAR_INPUT fIn : REAL; END_VAR
struct Limit_vars {
  REAL fIn;
};
struct I_Limit : interface_base<I_Limit> {
  virtual REAL Limit(args<Limit_vars> in) = 0;
};

// {attribute 'no_explicit_call' := 'use the methods'}
// FUNCTION_BLOCK ABSTRACT FB_Base IMPLEMENTS I_Limit
//   VAR_INPUT fMaximum : REAL; END_VAR
//   VAR nLimits : INT; END_VAR
//   METHOD Limit : REAL   nLimits := nLimits + 1; Limit := MIN(fIn, fMaximum);
//   METHOD ABSTRACT Name : STRING
// (its implementation part empty)
struct FB_Base : function_block<FB_Base, implements<I_Limit>, attributes<no_explicit_call>> {
  REAL fMaximum = 10.0F;
  var<INT> nLimits;
  using VAR_INPUT = pins<&FB_Base::fMaximum>;

  REAL Limit(args<Limit_vars> in) override {
    nLimits = nLimits + 1;
    log("Base.Limit");
    return MIN(in.fIn, fMaximum);
  }
  virtual STRING<> Name() = 0;

 protected:
  FB_Base() = default;
};

// FUNCTION_BLOCK FB_Clamp EXTENDS FB_Base
//   VAR_INPUT fIn : REAL; END_VAR  VAR_OUTPUT fOut : REAL; END_VAR
//   METHOD Name : STRING  Name := 'Clamp';
// fOut := Limit(fIn); SUPER^();
struct FB_Clamp : extends<FB_Clamp, FB_Base> {
  REAL fIn;
  REAL fOut;
  using VAR_INPUT = pins<&FB_Clamp::fIn>;
  using VAR_OUTPUT = pins<&FB_Clamp::fOut>;

  STRING<> Name() override { return "Clamp"; }
  void body() override {
    log("Clamp.body");
    fOut = Limit(fIn);
    SUPER::body();  // SUPER^(); — FB_Base's implementation, which is empty
  }
};

// FUNCTION_BLOCK FB_Scaled EXTENDS FB_Clamp
//   VAR_INPUT fScale : REAL := 2; END_VAR
//   METHOD Limit : REAL  log; Limit := SUPER^.Limit(fIn * fScale);
//   METHOD Name : STRING  Name := 'Scaled';
// SUPER^(); log;
struct FB_Scaled : extends<FB_Scaled, FB_Clamp> {
  REAL fScale = 2.0F;
  using VAR_INPUT = pins<&FB_Scaled::fScale>;

  REAL Limit(args<Limit_vars> in) override {
    log("Scaled.Limit");
    return SUPER::Limit({in.fIn * fScale});
  }
  STRING<> Name() override { return "Scaled"; }
  void body() override {
    SUPER::body();  // SUPER^(); — FB_Clamp's
    log("Scaled.body");
  }
};

// FUNCTION_BLOCK ABSTRACT FB_Counting EXTENDS FB_Base  (adds a variable, no implementation either)
//   VAR nRuns : INT; END_VAR
struct FB_Counting : extends<FB_Counting, FB_Base> {
  var<INT> nRuns;
  virtual void Count() { nRuns = nRuns + 1; }

 protected:
  FB_Counting() = default;
};

// FUNCTION_BLOCK FB_Counter EXTENDS FB_Counting
//   METHOD Name : STRING  Name := 'Counter';
// SUPER^(); Count();
struct FB_Counter : extends<FB_Counter, FB_Counting> {
  STRING<> Name() override { return "Counter"; }
  void body() override {
    SUPER::body();  // FB_Counting's implementation: as empty as FB_Base's
    log("Counter.body");
    Count();
  }
};

// The same block with and without attributes, for size and behaviour.
struct FB_Plain : function_block<FB_Plain> {
  INT iIn;
  INT iOut;
  using VAR_INPUT = pins<&FB_Plain::iIn>;
  using VAR_OUTPUT = pins<&FB_Plain::iOut>;
  void body() { iOut = iIn * INT(2); }
};
// {attribute 'no_assign'}
struct FB_Kept : function_block<FB_Kept, attributes<no_assign>> {
  INT iIn;
  INT iOut;
  using VAR_INPUT = pins<&FB_Kept::iIn>;
  using VAR_OUTPUT = pins<&FB_Kept::iOut>;
  void body() { iOut = iIn * INT(2); }
};
// {attribute 'no_explicit_call'} {attribute 'no_assign'}, with methods only
struct FB_Methods : function_block<FB_Methods, attributes<no_explicit_call, no_assign>> {
  INT iCount;
  void Add(INT n) { iCount = iCount + n; }
};
struct FB_KeptMore : extends<FB_KeptMore, FB_Base, attributes<no_assign>> {
  STRING<> Name() override { return "KeptMore"; }
  void body() override { log("KeptMore.body"); }
};
struct FB_DerivedFromKept : extends<FB_DerivedFromKept, FB_KeptMore> {
  void body() override { SUPER::body(); }
};

}  // namespace

TEST_SUITE("ABSTRACT block without a body; attributes") {
  TEST_CASE("a block extending a block without a body runs its own body; SUPER^() of that base runs nothing") {
    calls.clear();
    FB_Clamp fbClamp;
    fbClamp("fIn"_ = REAL(15.0F));
    CHECK(calls == "Clamp.body Base.Limit ");
    CHECK(fbClamp.fOut == REAL(10.0F));
    CHECK(fbClamp.nLimits == INT(1));
    fbClamp("fIn"_ = REAL(3.0F), "fMaximum"_ = REAL(4.0F));  // an input of the base, by name
    CHECK(fbClamp.fOut == REAL(3.0F));
    CHECK(fbClamp.fMaximum == REAL(4.0F));
    CHECK(fbClamp.nLimits == INT(2));
  }

  TEST_CASE("three levels: the most derived body runs, SUPER^() reaches each level's, methods dispatch") {
    calls.clear();
    FB_Scaled fbScaled;
    fbScaled("fIn"_ = REAL(4.0F));
    // FB_Scaled's body runs FB_Clamp's through SUPER^(); its Limit() is FB_Scaled's override.
    CHECK(calls == "Clamp.body Scaled.Limit Base.Limit Scaled.body ");
    CHECK(fbScaled.fOut == REAL(8.0F));
    CHECK(fbScaled.nLimits == INT(1));

    calls.clear();
    FB_Base& base = fbScaled;  // REFERENCE TO FB_Base
    CHECK(base.Name() == STRING<>("Scaled"));
    CHECK(base.Limit({REAL(6.0F)}) == REAL(10.0F));  // 6 * 2, limited to 10
    CHECK(calls == "Scaled.Limit Base.Limit ");
    CHECK(base.nLimits == INT(2));

    calls.clear();
    itf<I_Limit> ipLimit = fbScaled;  // through the interface the base implements
    CHECK(ipLimit->Limit({REAL(1.0F)}) == REAL(2.0F));
    CHECK(calls == "Scaled.Limit Base.Limit ");
  }

  TEST_CASE("a level without a body on top of one without: still empty, the block extending both runs its own") {
    calls.clear();
    FB_Counter fbCounter;
    fbCounter();
    fbCounter();
    CHECK(calls == "Counter.body Counter.body ");
    CHECK(fbCounter.nRuns == INT(2));
    FB_Counting& counting = fbCounter;
    CHECK(counting.Name() == STRING<>("Counter"));
    CHECK(fbCounter.nLimits == INT(0));  // the base's variables are there, untouched
  }

  TEST_CASE("no_explicit_call belongs to the block that lists it: blocks extending it are called") {
    static_assert(detail::lists_attribute<detail::own_attributes_t<FB_Base>, no_explicit_call>);
    static_assert(!detail::lists_attribute<detail::own_attributes_t<FB_Clamp>, no_explicit_call>);
    static_assert(!detail::lists_attribute<detail::own_attributes_t<FB_Counting>, no_explicit_call>);
    calls.clear();
    FB_KeptMore fbMore;
    fbMore();
    CHECK(calls == "KeptMore.body ");
    FB_Methods fbMethods;
    fbMethods.Add(INT(3));
    fbMethods.Add(INT(4));
    CHECK(fbMethods.iCount == INT(7));
  }

  TEST_CASE("attributes change neither the size nor the behaviour of a block") {
    static_assert(sizeof(FB_Kept) == sizeof(FB_Plain));
    static_assert(sizeof(FB_Methods) == sizeof(INT));
    static_assert(!std::is_polymorphic_v<FB_Kept> && !std::is_polymorphic_v<FB_Methods>);
    static_assert(sizeof(FB_KeptMore) == sizeof(FB_Clamp) - 2 * sizeof(REAL));
    FB_Plain plain;
    FB_Kept kept;
    plain("iIn"_ = INT(21));
    kept("iIn"_ = INT(21));
    CHECK(plain.iOut == INT(42));
    CHECK(kept.iOut == INT(42));
    FB_Kept copy = kept;  // a copy made by construction is not an assignment
    CHECK(copy.iOut == INT(42));
    CHECK(copy.iIn == INT(21));
  }

  TEST_CASE("no_assign is inherited by the blocks that extend the block; the library never assigns one") {
    static_assert(detail::refuses_assignment<FB_Kept>());
    static_assert(detail::refuses_assignment<FB_KeptMore>());
    static_assert(detail::refuses_assignment<FB_DerivedFromKept>());
    static_assert(!detail::refuses_assignment<FB_Plain>());
    static_assert(!detail::refuses_assignment<FB_Clamp>());
    static_assert(!detail::refuses_assignment<INT>());
    fault_recorder faults;
    POINTER_TO<FB_Kept> pKept;
    pKept->iIn = INT(5);  // a null pointer: a fault, and a stand-in (not assigned anew: no_assign)
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::null_pointer);
    CHECK((*pKept).iIn == INT(5));
    CHECK(faults.count == 2);
    POINTER_TO<FB_Plain> pPlain;
    pPlain->iIn = INT(5);
    CHECK((*pPlain).iIn == INT(0));  // an assignable block's stand-in starts anew
    CHECK(faults.count == 4);
  }
}
