// SPDX-License-Identifier: MIT
// iecoop/fault.hpp — the one place run-time faults go: division by zero, a call through an
// unassigned interface, an unbound VAR_IN_OUT, a watchdog overrun, ...
//
// A PLC stops the application with an exception on such faults. iecoop calls the fault
// handler instead; the default handler prints the message and aborts. A handler that
// returns lets the faulting operation finish with the defined result documented for it
// (division by zero yields 0, for example), so tests can install a recording handler and
// check that a fault happened. Nothing here allocates or throws.
#pragma once

#include <cstdint>
#include <cstdlib>
#if !defined(IECOOP_NO_STDIO)
#include <cstdio>
#endif

#include <iecoop/config.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// What went wrong. New kinds are only ever appended.
enum class fault_kind : std::uint8_t {
  division_by_zero,      ///< integer or TIME division or MOD by zero
  invalid_value,         ///< value() of a failed parse, or a similar unchecked access
  unbound_in_out,        ///< a block body ran with a VAR_IN_OUT not bound to a variable
  unassigned_interface,  ///< a call through an interface variable that is 0
  watchdog,              ///< a task exceeded its watchdog time sensitivity times in a row
  user,                  ///< raised by application code
  duplicate_program,     ///< a second instance of a PROGRAM while the first one lives
  duplicate_globals,     ///< a second instance of a global variable list while the first one lives
  property_layout,       ///< a PROPERTY member not at its block's address (not [[no_unique_address]])
  array_bounds,          ///< an ARRAY index outside its bounds (CODESYS: CheckBounds)
  out_of_range,          ///< a value outside its subrange type (CODESYS: CheckRangeSigned/Unsigned)
  null_pointer,          ///< a dereferenced null POINTER or invalid REFERENCE (CODESYS: CheckPointer)
  unsafe_chart,          ///< an SFC transition activated a step that was active already (an unsafe chart)
  lifecycle,             ///< FB_Init or FB_Exit could not run on the whole block (a constructor or destructor
                         ///< of a derived block does not call run_fb_init / run_fb_exit)
};

/// A fault as the handler sees it. `message` points to a string literal (or to text that lives
/// as long as the object that reported it: an io_chain's configuration error); `task` and `pou`
/// name the task whose cycle was running and the program it was calling when the fault
/// happened (nullptr outside a task cycle, and for a fault of the task itself, such as a
/// watchdog, `pou`). Both are set by the application's scheduler (fault_context). A fault of
/// kind lifecycle names in `pou` the block it is about (its message is a constant text), and so
/// does a fault about a PROGRAM's or a global variable list's one instance (a second instance;
/// one used while its application is stopped or that no application lists).
struct fault_info {
  fault_kind kind;
  const char* message;
  const char* task = nullptr;
  const char* pou = nullptr;
};

class task_info;  // <iecoop/runtime/task_info.hpp>

/// Where the code that runs now was called from: the task whose cycle is under way and the
/// program it is calling. The scheduler and its task cycles keep it; fault() reads it. One
/// per process, as the scheduler runs the cycles of all tasks from one thread.
struct fault_context {
  const char* task = nullptr;
  const char* pou = nullptr;
  /// The task whose cycle runs, as current_task() gives it (nullptr outside a task cycle).
  const task_info* cycle_task = nullptr;
};

/// A fault handler. It may return; the faulting operation then completes with its
/// documented fallback result.
using fault_handler = void (*)(const fault_info&);

/// The short name of a fault kind, e.g. "division by zero".
[[nodiscard]] constexpr const char* to_string(fault_kind kind) noexcept {
  switch (kind) {
    case fault_kind::division_by_zero: return "division by zero";
    case fault_kind::invalid_value: return "invalid value";
    case fault_kind::unbound_in_out: return "unbound VAR_IN_OUT";
    case fault_kind::unassigned_interface: return "call through unassigned interface";
    case fault_kind::watchdog: return "watchdog";
    case fault_kind::user: return "user fault";
    case fault_kind::duplicate_program: return "second PROGRAM instance";
    case fault_kind::duplicate_globals: return "second instance of a global variable list";
    case fault_kind::property_layout: return "property not at its block's address";
    case fault_kind::array_bounds: return "array index out of bounds";
    case fault_kind::out_of_range: return "value out of subrange";
    case fault_kind::null_pointer: return "null pointer dereferenced";
    case fault_kind::unsafe_chart: return "unsafe SFC chart";
    case fault_kind::lifecycle: return "FB_Init or FB_Exit not run on the whole block";
  }
  return "unknown fault";
}

