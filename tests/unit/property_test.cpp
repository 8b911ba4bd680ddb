// PROPERTY: Get and Set accessors behind the syntax of a variable, read-only and write-only
// properties, access modifiers on the property and on each accessor, virtual, ABSTRACT and
// FINAL properties, monitoring modes, properties of programs and GVLs, and zero cost.
#include "iecoop_test.hpp"

#include <memory>
#include <sstream>
#include <type_traits>

using namespace iecoop;

namespace {

// FUNCTION_BLOCK FB_Tank with PROPERTY Level : INT (Get and Set) and PROPERTY Full : BOOL
// (Get only), counting the accessor calls.
struct FB_Tank : function_block<FB_Tank> {
  INT iLevel;
  INT iMax = 100;
  int gets = 0;
  int sets = 0;

  INT Level_Get() {
    ++gets;
    return iLevel;
  }
  void Level_Set(INT value) {
    ++sets;
    iLevel = value > iMax ? iMax : value;  // a property filters what it stores
  }
  [[no_unique_address]] property<INT, &FB_Tank::Level_Get, &FB_Tank::Level_Set> Level{this};

  BOOL Full_Get() const { return iLevel >= iMax; }
  [[no_unique_address]] property<BOOL, &FB_Tank::Full_Get> Full{this};

  REAL Ratio_Get() const { return REAL(iLevel) / REAL(iMax); }
  [[no_unique_address]] property<REAL, &FB_Tank::Ratio_Get> Ratio{this};

  void body() {}
};

// The same block without its properties, to compare sizes.
struct FB_TankData : function_block<FB_TankData> {
  INT iLevel;
  INT iMax = 100;
  int gets = 0;
  int sets = 0;
  void body() {}
};

INT twice(INT value) { return value + value; }

}  // namespace

