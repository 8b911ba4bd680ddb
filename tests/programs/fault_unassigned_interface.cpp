// A call through an unassigned interface variable must stop the program, whatever the
// handler: with the default handler (argument "default") it prints the fault and aborts;
// with a handler that returns (argument "returning") the call still cannot be made, so the
// program aborts after the handler ran. CTest expects the message and a failing exit.
#include <iecoop/pou/interface.hpp>
#include <iecoop/types/elementary.hpp>

#include <cstdio>
#include <cstring>

namespace {
struct I_Motor : iecoop::interface_base<I_Motor> {
  virtual void Start() = 0;
};
void note_and_return(const iecoop::fault_info& fault) {
  std::printf("handler returned after: %s\n", fault.message);
  std::fflush(stdout);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "returning") == 0) iecoop::set_fault_handler(&note_and_return);
  iecoop::itf<I_Motor> motor;  // 0: never assigned
  motor->Start();
  std::puts("not reached: the call through an unassigned interface went on");
  return 0;
}
