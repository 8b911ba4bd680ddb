// One feature: RETAIN and PERSISTENT variables. A warm reset keeps RETAIN values, a cold reset
// keeps only PERSISTENT ones, a reset origin keeps none; a controller restart keeps both
// through the storage the application saves to at stop().
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  retain<UDINT> udiParts;           // VAR RETAIN udiParts : UDINT; END_VAR
  persistent<UDINT> udiLifetime;    // VAR PERSISTENT udiLifetime : UDINT; END_VAR
  UDINT udiSinceStart;              // VAR udiSinceStart : UDINT; END_VAR

  void body() {
    udiParts = udiParts + 1;              // udiParts := udiParts + 1;
    udiLifetime = udiLifetime + 1;        // udiLifetime := udiLifetime + 1;
    udiSinceStart = udiSinceStart + 1;    // udiSinceStart := udiSinceStart + 1;
  }
};

memory_storage<256> storage;  // the controller's retain memory, surviving a restart

void run_and_show(application<task<PLC_PRG>>& plc, const char* after) {
  plc.start();
  plc.run_cycles(10);  // ten parts
  const PLC_PRG& prg = plc.get<PLC_PRG>();
  fmt::print("{:<22} RETAIN {:>3}   PERSISTENT {:>3}   VAR {:>3}\n", after, prg.udiParts, prg.udiLifetime,
             prg.udiSinceStart);
}

int main() {
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}};
  plc.use_storage(storage);

  run_and_show(plc, "download, 10 cycles");
  plc.reset(reset_kind::warm);
  run_and_show(plc, "reset warm");
  plc.reset(reset_kind::cold);
  run_and_show(plc, "reset cold");
  plc.stop();  // saves RETAIN and PERSISTENT to the storage
  run_and_show(plc, "controller restart");
  plc.reset(reset_kind::origin);
  run_and_show(plc, "reset origin");
  plc.stop();
}
