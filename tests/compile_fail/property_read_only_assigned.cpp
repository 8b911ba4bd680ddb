// EXPECT: iecoop: the property has no Set accessor \(it is read-only\)
// A property without a Set accessor is read-only: assigning it does not compile.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Tank : function_block<FB_Tank> {
  INT iLevel;
  INT Level_Get() const { return iLevel; }
#ifndef IECOOP_COMPILE_FAIL
  void Level_Set(INT value) { iLevel = value; }
  [[no_unique_address]] property<INT, &FB_Tank::Level_Get, &FB_Tank::Level_Set> Level{this};
#else
  [[no_unique_address]] property<INT, &FB_Tank::Level_Get> Level{this};  // PROPERTY Level : INT (Get only)
#endif
  void body() {}
};
int main() {
  FB_Tank tank;
  tank.Level = 5;  // tank.Level := 5;
  return tank.Level == 5 ? 0 : 1;
}