TEST_SUITE("PROPERTY") {
  TEST_CASE("assigning calls Set, reading calls Get") {
    FB_Tank tank;
    tank.Level = 40;  // tank.Level := 40;
    CHECK(tank.sets == 1);
    CHECK(tank.iLevel == 40);
    const INT level = tank.Level;  // level := tank.Level;
    CHECK(tank.gets == 1);
    CHECK(level == 40);
    tank.Level = 250;  // Set filters
    CHECK(tank.iLevel == 100);
    CHECK(tank.Full == TRUE);
  }

  TEST_CASE("a property reads as its value in expressions, comparisons and calls") {
    FB_Tank tank;
    tank.Level = 30;
    CHECK(tank.Level > 20);  // IF tank.Level > 20 THEN
    CHECK(20 < tank.Level);
    CHECK(tank.Level == 30);
    CHECK(tank.Level != 31);
    CHECK(tank.Level + 1 == 31);  // integer constants are still checked while compiling
    CHECK(1 + tank.Level == 31);
    CHECK(tank.Level * INT(2) == 60);
    CHECK(-tank.Level == -30);
    CHECK(twice(tank.Level) == 60);  // passed to a function by value
    CHECK(!tank.Full);
    CHECK((tank.Full | BOOL(TRUE)) == TRUE);
    if (tank.Full) FAIL("the tank is not full");
    // REAL property: arithmetic with C++ numbers, and IEC's implicit REAL -> LREAL.
    CHECK(tank.Ratio * 2.0f == doctest::Approx(0.6));
    const LREAL wide = tank.Ratio;
    CHECK(wide == doctest::Approx(0.3));
    // A wider integer: INT -> DINT is implicit.
    const DINT widened = tank.Level;
    CHECK(widened == 30);
  }

  TEST_CASE("fbA.prop := fbB.prop calls fbB's Get and fbA's Set") {
    FB_Tank a;
    FB_Tank b;
    b.Level = 55;
    a.Level = b.Level;
    CHECK(a.iLevel == 55);
    CHECK(b.gets == 1);
    CHECK(a.sets == 1);
  }

  TEST_CASE("a copy of a block calls no accessor, assigning a whole block assigns its properties") {
    FB_Tank a;
    a.Level = 12;
    FB_Tank copy = a;  // a new instance: its variables copied, no accessor called
    CHECK(copy.iLevel == 12);
    CHECK(copy.gets == 0);
    CHECK(copy.sets == 1);  // the copied count
    FB_Tank b;
    b.iMax = 10;
    b = a;  // ST: b := a; — the variables, then b.Level := a.Level (a's Get, b's Set)
    CHECK(a.gets == 1);
    CHECK(b.sets == a.sets + 1);
    CHECK(b.iLevel == 12);  // iMax was copied (100) before Level's Set ran
    // An online change copies without calling accessors.
    alignas(FB_Tank) unsigned char storage[sizeof(FB_Tank)];
    FB_Tank& moved = online_change(a, storage);
    CHECK(moved.iLevel == 12);
    CHECK(moved.gets == 1);
    CHECK(moved.sets == 1);
    std::destroy_at(&moved);
    std::construct_at(&a);  // a's storage is used again by the test's own variable
  }

  TEST_CASE("inside the block, assigning from a const block's property calls its Get and this Set") {
    struct FB_Copier : function_block<FB_Copier> {
      INT iValue;
      int sets = 0;
      INT Value_Get() { return iValue; }  // not const, as ST accessors are
      void Value_Set(INT value) {
        ++sets;
        iValue = value;
      }
      [[no_unique_address]] property<INT, &FB_Copier::Value_Get, &FB_Copier::Value_Set> Value{this};
      void TakeFrom(const FB_Copier& other) { Value = other.Value; }
      void body() {}
    };
    FB_Copier source;
    source.Value = 7;
    FB_Copier target;
    target.TakeFrom(source);
    CHECK(target.iValue == 7);
    CHECK(target.sets == 1);
    const FB_Copier& view = source;
    CHECK(view.Value == 7);  // a non-const Get, read through a const reference
  }

  TEST_CASE("a property costs no bytes and lives at its block's address") {
    static_assert(sizeof(FB_Tank) == sizeof(FB_TankData));
    static_assert(std::is_empty_v<decltype(FB_Tank::Level)>);
    FB_Tank tank;
    CHECK(static_cast<void*>(&tank.Level) == static_cast<void*>(&tank));
    CHECK(static_cast<void*>(&tank.Full) == static_cast<void*>(&tank));
  }

  TEST_CASE("a property cannot be copied out of its block") {
    using level_type = decltype(FB_Tank::Level);
    static_assert(!std::is_copy_constructible_v<level_type>);
    static_assert(std::is_convertible_v<level_type&, INT>);
    // The owner itself stays copyable.
    static_assert(std::is_copy_constructible_v<FB_Tank> && std::is_copy_assignable_v<FB_Tank>);
    FB_Tank tank;
    tank.Level = 3;
    auto value = tank.Level.get();  // the value, not the property
    static_assert(std::is_same_v<decltype(value), INT>);
    CHECK(value == 3);
  }

  TEST_CASE("reading through a const block uses a const Get") {
    FB_Tank tank;
    tank.Level = 100;
    const FB_Tank& view = tank;
    CHECK(view.Full == TRUE);
  }

  TEST_CASE("properties print as their values") {
    FB_Tank tank;
    tank.Level = 7;
    std::ostringstream out;
    out << tank.Level << ' ' << tank.Full;
    CHECK(out.str() == "7 FALSE");
  }
}

namespace {

// Read-only and write-only properties.
struct FB_Setpoint : function_block<FB_Setpoint> {
  LREAL rTarget;
  // PROPERTY Target : LREAL (Set only: write-only)
  void Target_Set(LREAL value) { rTarget = value; }
  [[no_unique_address]] property<LREAL, nullptr, &FB_Setpoint::Target_Set> Target{this};
  // PROPERTY Reached : BOOL (Get only: read-only)
  BOOL Reached_Get() const { return rTarget > 10.0; }
  [[no_unique_address]] property<BOOL, &FB_Setpoint::Reached_Get> Reached{this};
  void body() {}
};

template <class P, class V>
concept assignable = requires(P& p, V v) { p = v; };
template <class P, class V>
concept readable_as = requires(const P& p) { V(p); };

}  // namespace

