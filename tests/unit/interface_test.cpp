// INTERFACE: IMPLEMENTS one or several interfaces, interface EXTENDS (several, and a diamond),
// interface variables (0 until assigned, reassigned, compared, a fault when called while 0),
// interface properties, __QUERYINTERFACE and __QUERYPOINTER without RTTI, and interfaces as
// concepts.
#include "iecoop_test.hpp"

#include <type_traits>

using namespace iecoop;

namespace {

// INTERFACE I_Named  METHOD GetName : STRING
struct I_Named : interface_base<I_Named> {
  virtual STRING<> GetName() = 0;
};

// INTERFACE I_Counter  METHOD Count  PROPERTY Value : DINT
// (Count's variables are declared outside the interface so that `Count()` can take them all
// from their initial values: Clang 14 cannot use a nested struct's initializers in a default
// argument of the enclosing class.)
struct Count_vars {
  DINT dStep = 1;  // VAR_INPUT dStep : DINT := 1; END_VAR
};
struct I_Counter : interface_base<I_Counter> {
  virtual void Count(args<Count_vars> in = {}) = 0;
  virtual DINT Value_Get() = 0;
  virtual void Value_Set(DINT value) = 0;
  [[no_unique_address]] property<DINT, &I_Counter::Value_Get, &I_Counter::Value_Set> Value{this};
};

// INTERFACE I_Device EXTENDS I_Named, I_Counter  METHOD Enabled : BOOL
struct I_Device : interface_base<I_Device, I_Named, I_Counter> {
  virtual BOOL Enabled() = 0;
};

// INTERFACE I_Other  (implemented by nobody here)
struct I_Other : interface_base<I_Other> {
  virtual void Nothing() = 0;
};

// FUNCTION_BLOCK FB_Up IMPLEMENTS I_Device
struct FB_Up : function_block<FB_Up, implements<I_Device>> {
  DINT dValue;
  virtual void body() {}
  STRING<> GetName() override { return "Up"; }
  void Count(args<Count_vars> in = {}) override { dValue = dValue + in.dStep; }
  DINT Value_Get() override { return dValue; }
  void Value_Set(DINT value) override { dValue = value; }
  BOOL Enabled() override { return TRUE; }
};

// FUNCTION_BLOCK FB_Down IMPLEMENTS I_Counter, I_Named
struct FB_Down : function_block<FB_Down, implements<I_Counter, I_Named>> {
  DINT dValue = 100;
  void body() {}
  STRING<> GetName() override { return "Down"; }
  void Count(args<Count_vars> in = {}) override { dValue = dValue - in.dStep; }
  DINT Value_Get() override { return dValue; }
  void Value_Set(DINT value) override { dValue = value < 0 ? DINT(0) : value; }
};

// FUNCTION DeliverName : STRING  VAR_INPUT l_i : I_Named; END_VAR
STRING<> DeliverName(itf<I_Named> l_i) { return l_i->GetName(); }

}  // namespace

