// Firmware example: what happens on a fault. A PROGRAM calls a method through an INTERFACE
// variable that was never assigned; iecoop reports fault_kind::unassigned_interface to the
// fault handler, which this firmware installed (embedded/fault_handler.hpp): it prints the
// fault and ends with exit_status::iecoop_fault (2), which the test expects. iecoop's default
// handler, which would print on stderr and abort, is not used.
#include <iecoop/iecoop.hpp>

#include "console.hpp"
#include "exit_status.hpp"
#include "fault_handler.hpp"
#include "i_math_interface.hpp"

namespace {

using namespace iecoop;

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  // VAR
  itf<seed_i_math::I_Math> ipMath;  // ipMath : I_Math;   (never assigned: 0)
  REAL rResult;                     // rResult : REAL;
  // END_VAR

  void body() {
    rResult = ipMath->M_Add(1.0F);  // rResult := ipMath.M_Add(1);   a fault: ipMath = 0
  }
};

PLC_PRG plc_prg;

}  // namespace

int main() {
  firmware::install_fault_handler();
  firmware::print_line("calling M_Add through an unassigned I_Math");
  plc_prg();
  firmware::print_line("RESULT fault FAIL: the call returned");
  return firmware::exit_status::failed;
}
