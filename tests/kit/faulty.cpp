// A test program of which three cases fail (a fault in a task, and two failed checks), between
// cases that pass, one of them with ';' and an unmatched '[' in its name (which CMake's lists
// split and group) and characters that XML escapes: cmake/check_kit_junit.cmake runs it whole
// and through CTest, and reads the JUnit XML both write with xmllint. Not registered as tests of
// its own: it must fail.
#include <iecoop/testing.hpp>

using namespace iecoop;

namespace {

struct GVL : global_variables<GVL> {
  INT iDivisor = 1;
  INT iResult;
};
// PROGRAM DIV_PRG: GVL.iResult := 100 / GVL.iDivisor;
struct DIV_PRG : program<DIV_PRG> {
  void body() {
    GVL& gvl = GVL::instance();
    gvl.iResult = INT(100) / gvl.iDivisor;
  }
};
auto make_plc() { return application{task<DIV_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}, globals<GVL>{}}; }

struct DivTest : testing::plc<make_plc> {
  GVL& gvl = get<GVL>();
};

}  // namespace

TEST_SUITE("DIV_PRG") {
  TEST_CASE_FIXTURE(DivTest, "runs before") {
    step(3);
    CHECK(gvl.iResult == 100);
  }
  TEST_CASE_FIXTURE(DivTest, "divides by zero") {
    step();
    write(gvl.iDivisor, INT(0));
    advance("T#1s"_iec);  // the fault fails this case; the cycles stop
    CHECK(gvl.iResult == 0);
  }
  TEST_CASE_FIXTURE(DivTest, "runs after") {
    advance("T#1s"_iec);
    CHECK(gvl.iResult == 100);
    CHECK(now() == LTIME(TIME(1000)));
  }
  TEST_CASE("prints a WORD as ST does") {
    const WORD wMask = "WORD#16#00FF"_iec;
    CHECK(wMask == 254U);
  }
  TEST_CASE_FIXTURE(DivTest, "runs 3 cycles; then reads [GVL.iResult <> 0 & 'ok'") {
    step(3);
    CHECK(gvl.iResult == 100);
  }
  TEST_CASE("prints ARRAYs as ST does") {
    const ARRAY<INT, 1, 3> aiExpected{1, 2, 3};
    const ARRAY<INT, 1, 3> aiResult{1, 2, 4};
    CHECK(aiResult == aiExpected);
  }
}