TEST_SUITE("INTERFACE") {
  TEST_CASE("an interface variable is 0 until assigned") {
    itf<I_Counter> ip;
    CHECK(ip == 0);  // IF ip = 0 THEN
    CHECK(ip == nullptr);
    CHECK_FALSE(ip);
    FB_Up up;
    ip = up;  // ip := up;
    CHECK(ip != 0);
    CHECK(ip.get() == static_cast<I_Counter*>(&up));
    ip = 0;  // ip := 0;
    CHECK(ip == 0);
    static_assert(sizeof(itf<I_Counter>) == sizeof(void*));
  }

  TEST_CASE("calls dispatch to the block assigned, which can change at run time") {
    FB_Up up;
    FB_Down down;
    itf<I_Counter> ip;
    for (const BOOL bUseUp : {TRUE, FALSE}) {
      if (bUseUp) {
        ip = up;
      } else {
        ip = down;
      }
      ip->Count();                // ip.Count();
      ip->Count({"dStep"_ = 5});  // ip.Count(dStep := 5);
    }
    CHECK(up.dValue == 6);
    CHECK(down.dValue == 94);
  }

  TEST_CASE("interface properties are read and written through the variable") {
    FB_Up up;
    FB_Down down;
    itf<I_Counter> ip = up;
    ip->Value = 42;  // ip.Value := 42;
    CHECK(up.dValue == 42);
    CHECK(ip->Value == 42);
    ip = down;
    ip->Value = -3;  // FB_Down's Set clamps
    const DINT value = ip->Value;
    CHECK(value == 0);
    // The block's own name for the property reaches the same accessors.
    up.Value = 7;
    CHECK(up.dValue == 7);
  }

  TEST_CASE("a block passed where an interface is expected (FUNCTION DeliverName)") {
    FB_Up up;
    FB_Down down;
    CHECK(DeliverName(up) == "Up");      // DeliverName(l_i := up);
    CHECK(DeliverName(down) == "Down");  // DeliverName(l_i := down);
  }

  TEST_CASE("an interface that EXTENDS others is usable as each of them") {
    FB_Up up;
    itf<I_Device> device = up;
    itf<I_Named> named = device;  // I_Device EXTENDS I_Named
    itf<I_Counter> counter = device;
    CHECK(named->GetName() == "Up");
    counter->Count();
    CHECK(device->Value == 1);  // I_Counter's property, through I_Device
    CHECK(device->Enabled() == TRUE);
    static_assert(std::is_convertible_v<itf<I_Device>, itf<I_Named>>);
    static_assert(!std::is_convertible_v<itf<I_Named>, itf<I_Device>>);  // that way needs a query
  }

  TEST_CASE("two variables compare equal when they refer to the same block") {
    FB_Up a;
    FB_Up b;
    itf<I_Named> x = a;
    itf<I_Named> y = a;
    itf<I_Named> z = b;
    CHECK(x == y);
    CHECK(x != z);
  }
}

namespace {

// A diamond: I_Left and I_Right both EXTEND I_Root; FB_Both IMPLEMENTS I_Left, I_Right.
struct I_Root : interface_base<I_Root> {
  virtual INT Id() = 0;
};
struct I_Left : interface_base<I_Left, I_Root> {
  virtual INT Left() = 0;
};
struct I_Right : interface_base<I_Right, I_Root> {
  virtual INT Right() = 0;
};
struct FB_Both : function_block<FB_Both, implements<I_Left, I_Right>> {
  void body() {}
  INT Id() override { return 7; }
  INT Left() override { return 1; }
  INT Right() override { return 2; }
};

// The same diamond split over EXTENDS: FB_LeftOnly IMPLEMENTS I_Left; FB_RightToo EXTENDS
// FB_LeftOnly IMPLEMENTS I_Right.
struct FB_LeftOnly : function_block<FB_LeftOnly, implements<I_Left>> {
  virtual void body() {}
  INT Id() override { return 8; }
  INT Left() override { return 1; }
};
struct FB_RightToo : extends<FB_RightToo, FB_LeftOnly, implements<I_Right>> {
  void body() override {}  // an empty implementation
  INT Right() override { return 2; }
};

}  // namespace

