// A PROPERTY of interface type (and of POINTER_TO, REFERENCE_TO and STRUCT type) used as ST uses
// it: `fbPID.IntegratorBounds.Maximum := 5;` is `fbPID.IntegratorBounds->Maximum = 5.0;` — the
// property's Get, then the interface's own property Set; `fbPID.IntegratorBounds.Reset();` is
// `fbPID.IntegratorBounds->Reset();`. An interface that is 0 faults as a call through an
// unassigned interface variable does. Also: interface variables from var<>, properties and
// references of interface variables and blocks, as ST assigns them.
#include "iecoop_test.hpp"

#include <type_traits>
#include <utility>

using namespace iecoop;

namespace {

// INTERFACE I_Bounds
//   PROPERTY Maximum : LREAL    PROPERTY Minimum : LREAL (Get only)    METHOD Reset
struct I_Bounds : interface_base<I_Bounds> {
  virtual LREAL Maximum_Get() = 0;
  virtual void Maximum_Set(LREAL value) = 0;
  [[no_unique_address]] property<LREAL, &I_Bounds::Maximum_Get, &I_Bounds::Maximum_Set> Maximum{this};
  virtual LREAL Minimum_Get() = 0;
  [[no_unique_address]] property<LREAL, &I_Bounds::Minimum_Get> Minimum{this};
  virtual void Reset() = 0;
};

// INTERFACE I_NamedBounds EXTENDS I_Bounds   METHOD Name : STRING
struct I_NamedBounds : interface_base<I_NamedBounds, I_Bounds> {
  virtual STRING<> Name() = 0;
};

// FUNCTION_BLOCK FB_Bounds IMPLEMENTS I_NamedBounds, counting the accessor calls.
struct FB_Bounds : function_block<FB_Bounds, implements<I_NamedBounds>> {
  LREAL fMaximum = 100.0;
  LREAL fMinimum = 0.0;
  int maximum_gets = 0;
  int maximum_sets = 0;
  int resets = 0;
  void body() {}
  LREAL Maximum_Get() override {
    ++maximum_gets;
    return fMaximum;
  }
  void Maximum_Set(LREAL value) override {
    ++maximum_sets;
    fMaximum = value < fMinimum ? fMinimum : value;
  }
  LREAL Minimum_Get() override { return fMinimum; }
  void Reset() override {
    ++resets;
    fMaximum = 100.0;
  }
  STRING<> Name() override { return "bounds"; }
};

// INTERFACE I_PID   PROPERTY IntegratorBounds : I_Bounds (Get only)
struct I_PID : interface_base<I_PID> {
  virtual itf<I_Bounds> IntegratorBounds_Get() = 0;
  [[no_unique_address]] property<itf<I_Bounds>, &I_PID::IntegratorBounds_Get> IntegratorBounds{this};
};

// STRUCT ST_Limits
struct ST_Limits {
  LREAL fLow = 0.0;
  LREAL fHigh = 10.0;
};

// FUNCTION_BLOCK FB_PID IMPLEMENTS I_PID
//   VAR _ipBounds : I_Bounds; END_VAR
//   PROPERTY IntegratorBounds : I_Bounds   (Get: IntegratorBounds := _ipBounds;  Set: _ipBounds := IntegratorBounds;)
//   PROPERTY pBounds : POINTER TO FB_Bounds        PROPERTY refBounds : REFERENCE TO FB_Bounds
//   PROPERTY Limits : ST_Limits                    PROPERTY NamedBounds : I_NamedBounds
struct FB_PID : function_block<FB_PID, implements<I_PID>> {
  var<itf<I_Bounds>> _ipBounds;
  var<itf<I_NamedBounds>> _ipNamed;
  FB_Bounds* _pBounds = nullptr;
  ST_Limits _stLimits;
  int gets = 0;
  int sets = 0;
  int limits_gets = 0;
  void body() {}

  itf<I_Bounds> IntegratorBounds_Get() override {
    ++gets;
    return _ipBounds;
  }
  void IntegratorBounds_Set(itf<I_Bounds> value) {
    ++sets;
    _ipBounds = value;
  }
  // The block's own property hides the interface's one of the same name and reaches the same
  // Get (the interface's has no Set: ST lets an implementing block add one).
  [[no_unique_address]] property<itf<I_Bounds>, &FB_PID::IntegratorBounds_Get, &FB_PID::IntegratorBounds_Set>
      IntegratorBounds{this};

  itf<I_NamedBounds> NamedBounds_Get() { return _ipNamed; }
  [[no_unique_address]] property<itf<I_NamedBounds>, &FB_PID::NamedBounds_Get> NamedBounds{this};