TEST_SUITE("PROPERTY") {
  TEST_CASE("a read-only property has no Set, a write-only one no Get") {
    FB_Setpoint sp;
    sp.Target = 12.5;
    CHECK(sp.rTarget == 12.5);
    CHECK(sp.Reached == TRUE);
    using target = decltype(FB_Setpoint::Target);
    using reached = decltype(FB_Setpoint::Reached);
    static_assert(target::writable && !target::readable);
    static_assert(reached::readable && !reached::writable);
    // (Reading Target or assigning Reached does not compile: tests/compile_fail/property_*.)
  }
}

namespace {

// PRIVATE Set accessor: readable everywhere, written only by the block itself.
struct FB_Counter : function_block<FB_Counter> {
  DINT dCount;
  DINT Count_Get() const { return dCount; }
  void Count_Set(DINT value) { dCount = value; }
  // PROPERTY Count : DINT    Get: PUBLIC    Set: PRIVATE
  [[no_unique_address]] property<DINT, &FB_Counter::Count_Get, &FB_Counter::Count_Set, owner_only_set> Count{this};

  BOOL bPulse;
  void body() {
    if (bPulse) Count = Count + 1;  // Count := Count + 1;  (inside: both accessors)
  }
  void Reset() { Count = 0; }  // METHOD Reset
};

// The property's own access modifier: PROTECTED, used by a derived block.
struct FB_Base : function_block<FB_Base> {
  virtual ~FB_Base() = default;
  virtual void body() {}

 protected:
  INT iHidden;
  INT Hidden_Get() const { return iHidden; }
  void Hidden_Set(INT value) { iHidden = value; }
  // PROPERTY PROTECTED Hidden : INT
  [[no_unique_address]] property<INT, &FB_Base::Hidden_Get, &FB_Base::Hidden_Set> Hidden{this};
};
struct FB_Derived : extends<FB_Derived, FB_Base> {
  INT iSeen;
  void body() override {
    Hidden = Hidden + 2;  // a derived block uses the PROTECTED property
    iSeen = Hidden;
  }
};

template <class B>
concept hidden_visible = requires(B& b) { b.Hidden; };

}  // namespace

TEST_SUITE("PROPERTY") {
  TEST_CASE("a PRIVATE accessor: only the block assigns, everyone reads") {
    FB_Counter counter;
    counter.bPulse = TRUE;
    counter();
    counter();
    CHECK(counter.Count == 2);  // Get is public
    counter.Reset();
    CHECK(counter.Count == 0);
    using count = decltype(FB_Counter::Count);
    static_assert(readable_as<count, DINT>);
    static_assert(!assignable<count, DINT>);  // Set is private (compile_fail/property_owner_only_set)
  }

  TEST_CASE("a PRIVATE Get: the block reads it in expressions, nobody else reads it") {
    struct FB_Secret : function_block<FB_Secret> {
      REAL rGain = REAL(2.5f);
      REAL Gain_Get() const { return rGain; }
      void Gain_Set(REAL value) { rGain = value; }
      [[no_unique_address]] property<REAL, &FB_Secret::Gain_Get, &FB_Secret::Gain_Set, owner_only_get> Gain{this};
      BOOL bHigh;
      REAL rScaled;
      void body() {
        const REAL gain = Gain;  // reads as its value inside the block
        bHigh = gain > REAL(2.0f);
        rScaled = Gain.get() * REAL(4.0f);  // in an operator's operand: get()
      }
    };
    FB_Secret secret;
    secret();
    CHECK(secret.bHigh == TRUE);
    CHECK(secret.rScaled == REAL(10.0f));
    secret.Gain = REAL(1.0f);  // Set is public
    secret();
    CHECK(secret.bHigh == FALSE);
    using gain = decltype(FB_Secret::Gain);
    static_assert(!readable_as<gain, REAL>);
  }

  TEST_CASE("a REAL property reads as a wider real, never as an integer") {
    using ratio = decltype(FB_Tank::Ratio);
    static_assert(std::is_convertible_v<ratio&, LREAL> && std::is_convertible_v<ratio&, double>);
    static_assert(!std::is_convertible_v<ratio&, int> && !std::is_convertible_v<ratio&, long>);
    FB_Tank tank;
    tank.Level = 50;
    const LREAL wide = tank.Ratio;
    CHECK(wide == LREAL(0.5));
  }

  TEST_CASE("a PROTECTED property: derived blocks use it, others cannot see it") {
    FB_Derived derived;
    derived();
    derived();
    CHECK(derived.iSeen == 4);
    static_assert(!hidden_visible<FB_Derived>);
    static_assert(!hidden_visible<FB_Base>);
  }
}

