// Firmware example: a function block with a PROPERTY and blocks with METHODs, from the seeds
// the host's tests check (examples/oop/prop_ia_plc_prg.hpp and method_doit.hpp).
//
// PLC_PRG calls FB_A 1,200 times; FB_A's property prop_iA, a Get and a Set accessor around its
// counter, resets it each time it passes 500. Then FB_DoIt's method DoIt is called with named
// arguments in any order, positionally and with inputs left out, and its STRING(12) input
// truncates a longer text.
#include <iecoop/iecoop.hpp>

#include "console.hpp"
#include "exit_status.hpp"
#include "fault_handler.hpp"
#include "method_doit.hpp"
#include "prop_ia_plc_prg.hpp"

namespace {

using namespace iecoop;

seed_prop_ia::PLC_PRG plc_prg;
seed_method_doit::FB_DoIt fbInstance;

bool property_cycles() {
  int wraps = 0;
  for (int cycle = 1; cycle <= 1200; ++cycle) {
    plc_prg();
    if (plc_prg.iVar == 0) ++wraps;
  }
  const INT iVar = plc_prg.iVar;
  firmware::print_line("PLC_PRG: 1200 cycles, prop_iA reset ", wraps, " times, iVar = ", iVar);
  return wraps == 2 && iVar == 198;  // reset at cycles 501 and 1002; 1200 - 2 * 501 left
}

bool method_calls() {
  // bFinishedMethod := fbInstance.DoIt(sInput_3 := 'Hello World ', iInput_2 := 16#FFFF, iInput_1 := 16);
  const BOOL named = fbInstance.DoIt({"sInput_3"_ = "Hello World ", "iInput_2"_ = 0xFFFF, "iInput_1"_ = 16});
  // bFinishedMethod := fbInstance.DoIt(16, 16#0010, 'Hello World ');
  const BOOL positional = fbInstance.DoIt({16, 0x0010, "Hello World "});
  // fbInstance.DoItWithDefault(iInput_1 := 16#10): iInput_2 keeps its initial value 16#10
  const BOOL with_default = fbInstance.DoItWithDefault({"iInput_1"_ = 0x10});
  firmware::print_line("FB_DoIt.DoIt: named ", named, ", positional ", positional, ", default input ", with_default);
  fbInstance.DoIt({"sInput_3"_ = "Hello World, again", "iInput_1"_ = 1});
  const STRING<12> text = fbInstance.sLastText;
  firmware::print_line("FB_DoIt.sLastText = '", text.view(), "' (STRING(12))");
  return !named && positional && with_default && text == "Hello World,";
}

}  // namespace

int main() {
  firmware::install_fault_handler();
  const bool properties = property_cycles();
  const bool methods = method_calls();
  const bool ok = properties && methods;
  firmware::print_line("RESULT property_and_method ", ok ? "PASS" : "FAIL");
  return ok ? firmware::exit_status::passed : firmware::exit_status::failed;
}
