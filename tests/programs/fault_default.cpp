// Division by zero with the default fault handler: the program must print the fault and
// abort (CTest expects the message and a failing exit).
#include <iecoop/types/elementary.hpp>

#include <cstdio>

int main(int argc, char**) {
  using namespace iecoop;
  const DINT zero = argc - 1;  // 0 at run time, unknown to the compiler
  const DINT result = DINT(7) / zero;
  std::puts("not reached: the default handler returned");
  return result == 0 ? 0 : 2;
}
