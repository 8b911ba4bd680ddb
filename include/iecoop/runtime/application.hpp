// SPDX-License-Identifier: MIT
// iecoop/runtime/application.hpp — an application: the program instances, the tasks that run them,
// the process image they share, and a deterministic scheduler in simulated time.
//
//     iecoop::application plc{
//         task<IO_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0, watchdog{"T#2ms"_iec, 2}},
//         task<SUPERVISION_PRG>{"Slow", cyclic{"T#20ms"_iec}, 5},
//         globals<GVL>{},
//     };
//     plc.connect(io);                 // the I/O driver (simulated_io in tests)
//     plc.start();                     // FB_Init of every instance; tasks start
//     plc.run_for("T#1h"_iec);         // an hour of machine time, in milliseconds of yours
//     plc.task("Fast").statistics();   // cycles, cycle time, jitter, overruns
//     plc.reset(reset_kind::warm);     // RETAIN and PERSISTENT kept, the rest initialised
//     plc.stop();                      // FB_Exit of every instance
//
// Time is simulated: run_for() jumps from one instant where something happens to the next,
// so a 1 ms task runs an hour in a fraction of a second and every run is the same. Each task
// cycle latches the inputs, sets the cycle clock the standard blocks read, calls the task's
// programs in order, and writes the outputs it changed at its end. A task's execution time is
// zero unless a test models it (task_state::model_execution_time), which makes preemption,
// overruns, watchdog faults and jitter testable too. The real-time runner
// (<iecoop/runtime/realtime.hpp>) runs the same application against the steady clock.
//
// The application is a composition of four parts, each in its own header:
//   configuration<Entries...>  what the tasks, lists, image and retain size are (compile time)
//   instance_store             the program and list instances (construction = FB_Init)
//   task_cycles                what a task cycle does: inputs, cycle clock, programs, outputs
//   scheduler                  when cycles start and end: releases, priorities, watchdog, time
// and itself holds the lifecycle (start, stop, reset) and the retained data.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/detail/lifecycle_state.hpp>
#include <iecoop/detail/single_instance.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/io/driver.hpp>
#include <iecoop/pou/lifecycle.hpp>
#include <iecoop/runtime/configuration.hpp>
#include <iecoop/runtime/instance_store.hpp>
#include <iecoop/runtime/retain.hpp>
#include <iecoop/runtime/retain_image.hpp>
#include <iecoop/runtime/retain_storage.hpp>
#include <iecoop/runtime/scheduler.hpp>
#include <iecoop/runtime/task.hpp>
#include <iecoop/runtime/task_cycles.hpp>
#include <iecoop/standard/detail/duration_argument.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// What the application is doing.
enum class application_state : std::uint8_t {
  stopped,    ///< no instances: before start() and after stop()
  running,    ///< tasks run
  halted,     ///< instances exist, tasks do not run (after a reset; start() runs them again)
  exception,  ///< a watchdog fault stopped the tasks; reset() leaves this state
};

/// How start() treats the retained data it finds (in the retain memory or the storage).
enum class start_mode : std::uint8_t {
  restart,   ///< a controller restart: RETAIN and PERSISTENT values are restored
  download,  ///< a new download: only PERSISTENT values are restored
};

/**
 * An application: tasks (task<...>{...}), global variable lists (globals<...>{}) and, if the
 * defaults do not fit, the process image (use_image<...>{}) and the retain memory size
 * (retain_capacity<N>{}). It owns one instance of every program its tasks call and of every
 * global variable list, constructs them at start() and destroys them at stop().
 *
 * Not copyable or movable (the instances are registered by address). Not thread-safe: run it
 * from one thread (the simulation is single-threaded; the real-time runner uses one thread).
 */
template <class... Entries>
class application {
  using config = detail::configuration<Entries...>;
  using store_type = detail::instance_store<typename config::owned_list>;
  using cycles_type = detail::task_cycles<typename config::image, store_type, typename config::task_list>;

 public:
  /// The process image the tasks latch and write.
  using image = typename config::image;
  /// Bytes of retain memory.
  static constexpr std::size_t retain_bytes = config::retain_bytes;
  /// The scheduler that runs the tasks.
  using scheduler_type = iecoop::scheduler<config::task_count, cycles_type>;

