// EXPECT: iecoop: a duration is a TIME, an LTIME or a std::chrono duration of whole nanoseconds, not a bare number
// EXPECT: application_run_for_number\.cpp:17:
// EXPECT-ERRORS: 1
// An application's simulated time runs for a duration: run_for(60000) is no minute (LTIME
// counts nanoseconds: 60 µs, not even one cycle), T#1m is.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct PLC_PRG : program<PLC_PRG> {
  DINT diCycles;
  void body() { diCycles += 1; }
};
inline auto make_plc() { return application{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 0}}; }
int main() {
  auto plc = make_plc();
  plc.start();
#ifdef IECOOP_COMPILE_FAIL
  plc.run_for(60000);
#else
  plc.run_for("T#1m"_iec);
#endif
  return plc.get<PLC_PRG>().diCycles == 6000 ? 0 : 1;
}
