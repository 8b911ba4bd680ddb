// Firmware example: located variables of every width at odd byte addresses, and fieldbus
// register windows over the same image — what a Cortex-M0+ must do without one unaligned
// access (it has none: an unaligned load or store is a HardFault there, and under QEMU's
// Cortex-M0, which runs the cortex-m0plus images, too).
//
// The image is addressed as TwinCAT addresses it (the number is the byte offset, whatever the
// size), so %IW3 is bytes 3..4, %ID5 bytes 5..8, %IL9 bytes 9..16: every multi-byte value of
// this example starts at an odd byte. A program in a 10 ms task reads them and writes its
// outputs, a simulated field writes the inputs and reads the outputs byte by byte, and a
// Modbus-style window of four registers and one of eight coils read the outputs as a
// fieldbus device would. main() prints what the field saw and checks it.
#include <cstddef>
#include <cstdint>
#include <span>

#include <iecoop/exchange/image_window.hpp>
#include <iecoop/iecoop.hpp>

#include "console.hpp"
#include "exit_status.hpp"
#include "fault_handler.hpp"

namespace {

using namespace iecoop;

struct field_image_tag {};
using field_image = process_image<24, 24, 8, addressing::byte_offset, field_image_tag>;

// PROGRAM IO_PRG
struct IO_PRG : program<IO_PRG> {
  // VAR
  [[no_unique_address]] located<BOOL, "%IX0.0", field_image> bEnable;   // bEnable AT %IX0.0 : BOOL;
  [[no_unique_address]] located<BYTE, "%IB1", field_image> byMode;      // byMode AT %IB1 : BYTE;
  [[no_unique_address]] located<INT, "%IW3", field_image> iSpeed;       // iSpeed AT %IW3 : INT;
  [[no_unique_address]] located<DINT, "%ID5", field_image> diCount;     // diCount AT %ID5 : DINT;
  [[no_unique_address]] located<LWORD, "%IL9", field_image> lwStamp;    // lwStamp AT %IL9 : LWORD;
  [[no_unique_address]] located<REAL, "%ID17", field_image> rGain;      // rGain AT %ID17 : REAL;
  [[no_unique_address]] located<BOOL, "%QX0.1", field_image> bOn;       // bOn AT %QX0.1 : BOOL;
  [[no_unique_address]] located<INT, "%QW1", field_image> iReference;   // iReference AT %QW1 : INT;
  [[no_unique_address]] located<DINT, "%QD3", field_image> diPosition;  // diPosition AT %QD3 : DINT;
  [[no_unique_address]] located<LWORD, "%QL7", field_image> lwEcho;     // lwEcho AT %QL7 : LWORD;
  [[no_unique_address]] located<REAL, "%QD15", field_image> rOut;       // rOut AT %QD15 : REAL;
  [[no_unique_address]] located<WORD, "%MW1", field_image> wCycles;     // wCycles AT %MW1 : WORD;
  // END_VAR
  using LOCATED =
      pins<&IO_PRG::bEnable, &IO_PRG::byMode, &IO_PRG::iSpeed, &IO_PRG::diCount, &IO_PRG::lwStamp, &IO_PRG::rGain,
           &IO_PRG::bOn, &IO_PRG::iReference, &IO_PRG::diPosition, &IO_PRG::lwEcho, &IO_PRG::rOut, &IO_PRG::wCycles>;

  void body() {
    wCycles = wCycles + 1;                          // wCycles := wCycles + 1;
    bOn = bEnable && byMode == BYTE(2);             // bOn := bEnable AND byMode = 2;
    iReference = iSpeed * 2;                        // iReference := iSpeed * 2;
    diPosition = diCount + 100000;                  // diPosition := diCount + 100000;
    lwEcho = lwStamp ^ LWORD(0xFF00FF00FF00FF00U);  // lwEcho := lwStamp XOR 16#FF00FF00FF00FF00;
    rOut = rGain * REAL(2.5F);                      // rOut := rGain * 2.5;
  }
};

// Little-endian values written and read one byte at a time, as a fieldbus frame carries them.
void put_bytes(std::span<std::byte> area, std::size_t at, std::uint64_t value, std::size_t bytes) {
  for (std::size_t i = 0; i < bytes; ++i) area[at + i] = static_cast<std::byte>((value >> (8 * i)) & 0xFFU);
}
std::uint64_t get_bytes(std::span<const std::byte> area, std::size_t at, std::size_t bytes) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < bytes; ++i) value |= std::uint64_t{std::to_integer<unsigned>(area[at + i])} << (8 * i);
  return value;
}

