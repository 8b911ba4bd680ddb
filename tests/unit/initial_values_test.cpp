// No variable is ever indeterminate (issue 35): every IEC type in every position starts at ST's
// initial value, also where C++ leaves a default-initialised value undefined (a block or STRUCT
// declared as a local variable on a stack filled with garbage); an enumeration at its first
// component (or its type's initial value), not at 0. The same cases run under valgrind's
// memcheck in tests/programs/initial_values.cpp.
#include <string>
#include <type_traits>

#include "iecoop_test.hpp"
#include "initial_values_cases.hpp"

using namespace iecoop;

namespace initial_values_test {

using namespace initial_values;

struct doctest_report {
  int checked = 0;
  void operator()(const char* what, bool ok) {
    ++checked;
    CHECK_MESSAGE(ok, what);
  }
};

// ST: TYPE E_Late : (First := 20, Second := 10, Third := 0); END_TYPE — the first component,
// not the smallest value nor the one that is 0.
enum class E_Late : SINT::rep { First = 20, Second = 10, Third = 0 };
// An enumeration iecoop knows nothing of: a variable of it needs its initial value written.
enum class E_Unknown : INT::rep { P = 1, Q };

}  // namespace initial_values_test

template <>
inline constexpr auto iecoop::enum_components<initial_values_test::E_Late> =
    iecoop::components<initial_values_test::E_Late::First, initial_values_test::E_Late::Second,
                       initial_values_test::E_Late::Third>{};

namespace initial_values_test {

TEST_CASE("every IEC type in every position starts at ST's initial value on a stack of garbage") {
  doctest_report report;
  check_all(report);
  CHECK(report.checked > 150);
}

TEST_CASE("an enumeration starts at its first component, whatever its value") {
  static_assert(detail::enum_start<E_Five>() == E_Five::a);
  static_assert(detail::enum_start<E_Late>() == E_Late::First);  // 20, though 0 is a component (Third)
  static_assert(detail::enum_start<E_Init>() == E_Init::Run);    // TYPE E_Init : (...) := Run
  static_assert(detail::enum_start<E_Zero>() == Zero_A);
  static_assert(!detail::knows_enum_start<E_Unknown>);
  constexpr ARRAY<E_Late, 1, 3> constant;  // also in a constant expression
  static_assert(constant[1] == E_Late::First && constant[3] == E_Late::First);
  static_assert(sizeof(ARRAY<E_Late, 1, 3>) == 3 && sizeof(ARRAY<E_Five, 1, 10>) == 20);
  static_assert(std::is_trivially_copyable_v<ARRAY<E_Late, 1, 3>>);

  ARRAY<E_Late, 1, 3> a;
  CHECK(a[2] == E_Late::First);
  a[2] = E_Late::Third;
  CHECK(a[2] == E_Late::Third);
  const ARRAY<E_Late, 1, 3> braced{E_Late::Second, E_Late::Third, E_Late::Second};
  CHECK(braced[1] == E_Late::Second);
  CHECK(braced[2] == E_Late::Third);
  // An enumeration variable with an initial value, and one of an enumeration iecoop knows nothing of.
  E_Unknown u = E_Unknown::P;
  CHECK(u == E_Unknown::P);
}

// METHOD M : INT  VAR_INPUT e : E_Late; n : INT; END_VAR  VAR t : E_Late; END_VAR
struct M_vars {
  E_Late e;
  INT n;
  E_Late eGiven = E_Late::Third;
  temp<E_Late> t;
};

TEST_CASE("a METHOD's enumeration inputs start at their first component at every call") {
  struct FB_M : function_block<FB_M> {
    INT M(args<M_vars> in) {
      const bool first = in.e == E_Late::First && in.eGiven == E_Late::Third && in.t.get() == E_Late::First;
      in.e = E_Late::Second;  // temporary: the next call starts again
      in.t = E_Late::Third;
      return first ? in.n : INT(-1);
    }
    void body() {}
  } fb;
  CHECK(fb.M({}) == 0);
  CHECK(fb.M({"n"_ = 4}) == 4);
  CHECK(fb.M({"e"_ = E_Late::First, "n"_ = 7}) == 7);
  CHECK(fb.M({E_Late::Third, 1}) == -1);  // a value passed is kept
}

TEST_CASE("initial values are no work in the cycle: a block's call does not re-initialise") {
  FB_All fb;
  INT iBound;
  fb.refIo.bind(iBound);
  fb.eFiveVar.ref() = E_Five::b;  // as the block's own code would
  fb.aeStrict[2] = E_Strict::On;
  fb();
  CHECK(fb.eFiveVar == E_Five::b);
  CHECK(fb.aeStrict[2] == E_Strict::On);
  CHECK(fb.aeStrict[1] == E_Strict::Off);
}

}  // namespace initial_values_test
