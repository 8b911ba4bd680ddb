// FUNCTION_BLOCK, EXTENDS and ACTION: both call forms, inputs that keep their values,
// outputs with =>, VAR_IN_OUT binding and its fault, the variable sections, actions,
// abstract and final blocks, STRUCT EXTENDS, and zero overhead.
#include "iecoop_test.hpp"

#include <type_traits>

using namespace iecoop;
using iecoop_test::fault_recorder;

namespace {

// A block with inputs, outputs, an in-out, locals, an action, VAR_STAT and VAR_INST.
struct FB_Counter : function_block<FB_Counter> {
  // VAR_INPUT  bCount : BOOL; iStep : INT := 1; END_VAR
  BOOL bCount;
  INT iStep = 1;
  // VAR_OUTPUT iValue : INT; bEven : BOOL; END_VAR
  INT iValue;
  BOOL bEven;
  // VAR_IN_OUT iShared : INT; END_VAR
  in_out<INT> iShared;
  // VAR iCalls : INT; END_VAR
  var<INT> iCalls;
  // VAR_STAT iInstancesCalled : INT; END_VAR  (shared by all instances)
  static inline INT iAllCalls;
  // VAR_INST of method Note: iNotes : INT;   (kept in the instance, used by Note only)
  INT Note_iNotes;

  using VAR_INPUT = pins<&FB_Counter::bCount, &FB_Counter::iStep>;
  using VAR_OUTPUT = pins<&FB_Counter::iValue, &FB_Counter::bEven>;
  using VAR_IN_OUT = pins<&FB_Counter::iShared>;

  void body() {
    INT temp = iStep * 2;  // VAR_TEMP temp : INT; END_VAR — new on every call
    iCalls = iCalls + 1;
    iAllCalls = iAllCalls + 1;
    if (bCount) {
      iValue = iValue + iStep;
      iShared = iShared + temp / 2;
    }
    bEven = iValue % 2 == 0;
  }

  // ACTION Reset: no declarations of its own, works on the block's variables
  void Reset() {
    iValue = 0;
    bEven = TRUE;
  }

  // METHOD Note : INT   (VAR_INST iNotes keeps its value between calls)
  INT Note() {
    Note_iNotes = Note_iNotes + 1;
    return Note_iNotes;
  }
};

// A block that calls its action by name from its body, and the action overridden below.
struct FB_Machine : function_block<FB_Machine> {
  virtual ~FB_Machine() = default;
  BOOL bStop;
  INT iState;
  using VAR_INPUT = pins<&FB_Machine::bStop>;
  using VAR_OUTPUT = pins<&FB_Machine::iState>;
  virtual void body() {
    if (bStop) {
      Stop();  // ST: Stop();   an action, called inside its host by name
    } else {
      iState = iState + 1;
    }
  }
  virtual void Stop() { iState = 0; }  // ACTION Stop
};
struct FB_SafeMachine : extends<FB_SafeMachine, FB_Machine> {
  BOOL bSafe;
  void body() override { SUPER::body(); }  // SUPER^();
  void Stop() override {                   // the action, overridden
    SUPER::Stop();
    bSafe = TRUE;
  }
};

struct Empty : function_block<Empty> {
  void body() {}
};
struct Small : function_block<Small> {
  BOOL a;
  BOOL b;
  INT c;
  void body() {}
};
struct Outer : function_block<Outer> {
  Small inner;
  INT x;
  void body() { inner(); }
};

// An ABSTRACT block (protected constructor) with an ABSTRACT method (pure virtual).
struct FB_AbstractAxis : function_block<FB_AbstractAxis> {
  virtual ~FB_AbstractAxis() = default;
  virtual void body() { iMoves = iMoves + 1; }
  virtual LREAL Position() = 0;  // METHOD ABSTRACT Position : LREAL
  INT iMoves;

 protected:
  FB_AbstractAxis() = default;  // FUNCTION_BLOCK ABSTRACT FB_AbstractAxis
};
struct FB_Axis final : extends<FB_Axis, FB_AbstractAxis> {  // FUNCTION_BLOCK FINAL FB_Axis EXTENDS FB_AbstractAxis
  LREAL Position() override { return 1.5; }
  void body() override { SUPER::body(); }  // SUPER^();
};

// STRUCT EXTENDS
struct ST_Base {
  INT iId;
  STRING<20> sName;
};
struct ST_Sub : ST_Base {  // TYPE ST_Sub EXTENDS ST_Base : STRUCT rWeight : REAL; END_STRUCT END_TYPE
  REAL rWeight;
};

}  // namespace

// No vtable, no per-instance overhead: a block is exactly its variables.
static_assert(sizeof(Empty) == 1 && std::is_empty_v<Empty>);
static_assert(sizeof(Small) == sizeof(BOOL) * 2 + sizeof(INT));
static_assert(sizeof(Outer) == sizeof(Small) + sizeof(INT));
static_assert(!std::is_polymorphic_v<Small> && std::is_trivially_copyable_v<Small>);
static_assert(sizeof(local<INT, Small>) == sizeof(INT) && sizeof(in_out<INT>) == sizeof(INT*));
// ABSTRACT and FINAL
static_assert(!std::is_default_constructible_v<FB_AbstractAxis> && std::is_abstract_v<FB_AbstractAxis>);
static_assert(std::is_default_constructible_v<FB_Axis> && std::is_final_v<FB_Axis>);
static_assert(FunctionBlock<FB_Counter> && FunctionBlock<FB_Axis> && !FunctionBlock<int>);