TEST_SUITE("INTERFACE") {
  TEST_CASE("EXTENDS a block with interfaces and IMPLEMENTS more, sharing an interface") {
    FB_RightToo block;
    itf<I_Root> root = block;
    CHECK(root->Id() == 8);
    itf<I_Right> right;
    CHECK(query_interface(root, right) == TRUE);
    CHECK(right->Right() == 2);
    itf<I_Left> left;
    CHECK(query_interface(right, left) == TRUE);
    CHECK(left->Left() == 1);
    CHECK(query_pointer<FB_RightToo>(left) == &block);
    CHECK(query_pointer<FB_LeftOnly>(right) == &block);
    FB_LeftOnly base;
    root = base;
    CHECK(query_interface(root, right) == FALSE);
    CHECK(query_pointer<FB_RightToo>(root) == nullptr);
  }

  TEST_CASE("an interface reached along two ways is one interface") {
    FB_Both both;
    itf<I_Root> root = both;  // unambiguous: I_Root is shared
    itf<I_Left> left = both;
    itf<I_Right> right = both;
    CHECK(root->Id() == 7);
    CHECK(left->Id() == 7);
    CHECK(right->Right() == 2);
    CHECK(itf<I_Root>(left) == itf<I_Root>(right));
    itf<I_Right> found;
    CHECK(query_interface(left, found) == TRUE);
    CHECK(found == right);
  }
}

namespace {

// A fault handler that throws, so a test can watch the call that did not happen.
struct unassigned_call {
  fault_kind kind;
};
void throw_fault(const fault_info& fault) { throw unassigned_call{fault.kind}; }

}  // namespace

TEST_SUITE("INTERFACE") {
  TEST_CASE("a call through an unassigned interface variable goes to the fault handler") {
    const fault_handler previous = set_fault_handler(&throw_fault);
    itf<I_Counter> ip;
    bool faulted = false;
    try {
      ip->Count();
    } catch (const unassigned_call& fault) {
      faulted = fault.kind == fault_kind::unassigned_interface;
    }
    CHECK(faulted);
    faulted = false;
    try {
      const DINT value = ip->Value;  // a property read too
      CHECK(value == -1);            // not reached
    } catch (const unassigned_call&) {
      faulted = true;
    }
    CHECK(faulted);
    set_fault_handler(previous);
    // (With the default handler, or one that returns, the program stops: see
    // fault.unassigned_interface_* in tests/CMakeLists.txt.)
  }
}

namespace {

// An ABSTRACT block implements part of an interface; the block EXTENDING it the rest, and
// another interface besides.
struct I_Extra : interface_base<I_Extra> {
  virtual INT Extra() = 0;
};
struct FB_AbstractCounter : function_block<FB_AbstractCounter, implements<I_Counter>> {
  DINT dValue;
  virtual void body() {}
  DINT Value_Get() override { return dValue; }
  void Value_Set(DINT value) override { dValue = value; }
  // Count stays ABSTRACT
};
struct FB_Concrete : extends<FB_Concrete, FB_AbstractCounter, implements<I_Extra>> {
  void body() override {}  // an empty implementation
  void Count(args<Count_vars> in = {}) override { dValue = dValue + in.dStep * DINT(10); }
  INT Extra() override { return 3; }
};
struct FB_ConcretePlus : extends<FB_ConcretePlus, FB_Concrete> {
  void body() override {}  // an empty implementation
  void Count(args<Count_vars> in = {}) override { dValue = dValue + in.dStep; }
};

}  // namespace

