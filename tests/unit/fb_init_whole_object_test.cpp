// FB_Init, FB_Reinit and FB_Exit run on the whole block (issue 35, point 1). CODESYS runs the
// FB_Init of every level of `FB_C EXTENDS FB_B EXTENDS FB_A` on the finished FB_C: a method or
// property FB_A.FB_Init calls is FB_C's override. Its static analysis rule SA0106 documents
// the order for two levels: FB_A.fb_init -> FB_B.Meth_MyInit -> FB_B.fb_init. FB_Exit runs
// derived first, then base, each on the whole block; FB_Reinit only the most derived one
// (a base's through SUPER^.FB_Reinit()). Checked here for three levels, in every place a
// block is declared: a local, a member of a program, of a global variable list, of another
// block, and an array element; and with the lifecycle operations' flags.
#include "iecoop_test.hpp"

#include <iecoop/runtime/application.hpp>

#include <memory>
#include <string>

using namespace iecoop;

namespace {

std::string calls;

void log(const char* what) {
  calls += what;
  calls += ' ';
}

// FUNCTION_BLOCK FB_A
//   VAR fMaximum : REAL; END_VAR
//   METHOD Meth_MyInit : BOOL ...  log('A.Meth')
//   PROPERTY Maximum : REAL (Get / Set)  log('A.Max')
//   METHOD FB_Init : BOOL  log('A.init'); Meth_MyInit(); THIS^.Maximum := 10;
//   METHOD FB_Reinit : BOOL  log('A.reinit'); Meth_MyInit();
//   METHOD FB_Exit : BOOL  log('A.exit'); Meth_MyInit();
struct FB_A : function_block<FB_A> {
  FB_A() { run_fb_init(*this); }
  FB_A(const FB_A&) = default;
  FB_A& operator=(const FB_A&) = default;
  virtual ~FB_A() { run_fb_exit(*this); }

  REAL fMaximum = 0.0F;
  virtual BOOL Meth_MyInit() {
    log("A.Meth");
    return TRUE;
  }
  virtual REAL Maximum_Get() { return fMaximum; }
  virtual void Maximum_Set(REAL value) {
    log("A.Max");
    fMaximum = value;
  }
  [[no_unique_address]] property<REAL, &FB_A::Maximum_Get, &FB_A::Maximum_Set> Maximum{this};

  BOOL FB_Init(BOOL, BOOL) {
    log("A.init");
    (void)Meth_MyInit();
    Maximum = 10.0F;
    return TRUE;
  }
  virtual BOOL FB_Reinit() {
    log("A.reinit");
    (void)Meth_MyInit();
    return TRUE;
  }
  BOOL FB_Exit(BOOL) {
    log("A.exit");
    (void)Meth_MyInit();
    return TRUE;
  }
  virtual void body() {}
};

// FUNCTION_BLOCK FB_B EXTENDS FB_A: overrides Meth_MyInit and Maximum; its FB_Init calls both.
struct FB_B : extends<FB_B, FB_A> {
  FB_B() { run_fb_init(*this); }
  FB_B(const FB_B&) = default;
  FB_B& operator=(const FB_B&) = default;
  ~FB_B() override { run_fb_exit(*this); }

  DINT nB = 0;
  BOOL Meth_MyInit() override {
    log("B.Meth");
    return TRUE;
  }
  void Maximum_Set(REAL value) override {
    log("B.Max");
    fMaximum = value * 2.0F;
  }
  BOOL FB_Init(BOOL, BOOL) {
    log("B.init");
    (void)Meth_MyInit();
    Maximum = 20.0F;
    return TRUE;
  }
  BOOL FB_Reinit() override {
    log("B.reinit");
    return TRUE;
  }
  BOOL FB_Exit(BOOL) {
    log("B.exit");
    (void)Meth_MyInit();
    return TRUE;
  }
  void body() override {}
};

// FUNCTION_BLOCK FB_C EXTENDS FB_B: overrides both again; Meth_MyInit counts its calls in a
// variable of FB_C's own, which exists (and is initialised) before any level's FB_Init runs.
struct FB_C : extends<FB_C, FB_B> {
  FB_C() { run_fb_init(*this); }
  FB_C(const FB_C&) = default;
  FB_C& operator=(const FB_C&) = default;
  ~FB_C() override { run_fb_exit(*this); }

