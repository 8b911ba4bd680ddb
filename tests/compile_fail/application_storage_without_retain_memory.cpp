// EXPECT: iecoop: an application without retain memory .retain_capacity<0>. saves nothing to a storage
#include <iecoop/runtime/application.hpp>
#include <iecoop/runtime/retain_storage.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct PLC_PRG : program<PLC_PRG> {
  INT n;
  void body() { n = n + 1; }
};
int main() {
  memory_storage<64> storage;
#ifdef IECOOP_COMPILE_FAIL
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, retain_capacity<0>{}};
#else
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, retain_capacity<16>{}};
#endif
  plc.use_storage(storage);
  plc.start();
  plc.stop();
  return plc.save_retained() ? 1 : 0;  // stopped: nothing to save
}