  POINTER_TO<FB_Bounds> pBounds_Get() { return POINTER_TO<FB_Bounds>(_pBounds); }
  [[no_unique_address]] property<POINTER_TO<FB_Bounds>, &FB_PID::pBounds_Get> pBounds{this};

  REFERENCE_TO<FB_Bounds> refBounds_Get() {
    REFERENCE_TO<FB_Bounds> reference;
    if (_pBounds != nullptr) reference.bind(*_pBounds);  // refBounds REF= _pBounds^;
    return reference;
  }
  [[no_unique_address]] property<REFERENCE_TO<FB_Bounds>, &FB_PID::refBounds_Get> refBounds{this};

  ST_Limits Limits_Get() {
    ++limits_gets;
    return _stLimits;
  }
  void Limits_Set(ST_Limits value) { _stLimits = value; }
  [[no_unique_address]] property<ST_Limits, &FB_PID::Limits_Get, &FB_PID::Limits_Set> Limits{this};
};

// FUNCTION MaximumOf : LREAL   VAR_INPUT ipBounds : I_Bounds; END_VAR
LREAL MaximumOf(itf<I_Bounds> ipBounds) { return ipBounds->Maximum; }

// `p->m` is usable on a P (for the checks that a STRUCT property's fields are read-only).
template <class P>
concept field_assignable = requires(P& p) { p->fHigh = 1.0; };

// `p.operator->()` is declared.
template <class P>
concept arrow_usable = requires(P& p) { p.operator->(); };

// A block with a property of a C++ scalar type.
struct FB_Plain : function_block<FB_Plain> {
  int Count_Get() { return 1; }
  [[no_unique_address]] property<int, &FB_Plain::Count_Get> Count{this};
  void body() {}
};

}  // namespace