  explicit application(const Entries&... entries)
      : scheduler_(detail::hooks_from_tasks, config::task_settings_of(entries...), store_) {
    static_assert(detail::none<typename config::program_outside_tasks>,
                  "iecoop: a PROGRAM is assigned to no task (the program in none<...>); name it in a task "
                  "(task<PRG>{\"Main\", cyclic{\"T#10ms\"_iec}, 1}) — a program that only other POUs call is "
                  "declared as an ordinary variable");
    static_assert(detail::none<typename config::list_outside_globals>,
                  "iecoop: a global variable list is given to the application outside globals<...> (the list in "
                  "none<...>); give it as globals<GVL>{}, as in application{task<...>{...}, globals<GVL>{}}");
    static_assert(detail::none<typename config::external_not_globals>,
                  "iecoop: a program's VAR_EXTERNAL names the global variable lists it uses as globals<...> (the "
                  "program in none<...>); write using VAR_EXTERNAL = iecoop::globals<GVL_A, GVL_B>;");
    static_assert(detail::none<typename config::external_not_in_globals>,
                  "iecoop: a program uses a global variable list (its VAR_EXTERNAL) that the application does not "
                  "list (the program and the list in none<...>); add the list to the application's globals<...>{}, as "
                  "in application{task<...>{...}, globals<GVL>{}}");
    config::check_located_variables();
    count_listed(1);
  }
  application(const application&) = delete;
  application& operator=(const application&) = delete;
  /// Stops the application (FB_Exit of every instance, retained data saved) if it runs.
  ~application() {
    stop();
    count_listed(-1);
  }

  // --- Lifecycle --------------------------------------------------------------------

  /**
   * Starts the tasks. If the instances do not exist yet (first start, or after stop()), they
   * are constructed first, and the retained values are restored (`mode` says which): from the
   * retain memory, which holds this application's last stop(), else from the attached storage.
   * The image is checked before any instance exists — intact, saved by the same variables,
   * every value one of its type (retain_status() tells what was found) — so that FB_Init gets
   * bInitRetains = FALSE exactly when the RETAIN values are restored, and each remanent
   * variable takes its kept value as it is constructed: FB_Init sees the kept values, as in
   * CODESYS (docs/retain.md, "Start-up order"). A missing, empty, damaged or too large image is
   * replaced by the storage's previous one if it has an intact one (load_previous(),
   * retain_load::restored_previous); a rejected image is moved aside (set_aside())
   * so that no save overwrites it. After a reset, start() continues with the existing
   * instances; cyclic and freewheeling tasks are released from now() on. On a running
   * application it does nothing. Returns FALSE in the exception state (reset first), and if the
   * RETAIN and PERSISTENT variables need more than the retain memory (a fault of kind
   * invalid_value; the application stays stopped: give it retain_capacity<N>{} with the N the
   * fault names). Returns FALSE too, before anything else, while the connected I/O driver
   * reports a configuration error (an io_chain of two drivers that write the same input bits:
   * a fault of kind invalid_value with its message, which names them).
   */
  bool start(start_mode mode = start_mode::restart) {
    if (scheduler_.state() == scheduler_state::exception) return false;
    if (scheduler_.state() == scheduler_state::running) return true;
    if (const char* error = scheduler_.cycles().io_configuration_error()) {
      fault(fault_kind::invalid_value, error);
      return false;
    }
    if (!constructed_ && !load(mode)) return false;
    return scheduler_.start();
  }

  /// Stops the tasks and ends the instances: saves the RETAIN and PERSISTENT values (to the
  /// retain memory and the attached storage), then FB_Exit of every instance. A storage that
  /// fails to save reports fault_kind::invalid_value after FB_Exit has run. The next start()
  /// is a controller restart.
  void stop() {
    if (!constructed_) return;
    if constexpr (retain_bytes == 0) {  // no retain memory: nothing to save (and none of its code)
      destroy();
      scheduler_.halt();
    } else {
      const std::size_t size = save(retain_kinds::both);
      memory_.size = size;
      memory_.own_verdict = size > 0
                                ? detail::check_retained(store_.objects(), retain_kinds::both, retained_image(size))
                                : detail::retained_verdict::nothing_found(retain_kinds::both);
      memory_.own_order = detail::retained_in_construction_order(store_.objects(), retain_kinds::both);
      const bool saved =
          size == 0 || memory_.storage.object == nullptr ||
          memory_.storage.save(memory_.storage.object, std::span<const std::byte>(memory_.bytes.data(), size));
      destroy();
      scheduler_.halt();
      if (!saved) {
        fault(fault_kind::invalid_value,
              "the storage did not save the RETAIN/PERSISTENT data; a restart in another process starts without it (or "
              "with older data)");
      }
    }
  }