namespace {

// ABSTRACT, virtual and FINAL properties.
struct FB_Sensor : function_block<FB_Sensor> {
  virtual ~FB_Sensor() = default;
  virtual void body() {}
  // PROPERTY ABSTRACT Value : LREAL
  virtual LREAL Value_Get() = 0;
  [[no_unique_address]] property<LREAL, &FB_Sensor::Value_Get> Value{this};
  // PROPERTY Scale : LREAL (overridable)
  LREAL rScale = 1.0;
  virtual LREAL Scale_Get() { return rScale; }
  virtual void Scale_Set(LREAL value) { rScale = value; }
  [[no_unique_address]] property<LREAL, &FB_Sensor::Scale_Get, &FB_Sensor::Scale_Set> Scale{this};
};

struct FB_Thermo : extends<FB_Thermo, FB_Sensor> {
  void body() override {}  // an empty implementation
  LREAL rRaw = 21.5;
  LREAL Value_Get() final { return rRaw * Scale; }                                     // implements Value, FINAL
  void Scale_Set(LREAL value) override { rScale = value < 0.0 ? LREAL(0.0) : value; }  // overrides Set only
  // A property of the derived block itself (its owner starts with the base's data).
  LREAL Raw_Get() const { return rRaw; }
  [[no_unique_address]] property<LREAL, &FB_Thermo::Raw_Get> Raw{this};
};

}  // namespace

TEST_SUITE("PROPERTY") {
  TEST_CASE("ABSTRACT, overridden and FINAL accessors dispatch like methods") {
    static_assert(std::is_abstract_v<FB_Sensor>);
    FB_Thermo thermo;
    FB_Sensor& sensor = thermo;
    CHECK(sensor.Value == doctest::Approx(21.5));
    sensor.Scale = 2.0;
    CHECK(sensor.Value == doctest::Approx(43.0));
    sensor.Scale = -1.0;  // the derived Set
    CHECK(thermo.Scale == 0.0);
    CHECK(thermo.Raw == 21.5);
    CHECK(static_cast<void*>(&thermo.Raw) == static_cast<void*>(&thermo));
  }
}

namespace {

// {attribute 'monitoring' := 'call'} and {attribute 'monitoring' := 'variable'}.
struct FB_Monitored : function_block<FB_Monitored> {
  INT iValue;
  int gets = 0;
  INT Called_Get() {
    ++gets;
    return iValue;
  }
  // {attribute 'monitoring' := 'call'}
  [[no_unique_address]] property<INT, &FB_Monitored::Called_Get> Called{this};

  INT Recorded_monitor;  // the implicit variable 'variable' monitoring shows
  INT Recorded_Get() {
    ++gets;
    return iValue;
  }
  void Recorded_Set(INT value) { iValue = value; }
  // {attribute 'monitoring' := 'variable'}
  [[no_unique_address]] property<INT, &FB_Monitored::Recorded_Get, &FB_Monitored::Recorded_Set,
                                 monitoring::variable<&FB_Monitored::Recorded_monitor>>
      Recorded{this};

  void body() {}
};

}  // namespace

TEST_SUITE("PROPERTY") {
  TEST_CASE("'call' monitoring calls Get to show the value") {
    FB_Monitored fb;
    fb.iValue = 5;
    static_assert(std::is_same_v<decltype(fb.Called)::monitoring_mode, monitoring::call>);
    CHECK(fb.Called.monitor() == 5);
    CHECK(fb.gets == 1);  // the watch list ran the accessor
  }

  TEST_CASE("'variable' monitoring shows the value of the last Get or Set, calling nothing") {
    FB_Monitored fb;
    fb.Recorded = 8;  // Set records 8
    CHECK(fb.Recorded.monitor() == 8);
    CHECK(fb.gets == 0);
    fb.iValue = 9;                      // changed behind the property's back:
    CHECK(fb.Recorded.monitor() == 8);  // the shown value is stale, as CODESYS warns
    const INT read = fb.Recorded;       // Get records 9
    CHECK(read == 9);
    CHECK(fb.Recorded.monitor() == 9);
    CHECK(fb.gets == 1);
  }
}

