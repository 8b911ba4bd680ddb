// Every IEC type in every position, constructed without an initial value, against ST's initial
// value (issue 35, point 3: no variable is ever indeterminate). Shared by the unit test
// (tests/unit/initial_values_test.cpp: doctest CHECKs on a stack filled with garbage) and the
// program run under valgrind's memcheck (tests/programs/initial_values.cpp: every value is
// branched on, so a value C++ left undefined is reported as "Conditional jump depends on
// uninitialised value").
//
// ST's initial values: 0, FALSE, 0.0, '' and T#0s, D#1970-01-01, ...; a subrange's 0, or its
// lower limit where 0 is outside it; an enumeration's first component, or the type's declared
// initial value (CODESYS: "initialization is automatically performed with the top member"); a
// POINTER 0 and a REFERENCE unbound.
#pragma once

#include <cstddef>
#include <cstdint>

#include <iecoop/iecoop.hpp>

namespace initial_values {

using namespace iecoop;

// --- Enumerations, declared as docs/porting-guide.md shows ---------------------------------

// TYPE E_Zero : (Zero_A, Zero_B); END_TYPE — starts at Zero_A, 0
enum E_Zero : INT::rep { Zero_A, Zero_B };
// {attribute 'qualified_only'} TYPE E_Five : (a := 5, b); END_TYPE — starts at a, 5
enum class E_Five : INT::rep { a = 5, b };
// {attribute 'qualified_only'} {attribute 'strict'} TYPE E_Strict : (Off := -3, On := 7) DINT; END_TYPE
enum class E_Strict : DINT::rep { Off = -3, On = 7 };
// TYPE E_Init : (Idle, Run, Fault) := Run; END_TYPE — starts at Run, 1
enum class E_Init : INT::rep { Idle, Run, Fault };
// TYPE E_Flags : (FlagA := 16#80, FlagB := 16#01) BYTE; END_TYPE — starts at FlagA, 16#80
enum E_Flags : BYTE::rep { FlagA = 0x80, FlagB = 0x01 };

}  // namespace initial_values

template <>
inline constexpr auto iecoop::enum_components<initial_values::E_Zero> =
    iecoop::components<initial_values::Zero_A, initial_values::Zero_B>{};
template <>
inline constexpr auto iecoop::enum_components<initial_values::E_Five> =
    iecoop::components<initial_values::E_Five::a, initial_values::E_Five::b>{};
template <>
inline constexpr bool iecoop::enum_strict<initial_values::E_Strict> = true;
template <>
inline constexpr auto iecoop::enum_components<initial_values::E_Strict> =
    iecoop::components<initial_values::E_Strict::Off, initial_values::E_Strict::On>{};
template <>
inline constexpr initial_values::E_Init iecoop::enum_initial<initial_values::E_Init> = initial_values::E_Init::Run;
template <>
struct iecoop::enum_base<initial_values::E_Flags> {
  using type = BYTE;
};
template <>
inline constexpr auto iecoop::enum_components<initial_values::E_Flags> =
    iecoop::components<initial_values::FlagA, initial_values::FlagB>{};

