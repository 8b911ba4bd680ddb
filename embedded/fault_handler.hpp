// embedded/fault_handler.hpp — the firmware's iecoop fault handler.
//
// iecoop's default handler prints on stderr with <cstdio> and calls abort(): on a
// microcontroller neither means anything. A firmware installs its own handler with
// iecoop::set_fault_handler at the start of main, before any block runs. This one reports
// the fault on the console and ends the program with exit_status::iecoop_fault, so that a
// test sees the fault; a real controller would rather put its outputs in a safe state,
// record the fault and stop or restart.
#pragma once

#include <iecoop/fault.hpp>

#include "console.hpp"
#include "exit_status.hpp"

namespace firmware {

[[noreturn]] inline void report_fault_and_stop(const iecoop::fault_info& fault) noexcept {
  put("iecoop fault: ");
  put(iecoop::to_string(fault.kind));
  put(": ");
  put(fault.message);
  // The POU the fault names: the program that ran, or the one the fault is about (a PROGRAM
  // used while stopped: the short message of a build for size names it only there).
  if (fault.pou != nullptr) {
    put(" (pou ");
    put(fault.pou);
    put(")");
  }
  put("\n");
  end(exit_status::iecoop_fault);
}

/// Installs report_fault_and_stop as iecoop's fault handler.
inline void install_fault_handler() noexcept { iecoop::set_fault_handler(&report_fault_and_stop); }

}  // namespace firmware
