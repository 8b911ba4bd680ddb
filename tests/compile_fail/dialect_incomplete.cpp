// EXPECT: Dialect
// A dialect of one's own must say all three things the dialects differ in; one that
// forgets the counters' value type is no Dialect.
#include <iecoop/iecoop.hpp>
#include <string_view>
using namespace iecoop;
struct plant_dialect {
  static constexpr std::string_view name = "plant";
  static constexpr bool f_trig_fires_on_first_call = true;
  static constexpr counter_limit counter_limits = counter_limit::preset;
  static constexpr counter_names counter_pin_names = counter_names::codesys;
#ifndef IECOOP_COMPILE_FAIL
  using counter_type = UINT;
#endif
};
int main() {
  falling_edge_trigger<plant_dialect> edge;
  edge("CLK"_ = FALSE);
  return edge.Q ? 0 : 1;
}
