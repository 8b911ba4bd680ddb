// EXPECT: no VAR_INPUT or VAR_IN_OUT of the name spelled in
// The default (CODESYS) CTU calls its reset input RESET; IEC's name R belongs to iec::CTU.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  CTU counter;
  iec::CTU iec_counter;
#ifdef IECOOP_COMPILE_FAIL
  counter("CU"_ = TRUE, "R"_ = FALSE, "PV"_ = 3);
#else
  counter("CU"_ = TRUE, "RESET"_ = FALSE, "PV"_ = 3);
#endif
  iec_counter("CU"_ = TRUE, "R"_ = FALSE, "PV"_ = 3);
  return counter.CV == 1 && iec_counter.CV == 1 ? 0 : 1;
}