  /**
   * Resets the application as CODESYS's Reset warm / cold / origin: FB_Exit of every instance,
   * then FB_Init (bInitRetains = FALSE for warm, TRUE otherwise); a warm reset keeps RETAIN and
   * PERSISTENT values, a cold one PERSISTENT values, origin none. The kept values are in place
   * when FB_Init runs (each variable takes its value as it is constructed). The process image
   * is cleared, the task statistics start afresh, an exception is cleared, and the application
   * is halted: start() runs the tasks again. Does nothing when stopped.
   */
  void reset(reset_kind kind) {
    if (!constructed_) return;
    const retain_kinds keep = kept_over(kind == reset_kind::warm   ? retain_event::warm_reset
                                        : kind == reset_kind::cold ? retain_event::cold_reset
                                                                   : retain_event::origin_reset);
    if constexpr (retain_bytes == 0) {
      // No retain memory: nothing was saved, so nothing can be lost; what the reset keeps
      // counts as kept (bInitRetains = FALSE on a warm reset, as with memory).
      destroy();
      iecoop::retain_status status;
      status.retain = keep.contains(retain_kind::retain) ? retain_load::restored : retain_load::not_kept;
      status.persistent = keep.contains(retain_kind::persistent) ? retain_load::restored : retain_load::not_kept;
      publish(status);
      construct(!keep.contains(retain_kind::retain));
      scheduler_.restart();
    } else {
      const std::size_t size = save(keep);
      // What the reset keeps, checked on the instances that wrote it, and whether they were
      // constructed in the image's order (then their next construction takes the values).
      detail::retained_verdict verdict = size > 0 ? detail::check_retained(store_.objects(), keep, retained_image(size))
                                                  : detail::retained_verdict::nothing_found(keep);
      for (const retain_kind k : {retain_kind::retain, retain_kind::persistent}) {
        if (size == 0) verdict[k] = keep.contains(k) ? retain_load::restored : retain_load::not_kept;
      }
      const retain_kinds ordered = detail::retained_in_construction_order(store_.objects(), keep);
      destroy();
      iecoop::retain_status status;
      status.retain = verdict.retain;
      status.persistent = verdict.persistent;
      construct_restoring(!verdict.restorable().contains(retain_kind::retain), verdict, ordered, size, status);
      scheduler_.restart();
    }
  }

  /// What the last start() that constructed the instances, or the last reset(), did with the
  /// retained data (also readable by the programs: retain_info()).
  [[nodiscard]] const iecoop::retain_status& retain_status() const noexcept { return retain_status_; }

  /// The bytes of retain memory the RETAIN and PERSISTENT variables need (their image), as
  /// the last start() found them; 0 before it, or without such variables.
  [[nodiscard]] std::size_t retain_bytes_needed() const noexcept { return retain_bytes_needed_; }

  [[nodiscard]] application_state state() const noexcept {
    if (!constructed_) return application_state::stopped;
    switch (scheduler_.state()) {
      case scheduler_state::running: return application_state::running;
      case scheduler_state::exception: return application_state::exception;
      case scheduler_state::halted: break;
    }
    return application_state::halted;
  }

  // --- Simulated time ---------------------------------------------------------------

  /// The simulated time: how long the application has run since it was created.
  [[nodiscard]] LTIME now() const noexcept { return scheduler_.now(); }

  /// Runs every task that is due in [now(), now() + duration), in priority order, and
  /// leaves now() at the end of that span. Time passes also while the tasks do not run.
  /// A duration is TIME, LTIME or std::chrono: `run_for(3000)` does not compile (3000 what?).
  void run_for(detail::duration_argument duration) { scheduler_.run_for(duration); }

  /// Runs every task that is due before `until` (see run_for), a time since the start.
  void run_until(detail::duration_argument until) { scheduler_.run_until(until); }

  /// Runs `n` base cycles: n times the shortest cyclic interval (1 ms without cyclic tasks).
  void run_cycles(std::uint64_t n) { run_for(base_cycle() * n); }

  /// The shortest interval of a cyclic task, or 1 ms without one.
  [[nodiscard]] LTIME base_cycle() const noexcept { return scheduler_.base_cycle(); }

