// A controller's firmware built with iecoop: a PROGRAM in a 10 ms task, its I/O through the
// process image, the SysTick as the time base. The starting point of your own project
// (docs/embedded.md, "Your own firmware project"): replace the PROGRAM with yours, and the two
// functions of the I/O driver with your part's GPIO (or fieldbus) access.
#include <cstddef>
#include <cstdint>
#include <span>

#include <iecoop/iecoop.hpp>

#include "console.hpp"
#include "exit_status.hpp"
#include "fault_handler.hpp"
#include "tick.hpp"

namespace {

using namespace iecoop;

// The process image: one input byte (%IB0) and one output byte (%QB0).
struct controller_image_tag {};
using controller_image = process_image<1, 1, 0, addressing::codesys, controller_image_tag>;

// PROGRAM PLC_PRG: a motor started by a button, stopped by another, with a start delay.
struct PLC_PRG : program<PLC_PRG> {
  // VAR
  [[no_unique_address]] located<BOOL, "%IX0.0", controller_image> ixStart;  // ixStart AT %IX0.0 : BOOL;
  [[no_unique_address]] located<BOOL, "%IX0.1", controller_image> ixStop;   // ixStop AT %IX0.1 : BOOL;
  [[no_unique_address]] located<BOOL, "%QX0.0", controller_image> qxMotor;  // qxMotor AT %QX0.0 : BOOL;
  RS rsRun;                                                                 // rsRun : RS;
  TON tonDelay;                                                             // tonDelay : TON;
  CTU ctuStarts;                                                            // ctuStarts : CTU;
  // END_VAR
  using LOCATED = pins<&PLC_PRG::ixStart, &PLC_PRG::ixStop, &PLC_PRG::qxMotor>;

  void body() {
    rsRun("S"_ = ixStart, "R1"_ = ixStop);             // rsRun(S := ixStart, R1 := ixStop);
    tonDelay("IN"_ = rsRun.Q1, "PT"_ = "T#50ms"_iec);  // tonDelay(IN := rsRun.Q1, PT := T#50ms);
    qxMotor = tonDelay.Q;                              // qxMotor := tonDelay.Q;
    ctuStarts("CU"_ = qxMotor, "PV"_ = WORD(1000));    // ctuStarts(CU := qxMotor, PV := 1000);
  }
};

// --- The board: replace these two with your part's I/O ------------------------------------
// Here a simulated panel: START pressed from 20 to 40 ms and from 300 to 320 ms, STOP from 200
// to 220 ms; the motor's output is remembered. On a part, read the input port's register and
// write the output port's (e.g. `GPIOA->IDR`, `GPIOB->ODR` on an STM32).
std::uint32_t now_ms = 0;
std::uint32_t motor_edges[4] = {};  // when the motor's output went on, off, on, off
std::uint32_t motor_edge_count = 0;
bool motor_on = false;
std::uint8_t read_input_port() {
  const auto pressed = [](std::uint32_t from) { return now_ms >= from && now_ms < from + 20U; };
  return static_cast<std::uint8_t>((pressed(20) || pressed(300) ? 0x01U : 0U) | (pressed(200) ? 0x02U : 0U));
}
void write_output_port(std::uint8_t bits) {
  const bool on = (bits & 0x01U) != 0;
  if (on != motor_on && motor_edge_count < 4) motor_edges[motor_edge_count++] = now_ms;
  motor_on = on;
}

// The I/O driver: the application calls read_inputs at the start of each task cycle and
// write_outputs at its end (docs/scheduler.md, "I/O").
struct board_io {
  void read_inputs(std::span<std::byte> inputs) { inputs[0] = std::byte{read_input_port()}; }
  void write_outputs(std::span<const std::byte> outputs) {
    write_output_port(std::to_integer<std::uint8_t>(outputs[0]));
  }
};
// ------------------------------------------------------------------------------------------

application plc{
    task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, use_image<controller_image>{},
    retain_capacity<0>{},  // no RETAIN variables
};
board_io io;

}  // namespace

// The SysTick interrupt only counts milliseconds; the main loop runs the application.
extern "C" void SysTick_Handler() noexcept { firmware::tick::on_interrupt(); }

int main() {
  firmware::install_fault_handler();  // a fault (e.g. a division by zero) stops here: put your outputs safe
  plc.connect(io);
  plc.start();
  // A tick every millisecond: the core clock divided by 1000 (25 MHz on QEMU's MPS2 boards).
  firmware::tick::start(25000);
  std::uint32_t done_ms = 0;
  for (;;) {
    while (done_ms != firmware::tick::count()) {  // catch up with the ticks that came
      now_ms = done_ms;
      plc.run_for("T#1ms"_iec);
      ++done_ms;
      if (CONTROLLER_QEMU_RUN_MS > 0 && done_ms == CONTROLLER_QEMU_RUN_MS) {
        const PLC_PRG& p = plc.get<PLC_PRG>();
        firmware::print_line("motor on at ", motor_edges[0], " ms, off at ", motor_edges[1], " ms, on at ",
                             motor_edges[2], " ms; starts counted ", WORD(p.ctuStarts.CV));
        const bool ok = motor_edge_count == 3 && motor_edges[0] == 70 && motor_edges[1] == 200 &&
                        motor_edges[2] == 350 && p.ctuStarts.CV == WORD(2);
        firmware::end(ok ? firmware::passed : firmware::failed);
      }
    }
    firmware::tick::wait();  // sleep until the next interrupt
  }
}