TEST_SUITE("INTERFACE") {
  TEST_CASE("an ABSTRACT block implementing part of an interface, completed by EXTENDS") {
    static_assert(std::is_abstract_v<FB_AbstractCounter>);
    static_assert(!std::is_abstract_v<FB_Concrete>);
    FB_Concrete concrete;
    itf<I_Counter> ip = concrete;
    ip->Count();
    CHECK(ip->Value == 10);
    FB_ConcretePlus plus;
    ip = plus;
    ip->Count();
    CHECK(plus.dValue == 1);
  }

  TEST_CASE("__QUERYINTERFACE: from one interface of a block to another") {
    FB_Down down;
    itf<I_Counter> counter = down;
    itf<I_Named> named;
    // bOk := __QUERYINTERFACE(counter, named);
    CHECK(query_interface(counter, named) == TRUE);
    CHECK(named->GetName() == "Down");
    // A block that does not implement the asked-for interface: FALSE, and dest becomes 0.
    FB_Both both;
    itf<I_Root> root = both;
    named = down;
    CHECK(query_interface(root, named) == FALSE);
    CHECK(named == 0);
    itf<I_Other> other = nullptr;
    CHECK(query_interface(counter, other) == FALSE);
    // From an unassigned variable: FALSE.
    itf<I_Counter> none;
    named = down;
    CHECK(query_interface(none, named) == FALSE);
    CHECK(named == 0);
  }

  TEST_CASE("__QUERYINTERFACE from an interface to one it EXTENDS or that extends it") {
    FB_Up up;
    itf<I_Named> named = up;
    itf<I_Device> device;
    CHECK(query_interface(named, device) == TRUE);  // down the EXTENDS chain, at run time
    CHECK(device->Enabled() == TRUE);
    itf<I_Counter> counter;
    CHECK(query_interface(device, counter) == TRUE);
    CHECK(counter == itf<I_Counter>(up));
  }

  TEST_CASE("__QUERYINTERFACE along EXTENDS: the interfaces of the base block and the block's own") {
    FB_ConcretePlus plus;
    itf<I_Extra> extra = plus;  // FB_Concrete's own interface, inherited
    itf<I_Counter> counter;
    CHECK(query_interface(extra, counter) == TRUE);  // the base block's interface
    counter->Count();
    CHECK(plus.dValue == 1);  // FB_ConcretePlus's override
    itf<I_Extra> back;
    CHECK(query_interface(counter, back) == TRUE);
    CHECK(back->Extra() == 3);
    // From a block rather than a variable.
    itf<I_Named> named;
    CHECK(query_interface(plus, named) == FALSE);
    CHECK(query_interface(plus, back) == TRUE);
  }

  TEST_CASE("__QUERYPOINTER: the block behind an interface variable") {
    FB_ConcretePlus plus;
    itf<I_Extra> extra = plus;
    void* pointer = nullptr;
    CHECK(query_pointer(extra, pointer) == TRUE);  // bOk := __QUERYPOINTER(extra, pointer);
    CHECK(pointer == static_cast<void*>(&plus));
    // Typed: the block as the type it is, or as a block it EXTENDS; otherwise nullptr.
    CHECK(query_pointer<FB_ConcretePlus>(extra) == &plus);
    CHECK(query_pointer<FB_Concrete>(extra) == static_cast<FB_Concrete*>(&plus));
    CHECK(query_pointer<FB_AbstractCounter>(extra) == static_cast<FB_AbstractCounter*>(&plus));
    CHECK(query_pointer<FB_Up>(extra) == nullptr);
    FB_Concrete concrete;
    extra = concrete;
    CHECK(query_pointer<FB_ConcretePlus>(extra) == nullptr);  // a base is not its derived block
    CHECK(query_pointer<FB_Concrete>(extra) == &concrete);
    // Unassigned: FALSE and 0.
    itf<I_Extra> none;
    CHECK(query_pointer(none, pointer) == FALSE);
    CHECK(pointer == nullptr);
    CHECK(query_pointer<FB_Concrete>(none) == nullptr);
  }
}

namespace {

// Interfaces as concepts: generic code constrained at compile time, called on the concrete
// type (no interface variable, no virtual dispatch where the method is final).
template <class T>
  requires Implements<T, I_Counter>
DINT count_three_times(T& block) {
  block.Count();
  block.Count();
  block.Count();
  return block.Value;
}

struct FB_Final final : function_block<FB_Final, implements<I_Counter>> {
  DINT dValue;
  void body() {}
  void Count(args<Count_vars> in = {}) override { dValue = dValue + in.dStep; }
  DINT Value_Get() override { return dValue; }
  void Value_Set(DINT value) override { dValue = value; }
};

}  // namespace

