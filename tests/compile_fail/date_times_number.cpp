// EXPECT: is a point in time, not a number: ST does not multiply or divide it
// A TOD is no duration: scale a TIME instead.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  const TOD todStart = "TOD#06:00:00"_iec;
#ifdef IECOOP_COMPILE_FAIL
  const TOD todHalf = todStart / 2;
  return todHalf.count() > 0 ? 0 : 1;
#else
  const TIME tHalf = (todStart - "TOD#00:00:00"_iec) / 2;
  return tHalf.count() > 0 ? 0 : 1;
#endif
}
