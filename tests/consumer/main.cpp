// A consumer of iecoop: compiles against the package and checks a few values at run time.
#include <iecoop/iecoop.hpp>

int main() {
  using namespace iecoop;
  INT counter = 32767;
  counter = counter + 1;  // wraps as on a PLC
  const TIME pt = "T#1s500ms"_iec;
  const STRING<8> name = "conveyor belt";  // truncated to 8 characters
  const bool ok =
      counter == -32768 && TIME_TO_DINT(pt) == 1500 && name == "conveyor" && TIME_TO_STRING(pt) == "T#1s500ms";
  return ok ? 0 : 1;
}