  DINT nInits = 0;
  BOOL Meth_MyInit() override {
    log("C.Meth");
    nInits = nInits + 1;
    return TRUE;
  }
  void Maximum_Set(REAL value) override {
    log("C.Max");
    fMaximum = value * 3.0F;
  }
  BOOL FB_Init(BOOL, BOOL) {
    log("C.init");
    (void)Meth_MyInit();
    return TRUE;
  }
  BOOL FB_Reinit() override {
    log("C.reinit");
    (void)Meth_MyInit();
    (void)FB_B::FB_Reinit();  // SUPER^.FB_Reinit()
    return TRUE;
  }
  BOOL FB_Exit(BOOL) {
    log("C.exit");
    (void)Meth_MyInit();
    return TRUE;
  }
  void body() override {}
};

// The documented order, for the whole FB_C: each level's FB_Init from the bottom up, each
// calling FB_C's Meth_MyInit and FB_C's Maximum Set.
constexpr const char* c_init = "A.init C.Meth C.Max B.init C.Meth C.Max C.init C.Meth ";
// FB_Exit from the top down, each calling FB_C's Meth_MyInit.
constexpr const char* c_exit = "C.exit C.Meth B.exit C.Meth A.exit C.Meth ";

// A block holding an FB_C and an array of them.
struct FB_Holder : function_block<FB_Holder> {
  FB_C fbInner;
  ARRAY<FB_C, 1, 2> aInner;
  void body() {}
};

// PROGRAM PLC_PRG  VAR fbC : FB_C; END_VAR
struct PLC_PRG : program<PLC_PRG> {
  FB_C fbC;
  void body() { fbC(); }
};

// VAR_GLOBAL  gC : FB_C; END_VAR
struct GVL_Blocks : global_variables<GVL_Blocks> {
  FB_C gC;
};

// SA0106's own example, two levels: FB_A2.fb_init calls Meth_MyInit, which FB_B2 overrides.
struct FB_A2 : function_block<FB_A2> {
  FB_A2() { run_fb_init(*this); }
  virtual ~FB_A2() = default;
  DINT mbMyDintA = 0;
  virtual BOOL Meth_MyInit() {
    mbMyDintA = 123;
    return TRUE;
  }
  BOOL FB_Init(BOOL, BOOL) {
    log("A2.fb_init");
    (void)Meth_MyInit();
    return TRUE;
  }
  virtual void body() {}
};
struct FB_B2 : extends<FB_B2, FB_A2> {
  FB_B2() { run_fb_init(*this); }
  DINT mbMyDintB = 0;
  BOOL Meth_MyInit() override {
    log("B2.Meth_MyInit");
    mbMyDintB = 123;
    return TRUE;
  }
  BOOL FB_Init(BOOL, BOOL) {
    log("B2.fb_init");
    return TRUE;
  }
  void body() override {}
};

// A derived block whose constructor forgets run_fb_init, and one whose destructor forgets
// run_fb_exit.
struct FB_Forgets_Init : extends<FB_Forgets_Init, FB_B> {
  FB_Forgets_Init() = default;
  ~FB_Forgets_Init() override { run_fb_exit(*this); }
  void body() override {}
};
struct FB_Forgets_Exit : extends<FB_Forgets_Exit, FB_B> {
  FB_Forgets_Exit() { run_fb_init(*this); }
  ~FB_Forgets_Exit() override = default;
  void body() override {}
};

// FB_Init parameters by name (point 9): swapping the two REALs in the declaration means the
// same, as in ST.
//   FUNCTION_BLOCK FB_Clamp  METHOD FB_Init : BOOL  VAR_INPUT fMinimum, fMaximum : LREAL; ...
struct FB_Clamp_Init {
  LREAL fMinimum = 0.0;
  LREAL fMaximum = 0.0;
};
struct FB_Clamp : function_block<FB_Clamp> {
  template <NamedInput... A>
  explicit FB_Clamp(A&&... a) {
    run_fb_init(*this, std::forward<A>(a)...);
  }
  LREAL fLow = 0.0;
  LREAL fHigh = 0.0;
  LREAL fIn = 0.0;
  LREAL fOut = 0.0;
  using VAR_INPUT = pins<&FB_Clamp::fIn>;
  using VAR_OUTPUT = pins<&FB_Clamp::fOut>;
  BOOL FB_Init(BOOL, BOOL, args<FB_Clamp_Init> in) {
    fLow = in.fMinimum;
    fHigh = in.fMaximum;
    return TRUE;
  }
  void body() { fOut = LIMIT(fLow, fIn, fHigh); }
};

// FUNCTION_BLOCK FINAL FB_Final EXTENDS FB_C, whose FB_Init is a C++ template (a FINAL block
// is no base level, so its FB_Init may be one): called with the declaration's parameters
// after the levels below.
struct FB_Final final : extends<FB_Final, FB_C> {
  template <class... A>
  explicit FB_Final(A&&... a) {
    run_fb_init(*this, std::forward<A>(a)...);
  }
  ~FB_Final() override { run_fb_exit(*this); }
  DINT nGiven = 0;
  template <class... A>
  BOOL FB_Init(BOOL, BOOL, A... given) {
    log("Final.init");
    nGiven = static_cast<DINT::rep>(sizeof...(given));
    (void)Meth_MyInit();
    return TRUE;
  }
  void body() override {}
};

}  // namespace