namespace {

// A PROGRAM's property, and a GVL's.
struct PRG_Line : program<PRG_Line> {
  UDINT udParts;
  UDINT Parts_Get() const { return udParts; }
  [[no_unique_address]] property<UDINT, &PRG_Line::Parts_Get> Parts{this};
  void body() { udParts = udParts + 1U; }
};

// VAR_GLOBAL  gMode : INT; END_VAR  with  PROPERTY ModeName : STRING
struct GVL {
  INT gMode;
  STRING<> ModeName_Get() const { return gMode == 0 ? STRING<>("Manual") : STRING<>("Auto"); }
  void ModeName_Set(STRING<> value) { gMode = value == "Auto" ? INT(1) : INT(0); }
  [[no_unique_address]] property<STRING<>, &GVL::ModeName_Get, &GVL::ModeName_Set> ModeName{this};
};

}  // namespace

TEST_SUITE("PROPERTY") {
  TEST_CASE("a PROGRAM's property") {
    PRG_Line line;
    PRG_Line::instance()();
    PRG_Line::instance()();
    CHECK(PRG_Line::instance().Parts == 2U);
    CHECK(static_cast<void*>(&line.Parts) == static_cast<void*>(&line));
  }

  TEST_CASE("a global variable list's property, of a STRING type") {
    GVL gvl;
    CHECK(gvl.ModeName == "Manual");
    gvl.ModeName = "Auto";
    CHECK(gvl.gMode == 1);
    CHECK(gvl.ModeName.get() == "Auto");
    static_assert(sizeof(GVL) == sizeof(INT));
    CHECK(static_cast<void*>(&gvl.ModeName) == static_cast<void*>(&gvl));
  }
}

// Where a property sits, in every shape of block it is allowed in: each one is at its owner's
// address (which its constructor checked, faulting otherwise), so its accessors reach the
// owner's variables.
namespace {

template <class Owner, class P>
bool at_owner(Owner& owner, P& property) {
  return static_cast<const void*>(&property) == static_cast<const void*>(&owner);
}

// A block with a vtable, the property after variables and a nested block.
struct FB_ShapeVirtual : function_block<FB_ShapeVirtual> {
  DINT dFirst = 7;
  TON tDelay;
  INT iValue;
  virtual INT Value_Get() { return iValue; }
  virtual void Value_Set(INT value) { iValue = value; }
  [[no_unique_address]] property<INT, &FB_ShapeVirtual::Value_Get, &FB_ShapeVirtual::Value_Set> Value{this};
  LREAL lLast = 1.5;
  virtual void body() {}
};
// EXTENDS: the derived block overrides the base's accessor and adds a property of its own;
// a third level adds another.
struct FB_ShapeDerived : extends<FB_ShapeDerived, FB_ShapeVirtual> {
  BOOL bSeen;
  INT Value_Get() override { return iValue + 1000; }
  BOOL Seen_Get() { return bSeen; }
  void Seen_Set(BOOL value) { bSeen = value; }
  [[no_unique_address]] property<BOOL, &FB_ShapeDerived::Seen_Get, &FB_ShapeDerived::Seen_Set> Seen{this};
  void body() override {}
};
struct FB_ShapeThird : extends<FB_ShapeThird, FB_ShapeDerived> {
  STRING<8> sName = "third";
  STRING<8> Name_Get() { return sName; }
  [[no_unique_address]] property<STRING<8>, &FB_ShapeThird::Name_Get> Name{this};
  void body() override {}
};

// Interfaces (virtual bases of their blocks), each with a property.
struct I_Speed : interface_base<I_Speed> {
  virtual REAL Speed_Get() = 0;
  virtual void Speed_Set(REAL value) = 0;
  [[no_unique_address]] property<REAL, &I_Speed::Speed_Get, &I_Speed::Speed_Set> Speed{this};
};
struct I_Named : interface_base<I_Named> {
  virtual STRING<8> Label_Get() = 0;
  [[no_unique_address]] property<STRING<8>, &I_Named::Label_Get> Label{this};
};
struct I_Drive : interface_base<I_Drive, I_Speed, I_Named> {};
struct FB_ShapeDrive : function_block<FB_ShapeDrive, implements<I_Drive>> {
  INT iPad;
  REAL rSpeed;
  REAL Speed_Get() override { return rSpeed; }
  void Speed_Set(REAL value) override { rSpeed = value; }
  STRING<8> Label_Get() override { return "drive"; }
  BOOL On_Get() { return rSpeed > 0.0f; }
  [[no_unique_address]] property<BOOL, &FB_ShapeDrive::On_Get> On{this};
  virtual void body() {}
};
struct FB_ShapeLoggedDrive : extends<FB_ShapeLoggedDrive, FB_ShapeDrive> {
  DINT dWrites;
  void Speed_Set(REAL value) override {
    dWrites = dWrites + 1;
    FB_ShapeDrive::Speed_Set(value);
  }
  void body() override {}
};

// A plain struct (a list of global variables without the list's base), with a property.
struct ST_Plain {
  INT iRaw;
  INT Scaled_Get() { return iRaw * 10; }
  [[no_unique_address]] property<INT, &ST_Plain::Scaled_Get> Scaled{this};
};

}  // namespace