  // --- Tasks and instances ----------------------------------------------------------

  [[nodiscard]] static constexpr std::size_t task_count() noexcept { return config::task_count; }
  /// The task at `index` in the configuration; an index out of range reports
  /// fault_kind::invalid_value and yields the first task.
  [[nodiscard]] task_state& task(std::size_t index) noexcept { return scheduler_.task(index); }
  [[nodiscard]] const task_state& task(std::size_t index) const noexcept { return scheduler_.task(index); }
  /// The task called `name`; an unknown name reports fault_kind::invalid_value and yields the first task.
  [[nodiscard]] task_state& task(std::string_view name) noexcept { return scheduler_.task(name); }
  [[nodiscard]] std::span<task_state, config::task_count> tasks() noexcept { return scheduler_.tasks(); }
  [[nodiscard]] std::span<const task_state, config::task_count> tasks() const noexcept { return scheduler_.tasks(); }

  /// The task whose watchdog stopped the application, or nullptr.
  [[nodiscard]] const task_state* faulted_task() const noexcept { return scheduler_.faulted_task(); }

  /// The scheduler, for a runner that drives the tasks against another clock
  /// (<iecoop/runtime/realtime.hpp>) or a test that steps them one by one.
  [[nodiscard]] scheduler_type& scheduler() noexcept { return scheduler_; }
  [[nodiscard]] const scheduler_type& scheduler() const noexcept { return scheduler_; }

  /// The application's instance of program or global variable list T. Before start() (or
  /// after stop()) it reports fault_kind::invalid_value and yields a scratch instance.
  template <class T>
  [[nodiscard]] T& get() {
    if constexpr (!config::template owns<T>) {
      if constexpr (detail::global_list_type<T>) {
        static_assert(config::template owns<T>,
                      "iecoop: the application does not list this global variable list (T); add it to the "
                      "application, as in application{task<...>{...}, globals<GVL>{}}");
      } else {
        static_assert(config::template owns<T>,
                      "iecoop: the application owns no instance of this type (T); name the program in a task, or the "
                      "list in globals<...>");
      }
      return stand_in<T>();
    } else {
      if (constructed_) return store_.template get<T>();
      return stand_in<T>();
    }
  }

  // --- I/O, storage, settings ------------------------------------------------------------

  /// Uses `driver` for the I/O from now on: its inputs are latched at the start of each task
  /// cycle, the outputs a cycle changed are written at its end. The driver must outlive its use.
  /// start() refuses a driver whose configuration_error() reports one (an io_chain of two
  /// drivers on the same input bits); while the tasks run, connect() refuses it: a fault of
  /// kind invalid_value, and the driver connected before stays.
  template <IoDriver D>
  void connect(D& driver) noexcept {
    if (scheduler_.state() == scheduler_state::running) {
      if (const char* error = detail::configuration_error_of(driver)) {
        fault(fault_kind::invalid_value, error);
        return;
      }
    }
    scheduler_.cycles().connect(driver);
  }

  /// Saves retained data to `storage` at stop() and reads it at the start() that constructs
  /// the instances (a controller restart, possibly of another process). Must outlive its use.
  /// Where the storage has them, start() uses its previous image (RetainStorageWithPrevious)
  /// for a damaged one, sets a rejected image aside (RetainStorageSetAside) and tells an image
  /// too large for the retain memory (RetainStorageSized). An application without retain
  /// memory (retain_capacity<0>) would save nothing: it does not compile.
  template <RetainStorage S>
  void use_storage(S& storage) noexcept {
    static_assert(retain_bytes > 0,
                  "iecoop: an application without retain memory (retain_capacity<0>) saves nothing to a storage; give "
                  "it retain_capacity<N>{} with N at least application::retain_bytes_needed(), or attach no storage");
    if constexpr (retain_bytes > 0) bind_storage(storage);
  }

  /// Saves the RETAIN and PERSISTENT values to the attached storage now (as TwinCAT's
  /// FB_WritePersistentData). FALSE without storage, instances or room.
  bool save_retained() {
    if constexpr (retain_bytes == 0) {
      return false;  // no retain memory, no storage (use_storage refuses one)
    } else {
      if (memory_.storage.object == nullptr || !constructed_) return false;
      const std::size_t size = save(retain_kinds::both);
      return size > 0 &&
             memory_.storage.save(memory_.storage.object, std::span<const std::byte>(memory_.bytes.data(), size));
    }
  }