// The field: inputs that change with every cycle, and the outputs as they arrived.
struct io_field {
  std::uint32_t cycle = 0;
  std::byte outputs[24]{};

  void read_inputs(std::span<std::byte> inputs) {
    ++cycle;
    put_bytes(inputs, 0, 0x01U, 1);                                                                   // bEnable
    put_bytes(inputs, 1, 2U, 1);                                                                      // byMode
    put_bytes(inputs, 3, static_cast<std::uint16_t>(-1000 + 700 * static_cast<int>(cycle)), 2);       // iSpeed
    put_bytes(inputs, 5, static_cast<std::uint32_t>(-250000 + 100000 * static_cast<int>(cycle)), 4);  // diCount
    put_bytes(inputs, 9, 0x0123456789ABCDEFULL + cycle, 8);                                           // lwStamp
    put_bytes(inputs, 17, 0x3FC00000U, 4);                                                            // rGain: 1.5
  }
  void write_outputs(std::span<const std::byte> image) {
    for (std::size_t i = 0; i < sizeof outputs; ++i) outputs[i] = image[i];
  }
};

application plc{
    task<IO_PRG>{"Io", cyclic{"T#10ms"_iec}, 1},
    use_image<field_image>{},
    retain_capacity<0>{},
};
io_field field;

}  // namespace

int main() {
  firmware::install_fault_handler();
  plc.connect(field);
  plc.start();
  plc.run_for("T#30ms"_iec);  // three cycles
  const std::span<const std::byte> out(field.outputs);

  const auto reference = static_cast<std::int16_t>(get_bytes(out, 1, 2));
  const auto position = static_cast<std::int32_t>(get_bytes(out, 3, 4));
  const std::uint64_t echo = get_bytes(out, 7, 8);
  const auto out_bits = static_cast<std::uint32_t>(get_bytes(out, 15, 4));
  const bool on = (get_bytes(out, 0, 1) & 0x02U) != 0;
  firmware::print_line("field after ", field.cycle, " cycles: bOn ", BOOL(on), ", iReference ", INT(reference),
                       ", diPosition ", DINT(position));
  firmware::print_line("lwEcho ", LWORD(echo), ", rOut bits ", DWORD(out_bits));
  const WORD cycles = plc.get<IO_PRG>().wCycles;
  firmware::print_line("wCycles at %MW1 (bytes 1..2 of %M): ", cycles);

  // The outputs as a fieldbus device reads them: 4 holding registers from %QW1 (bytes 1..8)
  // and 8 coils from %QX0.0, checked when made.
  const window_parse registers = register_window("%QW1", 4, io_area::output, addressing::byte_offset, 24);
  const window_parse coils = bit_window("%QX0.0", 8, io_area::output, addressing::byte_offset, 24);
  if (!registers || !coils) firmware::end(firmware::failed);
  std::uint32_t sum = 0;
  for (std::uint32_t r = 0; r < 4; ++r) sum += load_register(out, *registers, r);
  firmware::print_line("registers %QW1..: ", UINT(load_register(out, *registers, 0)), " ",
                       UINT(load_register(out, *registers, 1)), " ", UINT(load_register(out, *registers, 2)), " ",
                       UINT(load_register(out, *registers, 3)), ", coil 1 ", BOOL(load_bit(out, *coils, 1)));

  const bool ok = field.cycle == 3 && on && reference == 2200 && position == 150000 &&
                  echo == ((0x0123456789ABCDEFULL + 3) ^ 0xFF00FF00FF00FF00ULL) && out_bits == 0x40700000U &&
                  cycles == WORD(3) && load_bit(out, *coils, 1) &&
                  sum == (get_bytes(out, 1, 2) + get_bytes(out, 3, 2) + get_bytes(out, 5, 2) + get_bytes(out, 7, 2));
  firmware::print_line(ok ? "process image: as expected" : "process image: WRONG");
  return ok ? firmware::passed : firmware::failed;
}
