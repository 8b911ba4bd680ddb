// EXPECT: iecoop: the application owns no instance of this type
#include <iecoop/runtime/application.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct PLC_PRG : program<PLC_PRG> {
  INT n;
  void body() { n = n + 1; }
};
struct OTHER_PRG : program<OTHER_PRG> {
  INT n;
  void body() {}
};
int main() {
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}};
  plc.start();
#ifdef IECOOP_COMPILE_FAIL
  return plc.get<OTHER_PRG>().n == 0 ? 0 : 1;
#else
  return plc.get<PLC_PRG>().n == 0 ? 0 : 1;
#endif
}
