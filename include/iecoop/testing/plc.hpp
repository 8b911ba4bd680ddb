// SPDX-License-Identifier: MIT
// iecoop/testing/plc.hpp — testing a whole application: its tasks, programs, global variables
// and process image, in simulated time.
//
//     inline auto make_plc() { return application{task<IO_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}, globals<GVL>{}}; }
//
//     struct ConveyorTest : testing::plc<make_plc> {   // a fixture: the application, started
//       GVL& gvl = get<GVL>();
//     };
//     TEST_CASE_FIXTURE(ConveyorTest, "jam after T#2s") {
//       force(gvl.bStart, TRUE);
//       step();                                        // one base cycle (T#1ms)
//       advance("T#2s"_iec);
//       CHECK(gvl.bJam);
//     }
//
// testing::plc<Make> owns the application `Make()` returns and starts it; the fixture's
// constructor is the test's setup and its destructor the teardown (the application stops:
// FB_Exit). testing::plc_driver<App> drives an application the test owns itself. A call
// through an unassigned interface halts the application (faults.hpp).
// IWYU pragma: private, include <iecoop/testing.hpp>
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>

#include <iecoop/runtime/application.hpp>
#include <iecoop/runtime/cycle_observer.hpp>
#include <iecoop/testing/driver.hpp>
#include <iecoop/testing/faults.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::testing {

/// Drives the application `app` (which must outlive it): step() runs one base cycle (the
/// shortest cyclic interval), forced values are written in every task's cycles.
template <class App>
class plc_driver : public driver<plc_driver<App>> {
 public:
  /// Attaches to `app`'s tasks; starts it unless `start` is FALSE.
  explicit plc_driver(App& app, bool start = true) : app_(app) {
    for (std::size_t i = 0; i < App::task_count(); ++i) {
      hooks_[i].forces = &this->forces_;
      app_.task(i).attach(hooks_[i]);
    }
    if (start) app_.start();
  }

  [[nodiscard]] App& app() noexcept { return app_; }
  /// The application's instance of program or global variable list T.
  template <class T>
  [[nodiscard]] T& get() {
    return app_.template get<T>();
  }
  [[nodiscard]] task_state& task(std::string_view name) noexcept { return app_.task(name); }

  [[nodiscard]] LTIME now() const noexcept { return app_.now(); }
  /// Base cycles run by this driver.
  [[nodiscard]] std::uint64_t cycle() const noexcept { return cycle_; }
  [[nodiscard]] LTIME step_time() const noexcept { return app_.base_cycle(); }

  void run_cycles(std::uint64_t n) {
    for (std::uint64_t i = 0; i < n; ++i) {
      const LTIME end = app_.now() + app_.base_cycle();
      if (!detail::call_guarded([this] { app_.run_for(app_.base_cycle()); })) {
        // A fault a program could not go past (faults.hpp): the application stops, as a PLC
        // does on an exception (app().start() runs it again), and its time goes on.
        app_.scheduler().halt();
        app_.scheduler().advance_to(end);
      }
      ++cycle_;
      this->stepped();
    }
  }

 private:
  // One per task: forced values before and after the task's programs.
  struct force_hook : cycle_observer {
    force_hook()
        : cycle_observer(
              [](cycle_observer& self, LTIME, std::uint64_t) { static_cast<force_hook&>(self).forces->apply_at_end(); },
              [](cycle_observer& self, LTIME, std::uint64_t) {
                static_cast<force_hook&>(self).forces->apply_at_start();
              }) {}
    force_table* forces = nullptr;
  };

  App& app_;
  std::array<force_hook, App::task_count()> hooks_{};
  std::uint64_t cycle_ = 0;
};

namespace detail {
template <auto Make>
struct application_holder {
  decltype(Make()) application = Make();
};
}  // namespace detail

/**
 * A test fixture over the application `Make()` returns (a function or a lambda without
 * captures): it owns the application, starts it, and drives it (plc_driver). Derive the
 * test's fixture from it, or use it in a test case directly.
 */
template <auto Make>
class plc : private detail::application_holder<Make>, public plc_driver<decltype(Make())> {
 public:
  using application_type = decltype(Make());
  explicit plc(bool start = true) : plc_driver<application_type>(this->application, start) {}
};

}  // namespace iecoop::testing

#include <iecoop/detail/pop_macros.hpp>
