// EXPECT: iecoop: attributes<...> lists no_explicit_call and no_assign
// EXPECT: attributes_unknown\.cpp:1[0-9]:
// EXPECT: hide
// attributes<> holds the attribute pragmas iecoop checks; the others become nothing in C++
// (the porting guide says what each is), and a type that is no attribute is refused.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct hide {};  // {attribute 'hide'} is about the IDE, not the block
#ifdef IECOOP_COMPILE_FAIL
struct FB : function_block<FB, attributes<no_assign, hide>> {
#else
struct FB : function_block<FB, attributes<no_assign>> {
#endif
  INT iValue;
  void body() { iValue = iValue + 1; }
};
int main() {
  FB fb;
  fb();
  return fb.iValue == 1 ? 0 : 1;
}
