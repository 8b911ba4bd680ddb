// METHOD and FUNCTION variables (args<Vars>): positional, named in any order, omitted
// inputs, extra outputs, in-outs, the first output as return value, run-time range checks
// of C++ integers, and FUNCTION objects.
#include "iecoop_test.hpp"

#include <type_traits>

using namespace iecoop;
using iecoop_test::fault_recorder;

namespace {

struct Scale_vars {
  INT iIn;                      // VAR_INPUT iIn : INT;
  REAL rFactor = 2.0f;          //           rFactor : REAL := 2.0;
  output<INT> iOut;             // VAR_OUTPUT iOut : INT;
  output<BOOL> bClamped{TRUE};  //         bClamped : BOOL := TRUE;
};

struct Swap_vars {
  in_out<INT> a;  // VAR_IN_OUT a, b : INT; END_VAR
  in_out<INT> b;
};

struct FB_Tools : function_block<FB_Tools> {
  void body() {}

  // METHOD Scale      (no return type: CODESYS returns the first output, iOut)
  first_output_t<Scale_vars> Scale(args<Scale_vars> in) {
    in.iOut = REAL_TO_INT(INT_TO_REAL(in.iIn) * in.rFactor);
    in.bClamped = in.iOut > 100;
    return in.first_output();
  }
  // METHOD Swap
  void Swap(args<Swap_vars> in) {
    const INT t = in.a;
    in.a = in.b.get();
    in.b = t;
  }
  // METHOD Seen : BOOL  — reports whether bClamped started at its initial value
  BOOL FreshOutputs(args<Scale_vars> in) { return in.bClamped == TRUE && in.iOut == 0; }
};

// FUNCTION F_Limit : INT  VAR_INPUT iIn, iMin, iMax : INT; END_VAR  VAR_OUTPUT bLimited : BOOL; END_VAR
struct F_Limit_vars {
  INT iIn;
  INT iMin;
  INT iMax = 100;
  output<BOOL> bLimited;
};
inline constexpr iecoop::function F_Limit = [](args<F_Limit_vars> in) -> INT {
  if (in.iIn < in.iMin) {
    in.bLimited = TRUE;
    return in.iMin;
  }
  if (in.iIn > in.iMax) {
    in.bLimited = TRUE;
    return in.iMax;
  }
  return in.iIn;
};

}  // namespace

static_assert(std::is_same_v<first_output_t<Scale_vars>, INT>);
static_assert(first_output_index<Scale_vars> == 2);
static_assert(first_output_index<Swap_vars> == 2);  // none: field_count

TEST_SUITE("methods and functions") {
  TEST_CASE("positional arguments fill the inputs in declaration order, the rest keep their initial values") {
    FB_Tools tools;
    CHECK(tools.Scale(21) == 42);  // rFactor := 2.0 by default
    CHECK(tools.Scale({21, 3.0f}) == 63);
  }

  TEST_CASE("named arguments in any order, mixed after positional ones") {
    FB_Tools tools;
    CHECK(tools.Scale({"rFactor"_ = 0.5f, "iIn"_ = 10}) == 5);
    CHECK(tools.Scale({10, "rFactor"_ = 10.0f}) == 100);
  }

  TEST_CASE("extra outputs are assigned at the call with =>") {
    FB_Tools tools;
    INT out = 0;
    BOOL clamped = FALSE;
    const INT result = tools.Scale({"iIn"_ = 60, "iOut"_ >> out, "bClamped"_ >> clamped});
    CHECK(result == 120);
    CHECK(out == 120);
    CHECK(clamped == TRUE);
    tools.Scale({1, "bClamped"_ >> clamped});
    CHECK(clamped == FALSE);
  }

  TEST_CASE("outputs start every call at their initial value") {
    FB_Tools tools;
    CHECK(tools.FreshOutputs({}) == TRUE);
    tools.Scale({500});
    CHECK(tools.FreshOutputs({}) == TRUE);
  }

  TEST_CASE("when outputs arrive: a FUNCTION's before it returns, a method's at the end of the statement") {
    BOOL limited = FALSE;
    CHECK((F_Limit("iIn"_ = 150, "bLimited"_ >> limited) == 100 && limited == TRUE));
    FB_Tools tools;
    BOOL clamped = FALSE;
    const INT scaled = tools.Scale({"iIn"_ = 60, "bClamped"_ >> clamped});
    CHECK(scaled == 120);
    CHECK(clamped == TRUE);  // the statement above has ended
  }

  TEST_CASE("in-outs bind to the caller's variables, by name or by position") {
    FB_Tools tools;
    INT x = 1;
    INT y = 2;
    tools.Swap({x, y});
    CHECK(x == 2);
    CHECK(y == 1);
    tools.Swap({"b"_ = x, "a"_ = y});
    CHECK(x == 1);
    CHECK(y == 2);
  }

  TEST_CASE("a C++ integer argument is range-checked at run time") {
    fault_recorder faults;
    FB_Tools tools;
    CHECK(tools.Scale({100}) == 200);
    CHECK(faults.count == 0);
    const int too_big = iecoop_test::opaque(DINT(70000)).value();
    tools.Scale({"iIn"_ = too_big});
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    const SINT small = -5;  // IEC widening is fine
    CHECK(tools.Scale({small}) == -10);
    CHECK(faults.count == 1);
  }

  TEST_CASE("a FUNCTION: one return value and extra outputs") {
    BOOL limited = FALSE;
    CHECK(F_Limit(50, 0, 100) == 50);
    CHECK(F_Limit("iIn"_ = 150, "iMin"_ = 0, "bLimited"_ >> limited) == 100);  // iMax := 100 by default
    CHECK(limited == TRUE);
    CHECK(F_Limit("iMin"_ = 10, "iIn"_ = 5, "iMax"_ = 20, "bLimited"_ >> limited) == 10);
    CHECK(limited == TRUE);
    CHECK(F_Limit({"iIn"_ = 15, "iMin"_ = 10, "bLimited"_ >> limited}) == 15);
    CHECK(limited == FALSE);
    CHECK(F_Limit({"iIn"_ = 500, "bLimited"_ >> limited}) == 100);  // the braced form delivers outputs too
    CHECK(limited == TRUE);
    static_assert(F_Limit(5, 10, 20) == 10);  // a FUNCTION can be constexpr
  }
}

TEST_SUITE("reflection") {
  struct Record {
    INT iId;
    STRING<12> sName;
    TIME tAge;
    output<BOOL> bDone;
  };

  TEST_CASE("fields of an aggregate, with their names") {
    static_assert(field_count<Record> == 4);
    static_assert(field_name<Record, 0> == "iId" && field_name<Record, 3> == "bDone");
    static_assert(std::is_same_v<field_type<Record, 1>, STRING<12>>);
    static_assert(field_index<Record>("tAge") == 2 && field_index<Record>("nope") == 4);
    static_assert(member_name<&Record::sName> == "sName");
    Record r{};
    get_field<0>(r) = 7;
    CHECK(r.iId == 7);
    int visited = 0;
    apply_fields(r, [&visited](auto&... fields) { visited = static_cast<int>(sizeof...(fields)); });
    CHECK(visited == 4);
  }
}
