// EXPECT: iecoop: io_chain: the driver 'UndeclaredDriver' declares no input footprint
// EXPECT: io_chain_footprint_undeclared<2, old_card, 1, local_card>
// EXPECT-ERRORS: 1
// EXPECT: io_chain_footprint_undeclared\.cpp:29:
// A driver that declares no input footprint may write any input byte: it shares no chain with
// another driver that writes inputs. Declaring what it writes lets it in.
#include <iecoop/io/driver.hpp>

#include <array>
#include <cstddef>
#include <span>

using namespace iecoop;
struct local_card {
  static constexpr std::array<image_window, 1> input_footprint() { return {window_of<"%IB0", 4>}; }
  void read_inputs(std::span<std::byte>) {}
  void write_outputs(std::span<const std::byte>) {}
};
struct old_card {
#ifndef IECOOP_COMPILE_FAIL
  static constexpr std::array<image_window, 1> input_footprint() { return {window_of<"%IB4", 2>}; }
#endif
  void read_inputs(std::span<std::byte> in) { in[4] = std::byte{1}; }
  void write_outputs(std::span<const std::byte>) {}
};
int main() {
  local_card card;
  old_card old;
  io_chain io{card, old};
  return io.configuration_error() == nullptr ? 0 : 1;
}
