// EXPECT: integer constant out of range for this IEC type
// An integer constant must fit the variable it initialises, as in ST. (Clang 14 checks this
// only for local variables; in a namespace-scope or default member initializer it reports
// an undefined reference to iecoop::detail::compile_error at link time instead.)
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  INT counter = 70000;
#else
  DINT counter = 70000;
#endif
  return counter == 70000 ? 0 : 1;
}
