// Firmware example: the seed's INTERFACE I_Math (examples/oop/i_math_interface.hpp, the same
// POUs the host's tests check) on a microcontroller. PROGRAM MAIN points its interface variable
// at FB_MathMen, then at FB_MethErase, and calls M_Add, M_Mul and the property P_Result through
// it: virtual calls through an INTERFACE, with no heap and no RTTI.
#include <iecoop/iecoop.hpp>

#include "console.hpp"
#include "exit_status.hpp"
#include "fault_handler.hpp"
#include "i_math_interface.hpp"

namespace {

using namespace iecoop;

// The program instance has static storage, as on a PLC (and so the size table counts it).
seed_i_math::MAIN plc_main;

bool run_with(BOOL use_mem_instance, const char* block, REAL expected_add, REAL expected_result) {
  plc_main.bUseMemInstance = use_mem_instance;
  plc_main();
  const REAL add = plc_main.AddResult;
  const REAL result = plc_main.rResultInterface;
  firmware::print_line("I_Math -> ", block, ": AddResult = ", add, ", P_Result = ", result);
  return add == expected_add && result == expected_result;
}

}  // namespace

int main() {
  firmware::install_fault_handler();
  bool ok = run_with(TRUE, "FB_MathMen", 5.0F, 15.0F);     // (2 + 3) * 3, kept
  ok = run_with(FALSE, "FB_MethErase", 5.0F, 0.0F) && ok;  // 2 + 3, then erased: 0 * 3
  ok = run_with(TRUE, "FB_MathMen", 5.0F, 15.0F) && ok;    // P_Result := 2 starts it afresh
  firmware::print_line("RESULT i_math_interface ", ok ? "PASS" : "FAIL");
  return ok ? firmware::exit_status::passed : firmware::exit_status::failed;
}
