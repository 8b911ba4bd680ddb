// SPDX-License-Identifier: MIT
// iecoop/runtime/task.hpp — TASK: when the programs of an application run. A task has a type
// (cyclic, freewheeling or event), a priority (0 highest .. 31 lowest), an optional watchdog
// and the programs it calls, in order — CODESYS's task configuration, line for line:
//
//     // Task configuration
//     //   Fast    Cyclic t#1ms    priority 0   watchdog t#2ms, sensitivity 2   calls IO_PRG
//     //   Slow    Cyclic t#20ms   priority 5                                    calls SUPERVISION_PRG, LOG_PRG
//     //   Alarm   Event bAlarm    priority 1                                    calls ALARM_PRG
//     iecoop::task<IO_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0, watchdog{"T#2ms"_iec, 2}}
//     iecoop::task<SUPERVISION_PRG, LOG_PRG>{"Slow", cyclic{"T#20ms"_iec}, 5}
//     iecoop::task<ALARM_PRG>{"Alarm", event{bAlarm}, 1}
//
// or, in IEC's configuration syntax, `TASK Fast(INTERVAL := T#1ms, PRIORITY := 0);
// PROGRAM Io WITH Fast : IO_PRG;`. Tasks are handed to an application (<iecoop/runtime/application.hpp>),
// which owns the program instances and runs the tasks. Constants are checked while compiling:
// a priority outside 0..31, an interval or watchdog time of zero, a task without programs or
// calling one program twice do not compile. (Clang 14 evaluates a consteval constructor in a
// namespace-scope initializer at run time: there a bad value is reported as a fault.)
#pragma once

#include <cstdint>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/pou/program.hpp>
#include <iecoop/runtime/scheduler.hpp>
#include <iecoop/runtime/task_settings.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

template <class P>
concept program_type = std::is_base_of_v<program<P>, P>;

/// A global variable list (derived from global_variables<G>, <iecoop/pou/global_variables.hpp>).
template <class G>
concept global_list_type = requires { typename G::iecoop_global_variables; };

}  // namespace detail

/**
 * A task that calls the PROGRAMs `Programs`, in this order, each cycle. The application that
 * is given the task owns one instance of each program (reach it with P::instance()).
 *
 *     task<PLC_PRG>{"MainTask", cyclic{"T#10ms"_iec}, 1}
 *     task<PLC_PRG>{"MainTask", cyclic{"T#10ms"_iec}, 1, watchdog{"T#20ms"_iec, 3}}
 *     task<LOG_PRG>{"Background", freewheeling{}, 31}
 *     task<ALARM_PRG>{"Alarm", event{bAlarm}, 0}
 */
template <class... Programs>
class task {
  static_assert(sizeof...(Programs) > 0, "iecoop: a task calls at least one program; name them: task<PLC_PRG>{...}");
  static_assert(!(detail::global_list_type<Programs> || ...),
                "iecoop: a task calls PROGRAMs, and a global variable list is none (the type in task<...>); give "
                "the list to the application as globals<GVL>{}, beside the tasks");
  static_assert(
      ((detail::program_type<Programs> || detail::global_list_type<Programs>)&&...),
      "iecoop: a task calls PROGRAMs (types derived from iecoop::program<Self>); call function blocks from a program");
  static_assert(detail::all_distinct<Programs...>::value,
                "iecoop: a task calls the same program twice; list each program once per task");

 public:
  /// A cyclic task: `task<PLC_PRG>{"MainTask", cyclic{"T#10ms"_iec}, 1}`; the priority is 0..31.
  consteval task(const char* name, cyclic type, int priority)
      : task(name, task_kind::cyclic, type.interval, event{}, priority, nullptr) {}
  consteval task(const char* name, cyclic type, int priority, watchdog dog)
      : task(name, task_kind::cyclic, type.interval, event{}, priority, &dog) {}
  /// A freewheeling task: `task<LOG_PRG>{"Background", freewheeling{}, 31}`.
  consteval task(const char* name, freewheeling, int priority)
      : task(name, task_kind::freewheeling, {}, event{}, priority, nullptr) {}
  consteval task(const char* name, freewheeling, int priority, watchdog dog)
      : task(name, task_kind::freewheeling, {}, event{}, priority, &dog) {}
  /// An event task: `task<ALARM_PRG>{"Alarm", event{bAlarm}, 0}`.
  consteval task(const char* name, event trigger, int priority)
      : task(name, task_kind::event, {}, trigger, priority, nullptr) {}
  consteval task(const char* name, event trigger, int priority, watchdog dog)
      : task(name, task_kind::event, {}, trigger, priority, &dog) {}

  [[nodiscard]] constexpr const task_settings& settings() const noexcept { return settings_; }

 private:
  // Every check in one constructor (Clang 14 crashes when a check fails in a function that a
  // consteval constructor calls, or in a constructor it delegates to and then continues).
  consteval task(const char* name, task_kind kind, LTIME interval, event trigger, int priority, const watchdog* dog) {
    if (priority < 0 || priority > 31) {
      // The compiler shows the call's line, which must hold the whole message.
      // clang-format off
      detail::compile_error("iecoop: a task priority is 0 (highest) to 31 (lowest), as in CODESYS; use a value in 0..31");
      // clang-format on
    }
    if (kind == task_kind::cyclic && interval == LTIME::zero()) {
      // The compiler shows the call's line, which must hold the whole message.
      // clang-format off
      detail::compile_error("iecoop: a cyclic task needs an interval greater than zero; write e.g. cyclic{\"T#10ms\"_iec}");
      // clang-format on
    }
    if (dog != nullptr && dog->time == LTIME::zero()) {
      // The compiler shows the call's line, which must hold the whole message.
      // clang-format off
      detail::compile_error("iecoop: a watchdog time must be greater than zero; write e.g. watchdog{\"T#20ms\"_iec, 2}");
      // clang-format on
    }
    settings_.name = name;
    settings_.kind = kind;
    settings_.interval = interval;
    settings_.trigger = trigger;
    settings_.priority = static_cast<std::uint8_t>(priority);
    if (dog != nullptr) {
      settings_.has_watchdog = true;
      settings_.watchdog_time = dog->time;
      settings_.watchdog_sensitivity = dog->sensitivity;
    }
    // (the hooks name the scheduler's task_state: hence <iecoop/runtime/scheduler.hpp> above)
    settings_.hooks = detail::hooks_for<task_state>(kind, dog != nullptr);
  }

  task_settings settings_{};
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