TEST_SUITE("function blocks") {
  TEST_CASE("assigning inputs, then calling: ST's inst.x := ... then inst()") {
    FB_Counter counter;
    INT shared = 0;
    counter.iShared.bind(shared);
    counter.bCount = TRUE;
    counter.iStep = 3;
    counter();
    counter();
    CHECK(counter.iValue == 6);
    CHECK(counter.bEven == TRUE);
    CHECK(shared == 6);
    CHECK(counter.iCalls == 2);
  }

  TEST_CASE("a named call assigns the inputs it names, the others keep their values") {
    FB_Counter counter;
    INT shared = 100;
    counter("bCount"_ = TRUE, "iStep"_ = 5, "iShared"_ = shared);
    CHECK(counter.iValue == 5);
    counter("iShared"_ = shared);  // bCount and iStep keep TRUE and 5
    CHECK(counter.iValue == 10);
    CHECK(counter.iStep == 5);
    counter("bCount"_ = FALSE, "iShared"_ = shared);
    CHECK(counter.iValue == 10);
    CHECK(shared == 110);
  }

  TEST_CASE("outputs named with => are copied after the body") {
    FB_Counter counter;
    INT shared = 0;
    INT value = -1;
    DINT wide = -1;  // an INT output goes to a DINT variable: IEC widening
    BOOL even = FALSE;
    counter("bCount"_ = TRUE, "iShared"_ = shared, "iValue"_ >> value, "bEven"_ >> even);
    CHECK(value == 1);
    counter("iShared"_ = shared, "iValue"_ >> wide);
    CHECK(wide == 2);
    CHECK(even == FALSE);
  }

  TEST_CASE("a VAR_IN_OUT refers to the caller's variable") {
    FB_Counter counter;
    INT a = 0;
    INT b = 50;
    counter("bCount"_ = TRUE, "iShared"_ = a);
    counter("iShared"_ = b);  // rebound to b for this call
    CHECK(a == 1);
    CHECK(b == 51);
    CHECK(counter.iShared.bound());
    CHECK(&counter.iShared.get() == &b);
  }

  TEST_CASE("calling a block with an unbound VAR_IN_OUT is a fault and skips the body") {
    fault_recorder faults;
    FB_Counter counter;
    counter("bCount"_ = TRUE);
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::unbound_in_out);
    CHECK(counter.iCalls == 0);
    CHECK(counter.iValue == 0);
    INT x = counter.iShared;  // reading it unbound: another fault, a defined value
    CHECK(x == 0);
    CHECK(faults.count == 2);
  }

  TEST_CASE("outside code reads outputs and locals") {
    FB_Counter counter;
    INT shared = 0;
    counter("iShared"_ = shared);
    const INT calls = counter.iCalls;
    CHECK(calls == 1);
    CHECK(counter.iCalls + 1 == 2);
    CHECK(counter.iCalls.get() == 1);
  }

  TEST_CASE("VAR_TEMP is new on every call, VAR_STAT shared by all instances, VAR_INST kept by a method") {
    FB_Counter a;
    FB_Counter b;
    INT shared = 0;
    const INT before = FB_Counter::iAllCalls;
    a("iShared"_ = shared);
    b("iShared"_ = shared);
    CHECK(FB_Counter::iAllCalls - before == 2);
    CHECK(a.Note() == 1);
    CHECK(a.Note() == 2);
    CHECK(b.Note() == 1);
  }

  TEST_CASE("an action works on its host's variables, called from outside with input assignments") {
    FB_Counter counter;
    INT shared = 0;
    counter("bCount"_ = TRUE, "iStep"_ = 3, "iShared"_ = shared);
    counter.Reset();  // ST: counter.Reset();
    CHECK(counter.iValue == 0);
    counter.with("iStep"_ = 7).Reset();  // ST: counter.Reset(iStep := 7);
    CHECK(counter.iStep == 7);
    CHECK(counter.iValue == 0);
    counter("iShared"_ = shared);
    CHECK(counter.iValue == 7);
  }

  TEST_CASE("an action is called by name inside its host, inherited and overridable") {
    FB_Machine machine;
    machine();
    machine();
    CHECK(machine.iState == 2);
    machine("bStop"_ = TRUE);
    CHECK(machine.iState == 0);
    FB_SafeMachine safe;
    FB_Machine& as_base = safe;
    as_base();
    CHECK(safe.iState == 1);
    as_base("bStop"_ = TRUE);  // the inherited body calls the overriding action
    CHECK(safe.iState == 0);
    CHECK(safe.bSafe == TRUE);
  }

  TEST_CASE("an abstract block is used through its concrete extension") {
    FB_Axis axis;
    FB_AbstractAxis& abstract = axis;
    abstract();
    CHECK(axis.iMoves == 1);
    CHECK(abstract.Position() == 1.5);
  }

  TEST_CASE("STRUCT EXTENDS: the derived structure has the base's members") {
    ST_Sub sub{{7, "conveyor"}, 2.5f};
    CHECK(sub.iId == 7);
    CHECK(sub.sName == "conveyor");
    ST_Base& base = sub;
    base.iId = 8;
    CHECK(sub.iId == 8);
  }

  TEST_CASE("interfaces of blocks are listed, base pins first") {
    static_assert(inputs_of<FB_Counter>::size == 2 && inputs_of<FB_Counter>::names[1] == "iStep");
    static_assert(outputs_of<FB_Counter>::names[0] == "iValue");
    static_assert(in_outs_of<FB_Counter>::names[0] == "iShared");
    static_assert(inputs_of<FB_SafeMachine>::size == 1 && inputs_of<FB_SafeMachine>::names[0] == "bStop");
    static_assert(inputs_of<Empty>::size == 0);
    CHECK(inputs_of<FB_Counter>::index_of("bCount") == 0u);
  }
}