TEST_SUITE("INTERFACE") {
  TEST_CASE("interfaces as concepts") {
    static_assert(Implements<FB_Up, I_Counter>);
    static_assert(Implements<FB_Up, I_Named>);  // through I_Device
    static_assert(Implements<FB_Down, I_Counter>);
    static_assert(!Implements<FB_Down, I_Device>);
    static_assert(!Implements<FB_AbstractCounter, I_Counter>);  // still ABSTRACT
    static_assert(Implements<FB_Concrete, I_Counter>);
    FB_Final fb;
    CHECK(count_three_times(fb) == 3);
    FB_Down down;
    CHECK(count_three_times(down) == 97);
  }

  TEST_CASE("implementing an interface costs one vtable pointer, its property nothing") {
    struct layout {
      void* vtable;
      DINT dValue;
    };
    static_assert(sizeof(FB_Final) == sizeof(layout));
    FB_Final fb;
    CHECK(static_cast<void*>(&fb.Value) == static_cast<void*>(static_cast<I_Counter*>(&fb)));
  }
}

namespace diamond_test {
using namespace iecoop;
struct I_Root : interface_base<I_Root> {
  virtual INT Id() = 0;
};
struct I_Left : interface_base<I_Left, I_Root> {
  virtual INT Left() = 0;
};
// FUNCTION_BLOCK FB_Both IMPLEMENTS I_Root, I_Left  (I_Left EXTENDS I_Root)
struct FB_Both : function_block<FB_Both, implements<I_Root, I_Left>> {
  void body() {}
  INT Id() override { return 1; }
  INT Left() override { return 2; }
};
struct FB_Base : function_block<FB_Base, implements<I_Root>> {
  virtual void body() {}
  INT Id() override { return 10; }
};
// FUNCTION_BLOCK FB_Derived EXTENDS FB_Base IMPLEMENTS I_Left  (the base's interface, extended)
struct FB_Derived : extends<FB_Derived, FB_Base, implements<I_Left>> {
  void body() override {}  // an empty implementation
  INT Left() override { return 20; }
};
// FUNCTION_BLOCK FB_Again EXTENDS FB_Base IMPLEMENTS I_Root, I_Left  (repeated, as CODESYS allows)
struct FB_Again : extends<FB_Again, FB_Base, implements<I_Root, I_Left>> {
  void body() override {}  // an empty implementation
  INT Id() override { return 30; }
  INT Left() override { return 31; }
};
}  // namespace diamond_test

TEST_SUITE("INTERFACE: one interface reached along two ways") {
  using diamond_test::FB_Again;
  using diamond_test::FB_Base;
  using diamond_test::FB_Both;
  using diamond_test::FB_Derived;
  using diamond_test::I_Left;
  using diamond_test::I_Root;

  TEST_CASE("a block implementing an interface and one that extends it holds it once") {
    FB_Both both;
    itf<I_Root> root = both;
    itf<I_Left> left = both;
    CHECK(root->Id() == 1);
    CHECK(left->Id() == 1);
    CHECK(left->Left() == 2);
    CHECK(sizeof(FB_Both) <= 3 * sizeof(void*));  // vptrs only: no second I_Root
  }

  TEST_CASE("a derived block implements an extension of its base's interface") {
    FB_Derived derived;
    itf<I_Root> root = derived;
    CHECK(root->Id() == 10);
    itf<I_Left> left;
    CHECK(query_interface(root, left) == TRUE);
    CHECK(left->Left() == 20);
    CHECK(left->Id() == 10);
    CHECK(query_pointer<FB_Derived>(root) == &derived);
    CHECK(query_pointer<FB_Base>(root) == &derived);
  }

  TEST_CASE("a derived block may list its base's interface again") {
    FB_Again again;
    itf<I_Root> root = again;
    CHECK(root->Id() == 30);
    itf<I_Left> left;
    CHECK(query_interface(root, left) == TRUE);
    CHECK(left->Left() == 31);
  }

  TEST_CASE("querying an interface variable into itself keeps it") {
    FB_Both both;
    itf<I_Root> root = both;
    CHECK(query_interface(root, root) == TRUE);
    CHECK(root == itf<I_Root>(both));
  }
}
