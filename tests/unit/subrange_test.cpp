// Subrange types: the range checked at compile time for constants and at run time
// (CheckRangeSigned/CheckRangeUnsigned) for everything else, on the whole value.
#include <sstream>
#include <type_traits>

#include <fmt/format.h>

#include <iecoop/fmt.hpp>

#include "iecoop_test.hpp"

using namespace iecoop;
using iecoop_test::fault_recorder;
using iecoop_test::opaque;

namespace {

using T_Percent = subrange<INT, 0, 100>;  // TYPE T_Percent : INT(0..100); END_TYPE

struct FB_Dimmer : function_block<FB_Dimmer> {
  T_Percent iLevel;  // VAR_INPUT iLevel : T_Percent; END_VAR
  INT iOut;
  DINT diWide;
  var<T_Percent> iRaw;  // VAR iRaw : T_Percent; END_VAR
  using VAR_INPUT = pins<&FB_Dimmer::iLevel>;
  using VAR_OUTPUT = pins<&FB_Dimmer::iOut>;
  void body() {
    iOut = iLevel * 10;
    iRaw = iLevel + 5;
    diWide = iRaw * 655;  // a var<> of a subrange in arithmetic with a constant
  }
};

}  // namespace

TEST_SUITE("subrange types") {
  TEST_CASE("a subrange is as large as its base type and reads as it") {
    static_assert(sizeof(T_Percent) == sizeof(INT));
    static_assert(std::is_trivially_copyable_v<T_Percent>);
    T_Percent iPercent = 40;
    const INT i = iPercent + 1;
    CHECK(i == 41);
    CHECK(iPercent == 40);
    CHECK(iPercent < 50);
    CHECK(T_Percent::lower == 0);
    CHECK(T_Percent::upper == 100);
  }

  TEST_CASE("it starts at 0, or at its lower limit where 0 is outside the range") {
    const T_Percent a;
    const subrange<INT, 5, 10> b;
    const subrange<INT, -10, -5> c;
    CHECK(a == 0);
    CHECK(b == 5);
    CHECK(c == -10);
  }

  TEST_CASE("a value outside the range is a fault, then the nearest limit is stored") {
    fault_recorder faults;
    T_Percent iPercent;
    INT iRaw = opaque(INT(15));
    iPercent = iRaw * 10;  // 150: the upper limit
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::out_of_range);
    CHECK(iPercent == 100);
    iPercent = iRaw - 16;  // -1: the lower limit
    CHECK(iPercent == 0);
    CHECK(faults.count == 2);
    iPercent = iRaw;  // in range: no fault
    CHECK(iPercent == 15);
    CHECK(faults.count == 2);
  }

  TEST_CASE("the check sees the whole value, before narrowing to the base type") {
    fault_recorder faults;
    subrange<INT, -4095, 4095> i;
    const INT y = opaque(INT(1000));
    i = y * 10;  // 10000, not 10000 cut to 16 bits
    CHECK(i == 4095);
    i = y * 70;  // 70000 would wrap to 4464 in an INT; the whole value is above 4095
    CHECK(i == 4095);
    CHECK(faults.count == 2);
  }

  TEST_CASE("compound assignments are checked as x := x op v") {
    fault_recorder faults;
    T_Percent iPercent = 95;
    iPercent += 3;
    CHECK(iPercent == 98);
    iPercent += 3;
    CHECK(iPercent == 100);
    CHECK(faults.count == 1);
  }

  TEST_CASE("unsigned subranges: CheckRangeUnsigned") {
    fault_recorder faults;
    subrange<UINT, 10, 10000> ui = 10;
    ui = opaque(UINT(20000));
    CHECK(ui == 10000);
    ui = opaque(UINT(3));
    CHECK(ui == 10);
    subrange<BYTE, 1, 7> byMask;
    CHECK(byMask == 1);
    CHECK(faults.count == 2);
  }

  TEST_CASE("a call's C++ integer argument is checked when the call runs") {
    fault_recorder faults;
    FB_Dimmer fbDimmer;
    fbDimmer("iLevel"_ = 30);
    CHECK(fbDimmer.iOut == 300);
    CHECK(fbDimmer.iRaw == 35);
    CHECK(fbDimmer.diWide == 35 * 655);
    const DINT diLevel = fbDimmer.iLevel;  // an INT subrange widens as an INT does
    CHECK(diLevel == 30);
    int level = opaque(500);
    fbDimmer("iLevel"_ = level);
    CHECK(fbDimmer.iOut == 1000);
    CHECK(faults.count == 2);  // the input, then iRaw := 105
  }

  TEST_CASE("a subrange of another subrange type is checked as its value") {
    fault_recorder faults;
    subrange<INT, 0, 1000> iWide = 700;
    T_Percent iNarrow;
    iNarrow = iWide;
    CHECK(iNarrow == 100);
    CHECK(faults.count == 1);
  }
}

TEST_CASE("a subrange prints as its value, with fmt and iostreams") {
  const subrange<INT, -10, 10> i = -7;
  std::ostringstream os;
  os << i;
  CHECK(os.str() == "-7");
  CHECK(fmt::format("{:>4}", i) == "  -7");
}