TEST_SUITE("FB_Init on the whole block") {
  TEST_CASE("SA0106's example: FB_A.fb_init -> FB_B.Meth_MyInit -> FB_B.fb_init") {
    calls.clear();
    FB_B2 fbB;
    CHECK(calls == "A2.fb_init B2.Meth_MyInit B2.fb_init ");
    CHECK(fbB.mbMyDintB == 123);
    CHECK(fbB.mbMyDintA == 0);  // FB_A2's method did not run
  }

  TEST_CASE("three levels, a local: each level's FB_Init calls the most derived method and property") {
    calls.clear();
    {
      FB_C fbC;
      CHECK(calls == c_init);
      CHECK(fbC.nInits == 3);
      CHECK(fbC.fMaximum == doctest::Approx(60.0));  // FB_C's Set, from FB_B's FB_Init (20 * 3)
      calls.clear();
    }
    CHECK(calls == c_exit);
  }

  TEST_CASE("a FINAL block's FB_Init may be a template") {
    calls.clear();
    {
      FB_Final fbFinal{DINT(1), DINT(2)};
      CHECK(calls == std::string(c_init) + "Final.init C.Meth ");
      CHECK(fbFinal.nGiven == 2);
      CHECK(fbFinal.nInits == 4);
      calls.clear();
    }
    CHECK(calls == c_exit);
  }

  TEST_CASE("each level alone runs its own chain") {
    calls.clear();
    { FB_B fbB; }
    CHECK(calls == "A.init B.Meth B.Max B.init B.Meth B.Max B.exit B.Meth A.exit B.Meth ");
    calls.clear();
    { FB_A fbA; }
    CHECK(calls == "A.init A.Meth A.Max A.exit A.Meth ");
  }

  TEST_CASE("a block nested in a block, and array elements") {
    calls.clear();
    {
      FB_Holder holder;
      std::string expected;
      for (int i = 0; i < 3; ++i) expected += c_init;
      CHECK(calls == expected);
      CHECK(holder.fbInner.nInits == 3);
      CHECK(holder.aInner[1].nInits == 3);
      CHECK(holder.aInner[2].nInits == 3);
      calls.clear();
    }
    std::string expected;
    for (int i = 0; i < 3; ++i) expected += c_exit;
    CHECK(calls == expected);
  }

  TEST_CASE("a block in a program and in a global variable list of an application") {
    calls.clear();
    {
      application plc{task<PLC_PRG>{"Main", cyclic{"T#1ms"_iec}, 1}, globals<GVL_Blocks>{}};
      CHECK(plc.start());
      CHECK(calls == std::string(c_init) + c_init);
      CHECK(plc.get<PLC_PRG>().fbC.nInits == 3);
      CHECK(plc.get<GVL_Blocks>().gC.nInits == 3);
      calls.clear();
      plc.reset(reset_kind::warm);
      CHECK(calls == std::string(c_exit) + c_exit + c_init + c_init);
      calls.clear();
      plc.stop();
      CHECK(calls == std::string(c_exit) + c_exit);
    }
  }

  TEST_CASE("the lifecycle operations: reset and online change (FB_Reinit on the whole block)") {
    alignas(FB_C) unsigned char a[sizeof(FB_C)];
    alignas(FB_C) unsigned char b[sizeof(FB_C)];
    calls.clear();
    FB_C& first = first_start<FB_C>(a);
    CHECK(calls == c_init);
    calls.clear();
    reset(first, reset_kind::cold);
    CHECK(calls == std::string(c_exit) + c_init);
    first.nInits = 40;
    calls.clear();
    FB_C& moved = online_change(first, b);
    // old FB_Exit (C, B, A), new FB_Init (A, B, C), the copy, then FB_Reinit of the whole
    // block: FB_C's, which calls FB_C's method and SUPER^.FB_Reinit().
    CHECK(calls == std::string(c_exit) + c_init + "C.reinit C.Meth B.reinit ");
    CHECK(moved.nInits == 41);  // the copied 40, then FB_Reinit's call
    calls.clear();
    std::destroy_at(&moved);
    CHECK(calls == c_exit);
  }

  TEST_CASE("a derived constructor without run_fb_init is a lifecycle fault, not a quiet base-only init") {
    testing::expect_faults faults;
    calls.clear();
    {
      alignas(FB_Forgets_Init) unsigned char storage[sizeof(FB_Forgets_Init)];
      FB_Forgets_Init& fb = first_start<FB_Forgets_Init>(storage);
      CHECK(calls.empty());  // no level's FB_Init ran: none ran as a part of a half-built block
      REQUIRE(faults.count() == 1);
      CHECK(faults.only(fault_kind::lifecycle));
      REQUIRE(faults.last().pou != nullptr);
      CHECK(std::string(faults.last().pou) == "FB_Forgets_Init");
      CHECK(std::string(faults.last().message).find("run_fb_init") != std::string::npos);
      std::destroy_at(&fb);
    }
  }

  TEST_CASE("a derived destructor without run_fb_exit is a lifecycle fault") {
    testing::expect_faults faults;
    calls.clear();
    { FB_Forgets_Exit fb; }
    REQUIRE(faults.count() == 1);
    CHECK(faults.only(fault_kind::lifecycle));
    REQUIRE(faults.last().pou != nullptr);
    CHECK(std::string(faults.last().pou) == "FB_Forgets_Exit");
    CHECK(std::string(faults.last().message).find("run_fb_exit") != std::string::npos);
    // The bases' FB_Exit still ran (on what is left of the block: FB_B's level).
    CHECK(calls.find("B.exit") != std::string::npos);
  }

  TEST_CASE("FB_Init parameters by name, in any order") {
    // fbClamp : FB_Clamp(fMinimum := 0.0, fMaximum := 100.0);
    FB_Clamp fbClamp{"fMinimum"_ = 0.0, "fMaximum"_ = 100.0};
    FB_Clamp fbSwapped{"fMaximum"_ = 100.0, "fMinimum"_ = 0.0};
    fbClamp("fIn"_ = 150.0);
    fbSwapped("fIn"_ = 50.0);
    CHECK(fbClamp.fOut == doctest::Approx(100.0));
    CHECK(fbSwapped.fOut == doctest::Approx(50.0));
    CHECK(fbSwapped.fLow == doctest::Approx(0.0));
    CHECK(fbSwapped.fHigh == doctest::Approx(100.0));
  }
}