TEST_SUITE("PROPERTY") {
  TEST_CASE("a property sits at its owner's address in a block with a vtable and nested blocks") {
    FB_ShapeVirtual fb;
    CHECK(at_owner(fb, fb.Value));
    fb.Value = 5;
    CHECK(fb.iValue == 5);
    CHECK(fb.Value == 5);
    CHECK(fb.dFirst == 7);
    CHECK(fb.lLast == 1.5);
  }

  TEST_CASE("along an EXTENDS chain, each level's property sits at its level's address") {
    FB_ShapeThird fb;
    CHECK(at_owner(static_cast<FB_ShapeVirtual&>(fb), fb.Value));
    CHECK(at_owner(static_cast<FB_ShapeDerived&>(fb), fb.Seen));
    CHECK(at_owner(fb, fb.Name));
    fb.Value = 3;
    CHECK(fb.iValue == 3);
    CHECK(fb.Value == 1003);  // FB_ShapeDerived's override of the Get accessor
    FB_ShapeVirtual& base = fb;
    CHECK(base.Value == 1003);
    fb.Seen = TRUE;
    CHECK(fb.bSeen == TRUE);
    CHECK(fb.Name == "third");
  }

  TEST_CASE("an interface's property sits at the interface part of the block, wherever that is") {
    FB_ShapeLoggedDrive fb;
    I_Speed& speed = fb;
    I_Named& named = fb;
    CHECK(at_owner(speed, fb.Speed));
    CHECK(at_owner(named, fb.Label));
    CHECK(at_owner(static_cast<FB_ShapeDrive&>(fb), fb.On));
    itf<I_Drive> ip = fb;
    ip->Speed = 2.5f;  // ip.Speed := 2.5;  (the derived block's Set)
    CHECK(fb.rSpeed == 2.5f);
    CHECK(fb.dWrites == 1);
    CHECK(ip->Speed == 2.5f);
    CHECK(ip->Label == "drive");
    CHECK(fb.On == TRUE);
  }

  TEST_CASE("a plain struct's property") {
    ST_Plain plain;
    CHECK(at_owner(plain, plain.Scaled));
    plain.iRaw = 4;
    CHECK(plain.Scaled == 40);
  }

  TEST_CASE("no property adds a byte to its owner") {
    struct FB_ShapeVirtualData : function_block<FB_ShapeVirtualData> {
      DINT dFirst = 7;
      TON tDelay;
      INT iValue;
      LREAL lLast = 1.5;
      virtual void body() {}
    };
    CHECK(sizeof(FB_ShapeVirtual) == sizeof(FB_ShapeVirtualData));
    CHECK(sizeof(ST_Plain) == sizeof(INT));
  }
}
