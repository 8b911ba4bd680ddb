// Code-generation checks of located variables (see cmake/check_codegen.cmake): a located
// variable is one load or store at a link-time constant address, the same code as reading
// and writing the process image's bytes by hand.
#include <iecoop/io/located.hpp>

#include <cstdint>
#include <cstring>

using namespace iecoop;

namespace {
using image = default_process_image;
}  // namespace

extern "C" {

// Reading a word input is one 16-bit load.
short iecoop_same_located_read_a() {
  located<INT, "%IW2"> iSpeed;
  return iSpeed.get().value();
}
short iecoop_same_located_read_b() {
  std::int16_t v;
  std::memcpy(&v, image::inputs().data() + 4, sizeof v);
  return v;
}

// Writing a double word output is one 32-bit store.
void iecoop_same_located_write_a(std::int32_t value) {
  located<DINT, "%QD1"> diCount;
  diCount = DINT(value);
}
void iecoop_same_located_write_b(std::int32_t value) { std::memcpy(image::outputs().data() + 4, &value, sizeof value); }

// Arithmetic on located values is arithmetic on the bytes.
void iecoop_same_located_expression_a() {
  located<INT, "%IW0"> iSpeed;
  located<INT, "%QW0"> iSetpoint;
  iSetpoint = iSpeed + 1;
}
void iecoop_same_located_expression_b() {
  std::uint16_t v;
  std::memcpy(&v, image::inputs().data(), sizeof v);
  v = static_cast<std::uint16_t>(v + 1u);
  std::memcpy(image::outputs().data(), &v, sizeof v);
}

// Setting and clearing a bit is one OR or AND on its byte.
void iecoop_same_located_bit_set_a() {
  located<BOOL, "%QX1.3"> bMotor;
  bMotor = TRUE;
}
void iecoop_same_located_bit_set_b() { image::outputs()[1] |= std::byte{0x08}; }
void iecoop_same_located_bit_clear_a() {
  located<BOOL, "%QX1.3"> bMotor;
  bMotor = FALSE;
}
void iecoop_same_located_bit_clear_b() { image::outputs()[1] &= std::byte{0xF7}; }

}  // extern "C"
