// Variables at their edges (each case a defect once found and fixed): wrappers of structures
// and blocks, => into locals and in-outs, in-out value assignment and relocation, outputs
// handed on to SUPER, program scratch.
#include "iecoop_test.hpp"

#include <memory>

using namespace iecoop;

namespace {

struct ST_Pos {  // TYPE ST_Pos : STRUCT x, y : REAL; END_STRUCT END_TYPE
  REAL x;
  REAL y;
};

struct Callee : function_block<Callee> {
  INT q;
  using VAR_OUTPUT = pins<&Callee::q>;
  void body() { q = q + 1; }
  struct M_vars {
    INT a;
    output<INT> r;
    output<ST_Pos> p;
  };
  void M(args<M_vars> in) {
    in.r = in.a;
    in.p = ST_Pos{1.0f, 2.0f};
  }
};

struct User : function_block<User> {
  Callee c;
  var<INT> loc;     // => into the block's own VAR
  var<ST_Pos> pos;  // a structured VAR
  DINT wide;        // => with IEC widening
  in_out<INT> io;   // => into an in-out
  using VAR_IN_OUT = pins<&User::io>;
  void body() {
    c("q"_ >> loc);
    c.M({"a"_ = 7, "r"_ >> wide, "p"_ >> pos});
  }
  void ToInOut() { c.M({"a"_ = 9, "r"_ >> io}); }
};

struct Base : function_block<Base> {
  virtual ~Base() = default;
  virtual void body() {}
  struct M_vars {
    INT a;
    output<INT> r;
  };
  virtual void M(args<M_vars> in) { in.r = in.a * 2; }
};
struct Forwarding : extends<Forwarding, Base> {
  void body() override {}                             // an empty implementation
  void M(args<M_vars> in) override { SUPER::M(in); }  // SUPER^.M(a := a, r => r);
};
struct Adding : extends<Adding, Base> {
  void body() override {}  // an empty implementation
  void M(args<M_vars> in) override {
    SUPER::M(std::move(in));
    in.r = in.r + 1;  // r := r + 1;
  }
};

struct Acc : function_block<Acc> {
  in_out<INT> total;
  using VAR_IN_OUT = pins<&Acc::total>;
  void body() { total = total + 1; }
};
struct PRG_Acc : program<PRG_Acc> {
  INT counter;
  Acc acc;
  PRG_Acc() { acc.total.bind(counter); }
  void body() { acc(); }
};

struct PRG_Late : program<PRG_Late> {
  INT n;
  void body() { n = n + 1; }
};

}  // namespace

TEST_SUITE("variables: edge cases") {
  TEST_CASE("var<>, output<> and in_out<> hold structures and blocks") {
    User user;
    INT x = 0;
    user("io"_ = x);
    CHECK(user.loc == 1);
    CHECK(user.wide == 7);
    CHECK(user.pos->x == 1.0f);
    CHECK(user.pos->y == 2.0f);
    Callee target;
    in_out<Callee> block{target};
    block->body();
    CHECK(target.q == 1);
  }

  TEST_CASE("a method output delivers into an in-out") {
    User user;
    INT x = 0;
    user.io.bind(x);
    user.ToInOut();
    CHECK(x == 9);
  }

  TEST_CASE("assigning one in-out to another copies the value, as ST's a := b") {
    INT a = 1;
    INT b = 2;
    in_out<INT> ra{a};
    in_out<INT> rb{b};
    ra = rb;
    CHECK(a == 2);
    CHECK(&ra.get() == &a);
  }

  TEST_CASE("an online change keeps the bindings the new instance made") {
    alignas(PRG_Acc) unsigned char first[sizeof(PRG_Acc)];
    alignas(PRG_Acc) unsigned char second[sizeof(PRG_Acc)];
    PRG_Acc& p = first_start<PRG_Acc>(first);
    p();
    PRG_Acc& moved = online_change(p, second);
    moved();
    CHECK(moved.counter == 2);
    CHECK(&moved.acc.total.get() == &moved.counter);
    std::destroy_at(&moved);
  }

  TEST_CASE("a method that hands its variables on to SUPER still delivers its outputs") {
    INT x = 0;
    Base base;
    base.M({"a"_ = 5, "r"_ >> x});
    CHECK(x == 10);
    x = 0;
    Forwarding forwarding;
    forwarding.M({"a"_ = 5, "r"_ >> x});
    CHECK(x == 10);
    x = 0;
    Adding adding;
    adding.M({"a"_ = 5, "r"_ >> x});
    CHECK(x == 11);
  }

  TEST_CASE("a PROGRAM used too early gets a scratch stand-in that never becomes the instance") {
    iecoop_test::fault_recorder faults;
    PRG_Late::instance()();
    CHECK(faults.count == 1);
    PRG_Late real;
    CHECK(faults.count == 1);  // the real instance is no duplicate
    CHECK(&PRG_Late::instance() == &real);
  }
}

TEST_CASE("blocks and programs are value-initialised with {} too") {
  Callee c{};
  PRG_Late p{};
  CHECK(c.q == 0);
  CHECK(p.n == 0);
}

namespace {
// Wrapped REALs, BOOLs and STRINGs in expressions: the wrapper is its value, also where the
// value needs a second conversion (REAL -> float) or has template operators (STRING).
struct FB_Mixed : function_block<FB_Mixed> {
  var<REAL> rGain{2.0f};
  var<BOOL> bOn;
  var<STRING<>> sName;
  REAL rOut;
  BOOL bOut;
  void body() {
    bOn = !bOn;
    if (bOn) rOut = rGain * 1.5f + rGain;  // IF bOn THEN rOut := rGain * 1.5 + rGain;
    bOut = bOn & TRUE;
    sName = "mixed";
  }
};
struct Scale_vars {
  in_out<REAL> rValue;
  output<REAL> rHalf;
};
inline constexpr function Scale = [](args<Scale_vars> in) -> BOOL {
  in.rHalf = in.rValue / 2.0f;
  in.rValue = in.rValue * 3.0f;
  return BOOL(in.rHalf > 1.0f);
};
}  // namespace

TEST_CASE("var<>, in_out<> and output<> of REAL and BOOL work in expressions and conditions") {
  FB_Mixed fb;
  fb();
  CHECK(fb.rOut == doctest::Approx(5.0));
  CHECK(fb.bOut == TRUE);
  CHECK(-fb.rGain == doctest::Approx(-2.0));
  CHECK(fb.rGain + fb.rGain == doctest::Approx(4.0));
  CHECK(fb.sName == "mixed");
  CHECK(!fb.bOn == FALSE);
  REAL value = 4.0f;
  REAL half;
  CHECK(Scale("rValue"_ = value, "rHalf"_ >> half) == TRUE);
  CHECK(half == doctest::Approx(2.0));
  CHECK(value == doctest::Approx(12.0));
}