namespace initial_values {

// --- STRUCT, UNION, interface ----------------------------------------------------------------

// TYPE ST_Pos : STRUCT x, y : REAL; n : INT; s : STRING(8); e : E_Five; END_STRUCT END_TYPE
struct ST_Pos {
  REAL x, y;
  INT n;
  STRING<8> s;
  E_Five e = E_Five::a;  // an enumeration member states its initial value (iecoop refuses it without one)
  ARRAY<E_Five, 1, 2> ae;
};
// TYPE U_Word : UNION w : WORD; ab : ARRAY[0..1] OF BYTE; END_UNION END_TYPE
union U_Word {
  WORD w;
  ARRAY<BYTE, 0, 1> ab;
  constexpr U_Word() : w() {}
};

/// A process image of its own: the located variables below read what nothing else wrote.
struct initial_values_image_tag {};
using image = process_image<64, 64, 256, addressing::codesys, initial_values_image_tag>;

struct I_Named : interface_base<I_Named> {
  virtual INT Id() = 0;
};

// --- Values against ST's initial value: each is read (and branched on) by `report` -----------

/// Hides from the optimiser what the objects hold, so that each check reads them from memory
/// (and memcheck sees the read) rather than from what the compiler knows of their construction.
template <class T>
inline void escape_one(const T& object) {
  asm volatile("" : : "r"(&object) : "memory");
}
template <class... T>
inline void escape(const T&... objects) {
  (escape_one(objects), ...);
}

template <class R>
void expect(R& report, const char* what, bool ok) {
  report(what, ok);
}

template <class R>
void check_elementary(R& report, const char* where, const BOOL& b, const BYTE& by, const WORD& w, const DWORD& dw,
                      const LWORD& lw, const SINT& si, const INT& i, const DINT& di, const LINT& li) {
  (void)where;
  expect(report, "BOOL is FALSE", !b);
  expect(report, "BYTE is 0", by.value() == 0);
  expect(report, "WORD is 0", w.value() == 0);
  expect(report, "DWORD is 0", dw.value() == 0);
  expect(report, "LWORD is 0", lw.value() == 0);
  expect(report, "SINT is 0", si.value() == 0);
  expect(report, "INT is 0", i.value() == 0);
  expect(report, "DINT is 0", di.value() == 0);
  expect(report, "LINT is 0", li.value() == 0);
}

template <class R, class E>
void check_enum(R& report, const char* what, E e, E expected) {
  expect(report, what, static_cast<std::underlying_type_t<E>>(e) == static_cast<std::underlying_type_t<E>>(expected));
}

// --- A FUNCTION_BLOCK with every type as VAR_INPUT, VAR_OUTPUT and VAR -------------------------

struct FB_All : function_block<FB_All> {
  // VAR_INPUT
  BOOL bIn;
  USINT usIn;
  UINT uiIn;
  UDINT udIn;
  ULINT ulIn;
  REAL rIn;
  LREAL lrIn;
  TIME tIn;
  LTIME ltIn;
  DATE dIn;
  TOD todIn;
  DT dtIn;
  LDATE ldIn;
  LTOD ltodIn;
  LDT ldtIn;
  STRING<> sIn;
  WSTRING<12> wsIn;
  subrange<INT, -10, 10> srIn;
  subrange<INT, 5, 10> srHighIn;  // 0 is outside: starts at 5
  POINTER_TO<INT> pIn;
  E_Five eIn = E_Five::a;  // a C++ enum pin states its initial value (iecoop refuses it without one)
  ST_Pos stIn;
  ARRAY<INT, 1, 3> aiIn;
  // VAR_OUTPUT
  BOOL bOut;
  INT iOut;
  LREAL lrOut;
  STRING<20> sOut;
  // VAR_IN_OUT
  in_out<INT> refIo;
  // VAR
  var<BOOL> bVar;
  var<BYTE> byVar;
  var<WORD> wVar;
  var<DWORD> dwVar;
  var<LWORD> lwVar;
  var<SINT> siVar;
  var<INT> iVar;
  var<DINT> diVar;
  var<LINT> liVar;
  var<REAL> rVar;
  var<TIME> tVar;
  var<STRING<>> sVar;
  var<E_Zero> eZeroVar;
  var<E_Five> eFiveVar;
  var<E_Strict> eStrictVar;
  var<E_Init> eInitVar;
  var<E_Flags> eFlagsVar;
  var<ARRAY<E_Five, 1, 4>> aeVar;
  var<ARRAY<E_Init, 0, 2, 0, 1>> aeGrid;
  var<ST_Pos> stVar;
  var<U_Word> uVar;
  var<POINTER_TO<DINT>> pVar;
  var<itf<I_Named>> ipVar;
  retain<E_Five> eRetain;
  retain<UDINT> udRetain;
  persistent<E_Init> ePersistent;
  TON tonInner;  // a block inside a block
  ARRAY<TON, 1, 2> aTon;
  ARRAY<E_Strict, 1, 3> aeStrict;
  ARRAY<ST_Pos, 1, 2> aStruct;
  E_Five eProtected = E_Five::a;  // a plain enum member states its initial value
  // Located variables: their values live in the process image, whose bytes start at 0.
  [[no_unique_address]] located<INT, "%MW10", image> iMarker;
  [[no_unique_address]] located<BOOL, "%QX2.1", image> bLamp;
  [[no_unique_address]] located<REAL, "%ID4", image> rSensor;