TEST_SUITE("PROPERTY of interface type") {
  TEST_CASE("fbPID.IntegratorBounds.Maximum := 5 calls the property's Get, then the interface's Maximum Set") {
    FB_Bounds fbBounds;
    FB_PID fbPID;
    fbPID.IntegratorBounds = fbBounds;  // fbPID.IntegratorBounds := fbBounds;   (the outer Set)
    CHECK(fbPID.sets == 1);
    fbPID.IntegratorBounds->Maximum = 5.0;  // fbPID.IntegratorBounds.Maximum := 5;
    CHECK(fbPID.gets == 1);
    CHECK(fbPID.sets == 1);  // the outer Set is not called again
    CHECK(fbBounds.maximum_sets == 1);
    CHECK(fbBounds.fMaximum == 5.0);
    fbPID.IntegratorBounds->Maximum = -1.0;  // the interface's Set filters what it stores
    CHECK(fbBounds.fMaximum == 0.0);
    CHECK(fbPID.gets == 2);
  }

  TEST_CASE("fbPID.IntegratorBounds.Reset() calls the method of the block behind the property") {
    FB_Bounds fbBounds;
    FB_PID fbPID;
    fbPID.IntegratorBounds = fbBounds;
    fbBounds.fMaximum = 3.0;
    fbPID.IntegratorBounds->Reset();  // fbPID.IntegratorBounds.Reset();
    CHECK(fbBounds.resets == 1);
    CHECK(fbBounds.fMaximum == 100.0);
    CHECK(fbPID.gets == 1);
  }

  TEST_CASE("reading through the property: one Get, then the interface's Get") {
    FB_Bounds fbBounds;
    FB_PID fbPID;
    fbPID.IntegratorBounds = fbBounds;
    const LREAL fMax = fbPID.IntegratorBounds->Maximum;  // fMax := fbPID.IntegratorBounds.Maximum;
    CHECK(fMax == 100.0);
    CHECK(fbPID.gets == 1);
    CHECK(fbBounds.maximum_gets == 1);
    CHECK(fbPID.IntegratorBounds->Minimum == 0.0);  // a read-only property of the interface
    CHECK(fbPID.IntegratorBounds->Maximum > 50.0);
    CHECK(fbPID.gets == 3);
    // A compound assignment: the property's Get once per access, the interface's Get, then its Set.
    fbPID.IntegratorBounds->Maximum += 1.0;  // fbPID.IntegratorBounds.Maximum := fbPID.IntegratorBounds.Maximum + 1;
    CHECK(fbBounds.fMaximum == 101.0);
    CHECK(fbBounds.maximum_sets == 1);
  }

  TEST_CASE("the property's Get decides which block is reached, each time") {
    FB_Bounds fbA;
    FB_Bounds fbB;
    FB_PID fbPID;
    fbPID.IntegratorBounds = fbA;
    fbPID.IntegratorBounds->Maximum = 7.0;
    fbPID._ipBounds = fbB;  // the block changes its variable behind the property
    fbPID.IntegratorBounds->Maximum = 8.0;
    CHECK(fbA.fMaximum == 7.0);
    CHECK(fbB.fMaximum == 8.0);
    CHECK(fbPID.sets == 1);
  }

  TEST_CASE("through an interface variable of the block: ipPID.IntegratorBounds.Maximum := 5") {
    FB_Bounds fbBounds;
    FB_PID fbPID;
    fbPID.IntegratorBounds = fbBounds;
    itf<I_PID> ipPID = fbPID;
    ipPID->IntegratorBounds->Maximum = 5.0;  // ipPID.IntegratorBounds.Maximum := 5;
    ipPID->IntegratorBounds->Reset();        // ipPID.IntegratorBounds.Reset();
    CHECK(fbBounds.maximum_sets == 1);
    CHECK(fbBounds.resets == 1);
    CHECK(fbPID.gets == 2);
  }

  TEST_CASE("through a const block the property's Get is called all the same") {
    FB_Bounds fbBounds;
    FB_PID fbPID;
    fbPID.IntegratorBounds = fbBounds;
    const FB_PID& constPID = fbPID;
    constPID.IntegratorBounds->Maximum = 9.0;  // the interface's block is not const
    CHECK(fbBounds.fMaximum == 9.0);
    CHECK(fbPID.gets == 1);
  }

  TEST_CASE("a property whose interface is 0: the call is the fault of an unassigned interface variable") {
    FB_PID fbPID;  // _ipBounds is 0
    CHECK_FAULT(fbPID.IntegratorBounds->Reset(), fault_kind::unassigned_interface);
    CHECK(fbPID.gets == 1);  // Get was called; the call through its value was not made
    CHECK_FAULT(fbPID.IntegratorBounds->Maximum = 5.0, fault_kind::unassigned_interface);
    CHECK_FAULT((void)LREAL(fbPID.IntegratorBounds->Maximum), fault_kind::unassigned_interface);
    itf<I_PID> ipPID = fbPID;
    CHECK_FAULT(ipPID->IntegratorBounds->Reset(), fault_kind::unassigned_interface);
    CHECK(fbPID.gets == 4);
  }

  TEST_CASE("a property of an interface that extends another reaches both interfaces' members") {
    FB_Bounds fbBounds;
    FB_PID fbPID;
    fbPID._ipNamed = fbBounds;
    CHECK(fbPID.NamedBounds->Name() == "bounds");
    fbPID.NamedBounds->Maximum = 4.0;
    CHECK(fbBounds.fMaximum == 4.0);
  }

  TEST_CASE("a property of POINTER TO type: pBounds^.Maximum := 5, a fault (and a stand-in) when it is 0") {
    FB_Bounds fbBounds;
    FB_PID fbPID;
    fbPID._pBounds = &fbBounds;
    fbPID.pBounds->Maximum = 5.0;  // fbPID.pBounds^.Maximum := 5;
    fbPID.pBounds->Reset();        // fbPID.pBounds^.Reset();
    CHECK(fbBounds.maximum_sets == 1);
    CHECK(fbBounds.resets == 1);
    CHECK(fbPID.pBounds->fMaximum == 100.0);
    fbPID._pBounds = nullptr;
    testing::expect_faults faults;
    fbPID.pBounds->fMinimum = 1.0;  // goes to the stand-in
    CHECK(faults.count() == 1);
    CHECK(faults.last().kind == fault_kind::null_pointer);
    CHECK(fbBounds.fMinimum == 0.0);
  }

  TEST_CASE("a property of REFERENCE TO type: refBounds.Maximum := 5, a fault when it is not bound") {
    FB_Bounds fbBounds;
    FB_PID fbPID;
    fbPID._pBounds = &fbBounds;
    fbPID.refBounds->Maximum = 5.0;  // fbPID.refBounds.Maximum := 5;
    fbPID.refBounds->Reset();
    CHECK(fbBounds.maximum_sets == 1);
    CHECK(fbBounds.resets == 1);
    fbPID.refBounds->fMinimum = 2.0;  // a variable of the referenced block
    CHECK(fbBounds.fMinimum == 2.0);
    fbPID._pBounds = nullptr;
    testing::expect_faults faults;
    fbPID.refBounds->fMinimum = 3.0;
    CHECK(faults.count() == 1);
    CHECK(faults.last().kind == fault_kind::unbound_in_out);
    CHECK(fbBounds.fMinimum == 2.0);
  }

  TEST_CASE("a property of STRUCT type: its fields are read through ->, never written") {
    FB_PID fbPID;
    fbPID.Limits = ST_Limits{1.0, 2.0};
    const LREAL fHigh = fbPID.Limits->fHigh;  // fHigh := fbPID.Limits.fHigh;
    CHECK(fHigh == 2.0);
    CHECK(fbPID.Limits->fLow == 1.0);
    CHECK(fbPID.limits_gets == 2);
    // fbPID.Limits.fHigh := 5; would change a copy: it does not compile (assign the whole property).
    static_assert(!field_assignable<decltype(fbPID.Limits)>);
    static_assert(field_assignable<POINTER_TO<ST_Limits>>);  // (the check itself sees a writable field)
  }

  TEST_CASE("-> is there for properties of class types only (an elementary one has no members)") {
    static_assert(arrow_usable<decltype(std::declval<FB_PID&>().IntegratorBounds)>);
    static_assert(arrow_usable<decltype(std::declval<FB_PID&>().Limits)>);
    static_assert(!arrow_usable<decltype(std::declval<FB_Plain&>().Count)>);
    CHECK(true);
  }
}

