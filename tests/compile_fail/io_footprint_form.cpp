// EXPECT: iecoop: a driver's input_footprint\(\) is `static constexpr std::array<image_window, N> input_footprint\(\)`
// EXPECT-ERRORS: 1
// EXPECT: io_footprint_form\.cpp:27:
// A driver declares its input footprint as a static constexpr std::array (known while
// compiling) or as a std::span of windows it keeps (known at run time); an array returned by
// value from a member function would be gone before io_chain reads it.
#include <iecoop/io/driver.hpp>

#include <array>
#include <cstddef>
#include <span>

using namespace iecoop;
struct card {
#ifdef IECOOP_COMPILE_FAIL
  std::array<image_window, 1> input_footprint() const { return inputs; }
#else
  std::span<const image_window> input_footprint() const { return inputs; }
#endif
  void read_inputs(std::span<std::byte>) {}
  void write_outputs(std::span<const std::byte>) {}
  std::array<image_window, 1> inputs{window_of<"%IB0", 4>};
};
int main() {
  card a;
  no_io b;
  io_chain io{a, b};
  return io.configuration_error() == nullptr ? 0 : 1;
}