  /// The processor load freewheeling tasks may use, in percent (CODESYS: 80 by default).
  /// A freewheeling task pauses after each cycle for cycle time x (100 - L) / L, at least
  /// 1 ms, where L = min(100, percent) / 2 / (number of freewheeling tasks).
  void set_freewheeling_load(unsigned percent) noexcept { scheduler_.set_freewheeling_load(percent); }

  /// The outputs as last written to the driver (what the field sees).
  [[nodiscard]] std::span<const std::byte, image::output_bytes> published_outputs() const noexcept {
    return scheduler_.cycles().published();
  }

 private:
  struct storage_binding {
    void* object = nullptr;
    bool (*save)(void*, std::span<const std::byte>) = nullptr;
    std::size_t (*load)(void*, std::span<std::byte>) = nullptr;
    std::size_t (*load_previous)(void*, std::span<std::byte>) = nullptr;  // optional
    bool (*set_aside)(void*) = nullptr;                                   // optional
    std::size_t (*stored_size)(void*) = nullptr;                          // optional
  };

  /// What get<T>() yields while no instance is constructed, reporting a fault.
  template <class T>
  static T& stand_in() {
    if constexpr (requires { T::instance(); }) {
      return T::instance();  // a program or global_variables<>: reports the fault, yields its scratch instance
    } else {
      fault(fault_kind::invalid_value, "application::get before start(); a scratch instance stands in");
      static T& scratch = []() -> T& {
        detail::scratch_scope making;  // programs inside it do not become the live ones
        static T instance;
        return instance;
      }();
      return scratch;
    }
  }

  /// Tells each owned program and list that one more (`by` 1) or one fewer (-1) application
  /// lists it, for the message of its instance() while none is constructed.
  static void count_listed(int by) noexcept {
    [by]<class... Owned>(detail::type_list<Owned...>) {
      ((detail::listed_by_applications<Owned> += by), ...);
    }(typename config::owned_list{});
  }

  template <RetainStorage S>
  void bind_storage(S& storage) noexcept {
    memory_.storage = storage_binding{};
    memory_.storage.object = &storage;
    memory_.storage.save = [](void* s, std::span<const std::byte> data) { return static_cast<S*>(s)->save(data); };
    memory_.storage.load = [](void* s, std::span<std::byte> buffer) {
      return static_cast<std::size_t>(static_cast<S*>(s)->load(buffer));
    };
    if constexpr (RetainStorageWithPrevious<S>) {
      memory_.storage.load_previous = [](void* s, std::span<std::byte> buffer) {
        return static_cast<std::size_t>(static_cast<S*>(s)->load_previous(buffer));
      };
    }
    if constexpr (RetainStorageSetAside<S>) {
      memory_.storage.set_aside = [](void* s) { return static_cast<S*>(s)->set_aside(); };
    }
    if constexpr (RetainStorageSized<S>) {
      memory_.storage.stored_size = [](void* s) {
        return static_cast<std::size_t>(static_cast<const S*>(s)->stored_size());
      };
    }
  }

  void construct(bool init_retains) {
    image::clear();
    detail::lifecycle_scope initialising({init_retains, false, false, false});
    store_.construct_all();
    constructed_ = true;
    scheduler_.cycles().publish_image_outputs();  // what FB_Init wrote to %Q goes out with the first cycle
  }

  void publish(const iecoop::retain_status& status) noexcept {
    retain_status_ = status;
    retain_status_.BootDataLoaded =
        BOOL(status.persistent == retain_load::restored || status.persistent == retain_load::restored_previous);
    retain_status_.OldBootData = BOOL(status.persistent == retain_load::restored_previous);
    detail::last_retain_status = retain_status_;
  }

  void destroy() {
    detail::lifecycle_scope exiting({true, false, false, false});
    store_.destroy_all();
    constructed_ = false;
  }

