// EXPECT: private
// A property whose Set accessor is PRIVATE (owner_only_set) is assigned only inside its block.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Counter : function_block<FB_Counter> {
  DINT dCount;
  DINT Count_Get() const { return dCount; }
  void Count_Set(DINT value) { dCount = value; }
  [[no_unique_address]] property<DINT, &FB_Counter::Count_Get, &FB_Counter::Count_Set, owner_only_set> Count{this};
  void body() { Count = Count + 1; }  // inside the block: fine
};
int main() {
  FB_Counter counter;
  counter();
#ifdef IECOOP_COMPILE_FAIL
  counter.Count = 0;  // outside the block: the Set accessor is PRIVATE
#endif
  return counter.Count == 1 ? 0 : 1;  // the Get accessor is PUBLIC
}
