// EXPECT: a block that EXTENDS another states its own body
// CODESYS runs a derived block's own implementation, not its base's (only SUPER^() does):
// a derived block that writes no body would silently run the base's in C++, so it does not
// compile. Its twin states an empty implementation, and the base's body does not run.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct fbA : function_block<fbA> {
  INT iCalls;
  virtual void body() { iCalls = iCalls + 1; }
};
struct fbB : extends<fbB, fbA> {
  BOOL bFlag;
#ifndef IECOOP_COMPILE_FAIL
  void body() override {}  // an empty implementation
#endif
};
int main() {
  fbB b;
  fbA& a = b;
  a();
  return b.iCalls == 0 ? 0 : 1;
}