  /// Constructs the instances and restores what `mode` keeps; FALSE (and nothing
  /// constructed) if their RETAIN and PERSISTENT variables do not fit the retain memory.
  bool load(start_mode mode) {
    const retain_kinds wanted = kept_over(mode == start_mode::restart ? retain_event::restart : retain_event::download);
    iecoop::retain_status status;
    detail::retained_verdict verdict = detail::retained_verdict::nothing_found(wanted);
    retain_kinds ordered;
    std::size_t size = 0;
    if constexpr (retain_bytes > 0) {
      if (memory_.size > 0) {
        // This application's own last stop(): checked then, on the variables that wrote it.
        size = memory_.size;
        for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
          if (wanted.contains(kind)) verdict[kind] = memory_.own_verdict[kind];
        }
        ordered = memory_.own_order;
      } else if (memory_.storage.object != nullptr) {
        size = read_storage(wanted, verdict, status, ordered);
      }
    }
    status.retain = verdict.retain;
    status.persistent = verdict.persistent;
    // bInitRetains = FALSE where the RETAIN values are restored, checked before FB_Init runs.
    construct_restoring(!verdict.restorable().contains(retain_kind::retain), verdict, ordered, size, status);
    if (!retain_fits()) return false;
    if constexpr (retain_bytes > 0) memory_.size = 0;
    scheduler_.restart();
    return true;
  }

  /**
   * Constructs the instances (FB_Init with bInitRetains = `init_retains`) and restores the
   * kinds `verdict` found restorable in the first `size` bytes of the retain memory: for the
   * kinds in `ordered`, each variable as it is constructed, so that FB_Init sees the kept
   * values (CODESYS's order); for the others, after the construction (status
   * restored_after_init). Publishes `status` before FB_Init runs. If the construction turns
   * out to differ from the one the image was checked against (a constructor that makes its
   * remanent variables differently each time), the instances are ended and built again
   * without the values of that kind (status `changed`, a fault of kind invalid_value).
   */
  void construct_restoring(bool init_retains, detail::retained_verdict verdict, retain_kinds ordered, std::size_t size,
                           iecoop::retain_status status) {
    if constexpr (retain_bytes == 0) {  // nothing stored: constructed with the initial values
      publish(status);
      construct(init_retains);
    } else {
      const auto objects = store_.objects();
      const std::span<const std::byte> stored = retained_image(size);
      const retain_kinds restorable = size > 0 ? verdict.restorable() : retain_kinds::none;
      const retain_kinds early = restorable & ordered;
      retain_kinds late = without(restorable, early);
      status.restored_after_init = !late.empty();
      publish(status);
      retain_kinds failed;
      {
        const detail::retained_restore_session restoring(objects, early, stored);
        construct(init_retains);
        failed = without(restoring.kinds(), restoring.finish());
      }
      if (!failed.empty()) {
        destroy();
        for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
          if (failed.contains(kind)) verdict[kind] = retain_load::changed;
        }
        late = late | without(early, failed);
        status.retain = verdict.retain;
        status.persistent = verdict.persistent;
        status.restored_after_init = !late.empty();
        publish(status);
        construct(init_retains || failed.contains(retain_kind::retain));
      }
      if (!late.empty()) {
        // Checked again on the instances as they are now, then restored.
        const detail::retained_verdict found = detail::check_retained(objects, late, stored);
        (void)detail::restore_checked(objects, found, stored);
        for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
          if (late.contains(kind) && found[kind] != retain_load::restored) verdict[kind] = found[kind];
        }
        status.retain = verdict.retain;
        status.persistent = verdict.persistent;
        status.restored_after_init = detail::retained_count(objects, found.restorable()) > 0;
        publish(status);
      }
      if (!failed.empty()) {
        fault(
            fault_kind::invalid_value,
            "the RETAIN/PERSISTENT variables were constructed otherwise than when their values were saved (a "
            "constructor that makes them differently each time); the instances were built again without those values");
      }
    }
  }

  static constexpr retain_kinds without(retain_kinds kinds, retain_kinds removed) noexcept {
    retain_kinds rest;
    for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
      if (kinds.contains(kind) && !removed.contains(kind)) rest |= kind;
    }
    return rest;
  }

  [[nodiscard]] std::span<const std::byte> retained_image(std::size_t size) const noexcept {
    return std::span<const std::byte>(memory_.bytes.data(), size);
  }

  /// Reads the storage's image into the retain memory and checks it against the variables of
  /// a probe (the instances constructed without FB_Init, then destroyed without FB_Exit):
  /// the image's size, `verdict` for each kind in `wanted`, and in `ordered` the kinds whose
  /// variables the probe constructed in the image's order. A missing, empty, damaged or too
  /// large image gives way to the storage's previous one, if it has an intact one; a rejected
  /// image is set aside.
  std::size_t read_storage(retain_kinds wanted, detail::retained_verdict& verdict, iecoop::retain_status& status,
                           retain_kinds& ordered) {
    const auto mark_all = [&](retain_load load) {
      for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
        if (wanted.contains(kind)) verdict[kind] = load;
      }
    };
    std::size_t size = memory_.storage.load(memory_.storage.object, memory_.bytes);
    if (size > memory_.bytes.size()) size = 0;
    bool previous = false;
    bool rejected = false;  // the current image is set aside
    // The storage's previous image, where the current one is of no use: its size, or 0 if it
    // has none or none intact.
    const auto load_previous = [&]() -> std::size_t {
      if (memory_.storage.load_previous == nullptr) return 0;
      const std::size_t older = memory_.storage.load_previous(memory_.storage.object, memory_.bytes);
      if (older == 0 || older > memory_.bytes.size() ||
          !detail::valid_retained_image(std::span<const std::byte>(memory_.bytes.data(), older))) {
        return 0;
      }
      previous = true;
      return older;
    };
    if (size == 0) {
      // No current image: none stored, an empty one (its data lost), or one larger than the
      // retain memory. The previous image is the last one there is; only a storage with
      // neither is a first start.
      if (memory_.storage.stored_size != nullptr &&
          memory_.storage.stored_size(memory_.storage.object) > memory_.bytes.size()) {
        mark_all(retain_load::too_large);  // a valid image may be in it, but not one of this application
        rejected = true;
      }
      size = load_previous();
      if (size == 0 && !rejected) return 0;
    } else if (!detail::valid_retained_image(std::span<const std::byte>(memory_.bytes.data(), size))) {
      mark_all(retain_load::damaged);
      rejected = true;
      size = load_previous();
    }
    if (size > 0) {
      {
        const detail::lifecycle_scope probing({true, false, true, false, true});
        store_.construct_all();
        const detail::retained_verdict found =
            detail::check_retained(store_.objects(), wanted, std::span<const std::byte>(memory_.bytes.data(), size));
        ordered = detail::retained_in_construction_order(store_.objects(), wanted);
        store_.destroy_all();
        for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
          if (!wanted.contains(kind)) continue;
          verdict[kind] = found[kind];
          if (found[kind] == retain_load::restored && previous) verdict[kind] = retain_load::restored_previous;
          // A current image of other variables is set aside; a previous one stays where it is.
          if ((found[kind] == retain_load::changed || found[kind] == retain_load::invalid_value) && !previous) {
            rejected = true;
          }
        }
      }
    }
    if (rejected && memory_.storage.set_aside != nullptr)
      status.set_aside = memory_.storage.set_aside(memory_.storage.object);
    return size;
  }

  /// TRUE if the variables' image fits the retain memory; otherwise reports the fault, ends
  /// the instances (FB_Exit) and leaves the application stopped.
  bool retain_fits() {
    const std::size_t needed = detail::retained_image_size_needed(store_.objects());
    retain_bytes_needed_ = needed;
    if (needed <= retain_bytes) return true;
    destroy();
    fault(fault_kind::invalid_value,
          "the RETAIN and PERSISTENT variables need more retain memory than the application has; give it "
          "retain_capacity<N>{} with N at least application::retain_bytes_needed()");
    return false;
  }

  std::size_t save(retain_kinds kinds) {
    const auto objects = store_.objects();
    if (kinds.empty() || detail::retained_count(objects, kinds) == 0) return 0;
    return detail::save_retained(objects, kinds, memory_.bytes);
  }

  store_type store_;
  scheduler_type scheduler_;  // with the task_cycles, which call the programs in store_
  // The retain memory and what is known of its image; an application without retain memory
  // (retain_capacity<0>) has none of it: an empty member, no bytes.
  struct retain_memory {
    std::array<std::byte, retain_bytes> bytes{};
    std::size_t size = 0;                    // of the image the last stop() saved in `bytes`
    detail::retained_verdict own_verdict{};  // that image, checked on the variables that wrote it
    retain_kinds own_order{};                // the kinds those variables were constructed in the image's order
    storage_binding storage{};
  };
  struct no_retain_memory {};
  [[no_unique_address]] std::conditional_t<(retain_bytes > 0), retain_memory, no_retain_memory> memory_{};
  std::size_t retain_bytes_needed_ = 0;
  iecoop::retain_status retain_status_{};
  bool constructed_ = false;
};

template <class... Entries>
application(Entries...) -> application<Entries...>;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