/// The handler installed at start-up: prints "iecoop fault: <kind>: <message>" on stderr
/// and aborts the program, as a PLC stops on an exception.
///
/// With IECOOP_NO_STDIO defined (firmware without a console, see docs/embedded.md) it only
/// aborts. Being the handler's initial value, this function is linked into every program
/// that can fault, even one that installs its own handler first thing; on a microcontroller
/// its stderr would bring the C library's stream buffers, and with them malloc.
[[noreturn]] inline void default_fault_handler([[maybe_unused]] const fault_info& fault) {
#if !defined(IECOOP_NO_STDIO)
  // fputs rather than fprintf: no formatting code.
  std::fputs("iecoop fault: ", stderr);
  std::fputs(to_string(fault.kind), stderr);
  std::fputs(": ", stderr);
  std::fputs(fault.message, stderr);
  if (fault.task != nullptr) {
    std::fputs(" (task ", stderr);
    std::fputs(fault.task, stderr);
    if (fault.pou != nullptr) {
      std::fputs(", program ", stderr);
      std::fputs(fault.pou, stderr);
    }
    std::fputs(")", stderr);
  } else if (fault.pou != nullptr) {
    std::fputs(" (", stderr);  // outside a cycle: the block a lifecycle fault is about
    std::fputs(fault.pou, stderr);
    std::fputs(")", stderr);
  }
  std::fputs("\n", stderr);
#endif
  std::abort();
}

namespace detail {
inline fault_handler current_fault_handler = &default_fault_handler;
/// The context outside every scope: nothing runs.
inline fault_context outside_cycles{};
/// The context now: the innermost scope's. A pointer, so that a task cycle makes its context
/// (a local of the cycle's start) current with one store and gives the previous one back with
/// another; a program's name is written into it as the cycle calls the program.
inline fault_context* current_fault_context = &outside_cycles;

/// Makes `context` the fault context for as long as it lives and restores the previous one
/// after; `context` must outlive the scope.
class fault_context_scope {
 public:
  explicit fault_context_scope(fault_context& context) noexcept : previous_(current_fault_context) {
    current_fault_context = &context;
  }
  fault_context_scope(const fault_context_scope&) = delete;
  fault_context_scope& operator=(const fault_context_scope&) = delete;
  ~fault_context_scope() { current_fault_context = previous_; }

 private:
  fault_context* previous_;
};

/// Reports `kind` about the POU `name` (a block, a PROGRAM, a global variable list): the
/// fault's pou is that name, not the program running; its task is the running one. For a
/// message that is a constant text: the name is not composed into it.
inline void report_about(fault_kind kind, const char* message, const char* name) {
  current_fault_handler(fault_info{kind, message, current_fault_context->task, name});
}
}  // namespace detail

/// The task and program running now (both nullptr outside a task cycle).
[[nodiscard]] inline fault_context current_fault_context() noexcept { return *detail::current_fault_context; }

/// Installs `handler` (nullptr restores the default) and returns the previous one.
/// Install handlers at start-up or in tests, not while tasks run concurrently.
inline fault_handler set_fault_handler(fault_handler handler) noexcept {
  const fault_handler previous = detail::current_fault_handler;
  detail::current_fault_handler = handler != nullptr ? handler : &default_fault_handler;
  return previous;
}

/// The handler currently installed.
[[nodiscard]] inline fault_handler get_fault_handler() noexcept { return detail::current_fault_handler; }

/// Reports a fault to the installed handler. Not constexpr on purpose: a fault reached
/// during constant evaluation is a compile error.
/// The fault carries the current fault context: the task and the program running.
inline void fault(fault_kind kind, const char* message) {
  const fault_context& where = *detail::current_fault_context;
  detail::current_fault_handler(fault_info{kind, message, where.task, where.pou});
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
