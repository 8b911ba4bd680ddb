// EXPECT: iecoop: io_chain: two drivers write the same input bits
// EXPECT: local_card
// EXPECT: remote_card
// EXPECT: spelled<'%', 'I', 'B', '2', '.', '.', '%', 'I', 'B', '3'>
// EXPECT-ERRORS: 1
// EXPECT: io_chain_inputs_overlap\.cpp:33:
// Two drivers of a chain whose input footprints are known while compiling must not write the
// same input bits: the remote card's %IW1 is the local card's %IB2 and %IB3.
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
struct remote_card {
#ifdef IECOOP_COMPILE_FAIL
  static constexpr std::array<image_window, 1> input_footprint() { return {window_of<"%IW1", 2>}; }
#else
  static constexpr std::array<image_window, 1> input_footprint() { return {window_of<"%IW2", 2>}; }
#endif
  void read_inputs(std::span<std::byte>) {}
  void write_outputs(std::span<const std::byte>) {}
};
int main() {
  local_card card;
  remote_card remote;
  io_chain io{card, remote};
  return io.configuration_error() == nullptr ? 0 : 1;
}
