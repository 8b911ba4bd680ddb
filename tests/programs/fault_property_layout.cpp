// A PROPERTY declared without [[no_unique_address]] sits beside its block's variables, not at
// the block's address, and could not reach its block: constructing the block is a fault
// (property_layout), whatever the handler. With the default handler (argument "default") the
// program prints the fault and aborts; with a handler that returns (argument "returning") it
// aborts after the handler ran. No accessor is ever called on the wrong bytes. CTest expects
// the message and a failing exit.
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/property.hpp>
#include <iecoop/types/elementary.hpp>

#include <cstdio>
#include <cstring>

namespace {
struct FB_Slip : iecoop::function_block<FB_Slip> {
  iecoop::INT iA;
  iecoop::INT prop_iA_Get() { return iA; }
  void prop_iA_Set(iecoop::INT value) { iA = value; }
  // The slip: no [[no_unique_address]]. The property is a byte after iA.
  iecoop::property<iecoop::INT, &FB_Slip::prop_iA_Get, &FB_Slip::prop_iA_Set> prop_iA{this};
  void body() {}
};
void note_and_return(const iecoop::fault_info& fault) {
  std::printf("handler returned after: %s\n", fault.message);
  std::fflush(stdout);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "returning") == 0) iecoop::set_fault_handler(&note_and_return);
  FB_Slip fb;
  fb.prop_iA = 5;
  std::printf("not reached: the misplaced property was used (%d)\n", static_cast<int>(fb.iA.value()));
  return 0;
}
