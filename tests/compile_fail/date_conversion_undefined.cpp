// EXPECT: no IEC conversion between the types spelled in `From` and `To`
// A duration is no point in time: TO_TOD(T#1h) has no meaning; add the TIME to a TOD.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  const TIME tOffset = "T#1h"_iec;
#ifdef IECOOP_COMPILE_FAIL
  const TOD todAt = TO_TOD(tOffset);
#else
  const TOD todAt = "TOD#00:00:00"_iec + tOffset;
#endif
  return todAt.count() > 0 ? 0 : 1;
}
