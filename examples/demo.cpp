// The iecoop demo. For now it tours the foundation: IEC types that wrap like a PLC, IEC
// literals checked at compile time, fixed-capacity strings and the conversion functions.
// Each line shows the ST it mirrors and the value iecoop computes for it.
#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

#include <fmt/core.h>

#include <string_view>

namespace {
template <class T>
void show(std::string_view st, const T& value) {
  fmt::print("  {:<44} {}\n", st, value);
}
}  // namespace

int main() {
  using namespace iecoop;
  fmt::print("iecoop {}.{}.{} demo: ST on the left, what iecoop computes on the right\n\n", IECOOP_VERSION_MAJOR,
             IECOOP_VERSION_MINOR, IECOOP_VERSION_PATCH);

  INT counter = 32767;
  counter = counter + 1;  // wraps as on a PLC, never undefined behaviour
  show("counter := 32767; counter := counter + 1;", counter);  // -32768

  const TIME pt = "T#1h2m3s4ms"_iec;
  show("TIME_TO_UDINT(T#1h2m3s4ms)", TIME_TO_UDINT(pt));  // 3723004
  show("T#1h2m3s4ms + T#996ms", pt + "T#996ms"_iec);       // T#1h2m4s
  show("TIME_TO_STRING(T#90s)", TIME_TO_STRING("T#90s"_iec));  // T#1m30s

  const STRING<12> name = "conveyor belt one";  // STRING(12): truncated on the right
  show("name : STRING(12) := 'conveyor belt one';", name);  // conveyor bel
  show("LEN(name)", LEN(name));                              // 12
  show("MID(name, 4, 1)", MID(name, 4, 1));                  // conv
  show("CONCAT(LEFT(name, 8), '/2')", CONCAT(LEFT(name, 8), "/2"));  // conveyor/2

  const REAL speed = INT_TO_REAL(INT(125)) / 10.0f;
  show("REAL_TO_INT(12.5)", REAL_TO_INT(speed));    // 13: halves round away from zero
  show("INT_TO_SINT(4223)", INT_TO_SINT(4223));     // 127: narrowing keeps the low byte
  show("STRING_TO_WORD('16#FF')", STRING_TO_WORD("16#FF"));  // 255
  return 0;
}