TEST_SUITE("interface variables from variables of every form") {
  TEST_CASE("ipBounds := a var of the block, a property, a reference, as ST assigns them") {
    FB_Bounds fbBounds;
    FB_PID fbPID;
    fbPID._ipBounds = fbBounds;
    fbPID._ipNamed = fbBounds;

    itf<I_Bounds> ipFromVar = fbPID._ipBounds;  // ipFromVar := fbPID._ipBounds;
    CHECK(ipFromVar.get() == static_cast<I_Bounds*>(&fbBounds));
    itf<I_Bounds> ipAssigned;
    ipAssigned = fbPID._ipBounds;  // ipAssigned := fbPID._ipBounds;
    CHECK(ipAssigned == ipFromVar);

    itf<I_Bounds> ipFromExtended = fbPID._ipNamed;  // an I_NamedBounds variable into an I_Bounds one
    CHECK(ipFromExtended == ipFromVar);
    ipAssigned = nullptr;
    ipAssigned = fbPID._ipNamed;
    CHECK(ipAssigned == ipFromVar);

    itf<I_Bounds> ipFromProperty = fbPID.IntegratorBounds;  // ipFromProperty := fbPID.IntegratorBounds;
    CHECK(ipFromProperty == ipFromVar);
    itf<I_Bounds> ipFromExtendedProperty = fbPID.NamedBounds;
    CHECK(ipFromExtendedProperty == ipFromVar);
    ipAssigned = nullptr;
    ipAssigned = fbPID.NamedBounds;
    CHECK(ipAssigned == ipFromVar);

    REFERENCE_TO<FB_Bounds> refBounds;
    refBounds.bind(fbBounds);             // refBounds REF= fbBounds;
    itf<I_Bounds> ipFromRef = refBounds;  // ipFromRef := refBounds;
    CHECK(ipFromRef == ipFromVar);
    ipAssigned = nullptr;
    ipAssigned = refBounds;
    CHECK(ipAssigned == ipFromVar);

    REFERENCE_TO<itf<I_NamedBounds>> refNamed;
    itf<I_NamedBounds> ipNamed = fbBounds;
    refNamed.bind(ipNamed);
    itf<I_Bounds> ipFromRefNamed = refNamed;
    CHECK(ipFromRefNamed == ipFromVar);

    // Passed to a function's interface input.
    fbBounds.fMaximum = 12.0;
    CHECK(MaximumOf(fbPID._ipBounds) == 12.0);
    CHECK(MaximumOf(fbPID._ipNamed) == 12.0);
    CHECK(MaximumOf(fbPID.IntegratorBounds) == 12.0);
    CHECK(MaximumOf(refBounds) == 12.0);
  }

  TEST_CASE("a variable of the block's var<> of interface type calls through ->") {
    FB_Bounds fbBounds;
    FB_PID fbPID;
    fbPID._ipBounds = fbBounds;
    fbPID._ipBounds->Maximum = 6.0;  // fbPID._ipBounds.Maximum := 6;  (VAR read from outside)
    CHECK(fbBounds.fMaximum == 6.0);
  }

  TEST_CASE("an unrelated block, or an interface that does not extend the one asked, does not convert") {
    static_assert(!std::is_convertible_v<itf<I_Bounds>, itf<I_NamedBounds>>);
    static_assert(!std::is_convertible_v<decltype((std::declval<FB_PID&>()._ipBounds)), itf<I_NamedBounds>>);
    static_assert(!std::is_convertible_v<decltype((std::declval<FB_PID&>().IntegratorBounds)), itf<I_NamedBounds>>);
    static_assert(!std::is_convertible_v<REFERENCE_TO<FB_PID>&, itf<I_Bounds>>);
    CHECK(true);
  }
}