  using VAR_INPUT = pins<&FB_All::bIn, &FB_All::usIn, &FB_All::uiIn, &FB_All::udIn, &FB_All::ulIn, &FB_All::rIn,
                         &FB_All::lrIn, &FB_All::tIn, &FB_All::ltIn, &FB_All::dIn, &FB_All::todIn, &FB_All::dtIn,
                         &FB_All::ldIn, &FB_All::ltodIn, &FB_All::ldtIn, &FB_All::sIn, &FB_All::wsIn, &FB_All::srIn,
                         &FB_All::srHighIn, &FB_All::pIn, &FB_All::eIn, &FB_All::stIn, &FB_All::aiIn>;
  using VAR_OUTPUT = pins<&FB_All::bOut, &FB_All::iOut, &FB_All::lrOut, &FB_All::sOut>;
  using VAR_IN_OUT = pins<&FB_All::refIo>;

  void body() {}
};

template <class R>
void check_struct(R& report, const ST_Pos& st) {
  expect(report, "STRUCT REAL is 0.0", st.x == 0.0f && st.y == 0.0f);
  expect(report, "STRUCT INT is 0", st.n.value() == 0);
  expect(report, "STRUCT STRING is ''", st.s.empty() && st.s.data()[0] == '\0');
  check_enum(report, "STRUCT enum member at its initial value", st.e, E_Five::a);
  check_enum(report, "STRUCT ARRAY OF E_Five[1] is a", st.ae[1], E_Five::a);
  check_enum(report, "STRUCT ARRAY OF E_Five[2] is a", st.ae[2], E_Five::a);
}

template <class R>
void check_block(R& report, const FB_All& fb) {
  expect(report, "VAR_INPUT BOOL is FALSE", !fb.bIn);
  expect(report, "VAR_INPUT USINT UINT UDINT ULINT are 0",
         fb.usIn.value() == 0 && fb.uiIn.value() == 0 && fb.udIn.value() == 0 && fb.ulIn.value() == 0);
  expect(report, "VAR_INPUT REAL is 0.0", fb.rIn == 0.0f);
  expect(report, "VAR_INPUT LREAL is 0.0", fb.lrIn == 0.0);
  expect(report, "VAR_INPUT TIME is T#0s", fb.tIn.count() == 0);
  expect(report, "VAR_INPUT LTIME is LTIME#0ns", fb.ltIn.count() == 0);
  expect(report, "VAR_INPUT DATE is D#1970-01-01", fb.dIn.count() == 0);
  expect(report, "VAR_INPUT TOD is TOD#00:00:00", fb.todIn.count() == 0);
  expect(report, "VAR_INPUT DT is DT#1970-01-01-00:00:00", fb.dtIn.count() == 0);
  expect(report, "VAR_INPUT LDATE LTOD LDT are 0",
         fb.ldIn.count() == 0 && fb.ltodIn.count() == 0 && fb.ldtIn.count() == 0);
  expect(report, "VAR_INPUT STRING is ''", fb.sIn.empty() && fb.sIn.size() == 0);
  expect(report, "VAR_INPUT WSTRING is \"\"", fb.wsIn.empty());
  expect(report, "VAR_INPUT subrange INT(-10..10) is 0", fb.srIn.get().value() == 0);
  expect(report, "VAR_INPUT subrange INT(5..10) is 5", fb.srHighIn.get().value() == 5);
  expect(report, "VAR_INPUT POINTER is 0", fb.pIn == nullptr);
  check_enum(report, "VAR_INPUT enum at its initial value", fb.eIn, E_Five::a);
  check_struct(report, fb.stIn);
  expect(report, "VAR_INPUT ARRAY OF INT is 0", fb.aiIn[1].value() == 0 && fb.aiIn[3].value() == 0);
  expect(report, "VAR_OUTPUT BOOL INT LREAL STRING",
         !fb.bOut && fb.iOut.value() == 0 && fb.lrOut == 0.0 && fb.sOut.empty());
  expect(report, "VAR_IN_OUT is unbound", !fb.refIo.bound());
  check_elementary(report, "VAR", fb.bVar.get(), fb.byVar.get(), fb.wVar.get(), fb.dwVar.get(), fb.lwVar.get(),
                   fb.siVar.get(), fb.iVar.get(), fb.diVar.get(), fb.liVar.get());
  expect(report, "VAR REAL is 0.0", fb.rVar.get() == 0.0f);
  expect(report, "VAR TIME is T#0s", fb.tVar.get().count() == 0);
  expect(report, "VAR STRING is ''", fb.sVar.get().empty());
  check_enum(report, "VAR E_Zero starts at Zero_A", fb.eZeroVar.get(), Zero_A);
  check_enum(report, "VAR E_Five starts at a (5)", fb.eFiveVar.get(), E_Five::a);
  check_enum(report, "VAR E_Strict starts at Off (-3)", fb.eStrictVar.get(), E_Strict::Off);
  check_enum(report, "VAR E_Init starts at the type's initial value Run", fb.eInitVar.get(), E_Init::Run);
  check_enum(report, "VAR E_Flags starts at FlagA (16#80)", fb.eFlagsVar.get(), FlagA);
  for (const E_Five e : fb.aeVar.get()) check_enum(report, "VAR ARRAY OF E_Five starts at a", e, E_Five::a);
  for (const E_Init e : fb.aeGrid.get())
    check_enum(report, "VAR ARRAY[0..2, 0..1] OF E_Init starts at Run", e, E_Init::Run);
  check_struct(report, fb.stVar.get());
  expect(report, "VAR UNION is 0", fb.uVar.get().w.value() == 0);
  expect(report, "VAR POINTER is 0", fb.pVar.get() == nullptr);
  expect(report, "VAR interface variable is 0", !fb.ipVar.get());
  check_enum(report, "RETAIN E_Five starts at a", fb.eRetain.get(), E_Five::a);
  expect(report, "RETAIN UDINT is 0", fb.udRetain.get().value() == 0);
  check_enum(report, "PERSISTENT E_Init starts at its type's initial value", fb.ePersistent.get(), E_Init::Run);
  expect(report, "a TON inside starts idle",
         !fb.tonInner.Q && fb.tonInner.ET.get().count() == 0 && !fb.tonInner.IN && fb.tonInner.PT.count() == 0);
  expect(report, "ARRAY OF TON starts idle", !fb.aTon[1].Q && !fb.aTon[2].Q && fb.aTon[2].ET.get().count() == 0);
  for (const E_Strict e : fb.aeStrict) check_enum(report, "ARRAY OF E_Strict starts at Off", e, E_Strict::Off);
  check_struct(report, fb.aStruct[1]);
  check_struct(report, fb.aStruct[2]);
  check_enum(report, "a plain enum member at its initial value", fb.eProtected, E_Five::a);
  expect(report, "located %MW INT is 0", fb.iMarker.get().value() == 0);
  expect(report, "located %QX BOOL is FALSE", !fb.bLamp.get());
  expect(report, "located %ID REAL is 0.0", fb.rSensor.get() == 0.0f);
}

// --- A PROGRAM -------------------------------------------------------------------------------

struct PRG_All : program<PRG_All> {
  INT iIn;
  E_Init eIn = E_Init::Run;
  var<E_Five> eVar;
  var<ARRAY<E_Flags, 1, 3>> aFlags;
  STRING<> sOut;
  using VAR_INPUT = pins<&PRG_All::iIn, &PRG_All::eIn>;
  using VAR_OUTPUT = pins<&PRG_All::sOut>;
  void body() {}
};

template <class R>
void check_program(R& report, const PRG_All& p) {
  expect(report, "PROGRAM VAR_INPUT INT is 0", p.iIn.value() == 0);
  check_enum(report, "PROGRAM VAR_INPUT enum at its initial value", p.eIn, E_Init::Run);
  check_enum(report, "PROGRAM VAR E_Five starts at a", p.eVar.get(), E_Five::a);
  for (const E_Flags e : p.aFlags.get()) check_enum(report, "PROGRAM ARRAY OF E_Flags starts at FlagA", e, FlagA);
  expect(report, "PROGRAM VAR_OUTPUT STRING is ''", p.sOut.empty());
}

// --- A global variable list ------------------------------------------------------------------

struct GVL_All : global_variables<GVL_All> {
  INT iMode;
  BOOL bAuto;
  E_Five eMode = E_Five::a;
};

// --- A METHOD's and a FUNCTION's variables ---------------------------------------------------

// METHOD M_All : INT
// VAR_INPUT iIn : INT; eIn : E_Five; sIn : STRING; END_VAR
// VAR_OUTPUT eOut : E_Strict; rOut : REAL; END_VAR
// VAR iTemp : DINT; eTemp : E_Init; aeTemp : ARRAY[1..2] OF E_Five; stTemp : ST_Pos; END_VAR
struct M_All_vars {
  INT iIn;
  E_Five eIn;  // a C++ enum without an initial value: args<> starts it at its first component
  E_Init eInitIn;
  E_Zero eZeroIn;
  STRING<> sIn;
  output<E_Strict> eOut;
  output<REAL> rOut;
  temp<DINT> iTemp;
  temp<E_Init> eTemp;
  temp<ARRAY<E_Five, 1, 2>> aeTemp;
  temp<ST_Pos> stTemp;
};

template <class R>
struct method_checker {
  R* report;
  INT M_All(args<M_All_vars> in) {
    escape(in);
    expect(*report, "METHOD VAR_INPUT INT is 0", in.iIn.value() == 0);
    check_enum(*report, "METHOD VAR_INPUT E_Five starts at a (5)", in.eIn, E_Five::a);
    check_enum(*report, "METHOD VAR_INPUT E_Init starts at Run", in.eInitIn, E_Init::Run);
    check_enum(*report, "METHOD VAR_INPUT E_Zero starts at Zero_A", in.eZeroIn, Zero_A);
    expect(*report, "METHOD VAR_INPUT STRING is ''", in.sIn.empty());
    check_enum(*report, "METHOD VAR_OUTPUT E_Strict starts at Off", in.eOut.get(), E_Strict::Off);
    expect(*report, "METHOD VAR_OUTPUT REAL is 0.0", in.rOut.get() == 0.0f);
    expect(*report, "METHOD VAR DINT is 0", in.iTemp.get().value() == 0);
    check_enum(*report, "METHOD VAR E_Init starts at Run", in.eTemp.get(), E_Init::Run);
    for (const E_Five e : in.aeTemp.get()) check_enum(*report, "METHOD VAR ARRAY OF E_Five starts at a", e, E_Five::a);
    check_struct(*report, in.stTemp.get());
    INT M_All;  // the return variable: 0
    escape(M_All);
    return M_All;
  }
};

// --- Locals: a function's VAR_TEMP and a block or PROGRAM declared as a local variable ----------

template <class R>
[[gnu::noinline]] void check_locals(R& report) {
  BOOL b;
  BYTE by;
  WORD w;
  DWORD dw;
  LWORD lw;
  SINT si;
  INT i;
  DINT di;
  LINT li;
  escape(b, by, w, dw, lw, si, i, di, li);
  check_elementary(report, "local", b, by, w, dw, lw, si, i, di, li);
  REAL r;
  LREAL lr;
  escape(r, lr);
  expect(report, "local REAL LREAL are 0.0", r == 0.0f && lr == 0.0);
  TIME t;
  LTIME lt;
  DATE d;
  TOD tod;
  DT dt;
  escape(t, lt, d, tod, dt);
  expect(report, "local TIME LTIME DATE TOD DT are 0",
         t.count() == 0 && lt.count() == 0 && d.count() == 0 && tod.count() == 0 && dt.count() == 0);
  STRING<40> s;
  WSTRING<> ws;
  escape(s, ws);
  expect(report, "local STRING WSTRING are empty", s.empty() && ws.empty() && s.data()[40] == '\0');
  subrange<DINT, 100, 200> sr;
  escape(sr);
  expect(report, "local subrange DINT(100..200) is 100", sr.get().value() == 100);
  POINTER_TO<LREAL> p;
  REFERENCE_TO<INT> ref;
  itf<I_Named> ip;
  escape(p, ref, ip);
  expect(report, "local POINTER is 0, REFERENCE unbound, interface 0", p == nullptr && !is_valid_ref(ref) && !ip);
  ARRAY<E_Five, 1, 5> ae;
  escape(ae);
  for (const E_Five e : ae) check_enum(report, "local ARRAY OF E_Five starts at a", e, E_Five::a);
  ARRAY<E_Five, 1, 4> aePartial = array_init(E_Five::b);
  escape(aePartial);
  check_enum(report, "array_init: the given element", aePartial[1], E_Five::b);
  for (DINT k = 2; k <= 4; k = k + 1) check_enum(report, "array_init: the rest start at a", aePartial[k], E_Five::a);
  ARRAY<LREAL, -2, 2> alr;
  escape(alr);
  for (const LREAL x : alr) expect(report, "local ARRAY OF LREAL is 0.0", x == 0.0);
  ST_Pos st;  // default-initialised: its members' initial values
  escape(st);
  check_struct(report, st);
  U_Word u;
  escape(u);
  expect(report, "local UNION is 0", u.w.value() == 0 && u.ab[0].value() == 0 && u.ab[1].value() == 0);
  FB_All fb;  // a block declared as a local variable (default-initialised)
  escape(fb);
  check_block(report, fb);
  PRG_All prg;  // a PROGRAM declared as a local variable
  escape(prg);
  check_program(report, prg);
  GVL_All gvl;
  escape(gvl);
  expect(report, "global variable list INT BOOL", gvl.iMode.value() == 0 && !gvl.bAuto);
  check_enum(report, "global variable list enum at its initial value", gvl.eMode, E_Five::a);
  TON ton;
  escape(ton);
  expect(report, "local TON", !ton.Q && !ton.IN && ton.PT.count() == 0 && ton.ET.get().count() == 0);
  CTU ctu;
  escape(ctu);
  expect(report, "local CTU", !ctu.Q && ctu.CV.get().value() == 0 && ctu.PV.value() == 0);
  R_TRIG trig;
  escape(trig);
  expect(report, "local R_TRIG", !trig.Q && !trig.CLK);
  method_checker<R> m{&report};
  expect(report, "METHOD returns its return variable 0", m.M_All({}).value() == 0);
  expect(report, "METHOD with an argument", m.M_All({"iIn"_ = 0}).value() == 0);
}

/// Fills `bytes` bytes of the stack below the caller with 0xA5, so that what is constructed
/// next in that place would read as garbage if it were not initialised.
[[gnu::noinline]] inline void fill_stack_with_garbage() {
  constexpr std::size_t bytes = 64 * 1024;
  unsigned char garbage[bytes];
  for (std::size_t k = 0; k < bytes; ++k) garbage[k] = 0xA5;
  asm volatile("" : : "r"(garbage) : "memory");  // the stores are not dead
}

/// Constructs every type in every position on a stack filled with garbage, and reports each
/// value against ST's initial value: report(const char* what, bool ok).
template <class R>
void check_all(R& report) {
  fill_stack_with_garbage();
  check_locals(report);
}

}  // namespace initial_values
