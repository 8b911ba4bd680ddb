// SPDX-License-Identifier: MIT
// iecoop/application.hpp — an application: the program instances, the tasks that run them,
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
// (<iecoop/realtime.hpp>) runs the same application against the steady clock.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/cycle_clock.hpp>
#include <iecoop/detail/lifecycle_state.hpp>
#include <iecoop/detail/ready_queues.hpp>
#include <iecoop/detail/single_instance.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/interface.hpp>
#include <iecoop/io.hpp>
#include <iecoop/lifecycle.hpp>
#include <iecoop/process_image.hpp>
#include <iecoop/program.hpp>
#include <iecoop/retain.hpp>
#include <iecoop/task.hpp>
#include <iecoop/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// Global variable lists (VAR_GLOBAL, with RETAIN and PERSISTENT members) the application owns:
/// it constructs them at start, resets them with the programs and keeps their retained values.
/// Reach one with application::get<GVL>(), or, from any POU, with GVL::instance() when the
/// list derives from global_variables<GVL> (<iecoop/global_variables.hpp>).
template <class... Lists>
struct globals {};

/// The process image the application's tasks latch (default_process_image if not given).
template <class Image>
struct use_image {};

/// The bytes the application keeps for RETAIN and PERSISTENT values over a reset or a stop
/// (its retain memory); 1024 if not given.
template <std::size_t Bytes>
struct retain_capacity {};

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

template <class App>
class realtime_runner;

/**
 * A task as the application runs it: its settings, its statistics, and the execution time a
 * simulation gives its cycles.
 */
class task_state {
 public:
  [[nodiscard]] const char* name() const noexcept { return settings_.name; }
  [[nodiscard]] task_kind kind() const noexcept { return settings_.kind; }
  [[nodiscard]] std::uint8_t priority() const noexcept { return settings_.priority; }
  [[nodiscard]] LTIME interval() const noexcept { return settings_.interval; }
  [[nodiscard]] const task_settings& settings() const noexcept { return settings_; }

  [[nodiscard]] const task_statistics& statistics() const noexcept { return statistics_; }
  /// Starts the statistics afresh (CODESYS: IecTaskResetStatistics).
  void reset_statistics() noexcept { statistics_ = task_statistics{}; }

  /// TRUE while a cycle is released or under way.
  [[nodiscard]] bool busy() const noexcept { return released_ || active_; }

  /// In simulation, each cycle of this task takes `each_cycle` of processor time.
  void model_execution_time(LTIME each_cycle) noexcept {
    cost_constant_ = each_cycle;
    cost_function_ = nullptr;
  }
  /// In simulation, cycle number n (0, 1, ... since start) takes cost(n, context).
  void model_execution_time(LTIME (*cost)(std::uint64_t cycle, void* context), void* context = nullptr) noexcept {
    cost_function_ = cost;
    cost_context_ = context;
  }

 private:
  template <class...>
  friend class application;
  template <class>
  friend class realtime_runner;

  [[nodiscard]] LTIME cost_of(std::uint64_t cycle) const {
    return cost_function_ != nullptr ? cost_function_(cycle, cost_context_) : cost_constant_;
  }
  // Forget the cycle under way and the releases (a stop, reset or exception).
  void clear_schedule() noexcept {
    released_ = active_ = false;
    remaining_ = LTIME{};
  }

  task_settings settings_{};
  task_statistics statistics_{};
  // Scheduling.
  LTIME next_release_ = LTIME::max();  // cyclic and freewheeling tasks
  LTIME release_time_{};
  LTIME start_time_{};
  LTIME remaining_{};  // simulated processor time the running cycle still needs
  std::uint64_t cycle_number_ = 0;
  std::uint32_t watchdog_streak_ = 0;  // watchdog overruns in a row
  bool released_ = false;
  bool active_ = false;
  bool event_previous_ = false;
  // Execution time model.
  LTIME cost_constant_{};
  LTIME (*cost_function_)(std::uint64_t, void*) = nullptr;
  void* cost_context_ = nullptr;
};

namespace detail {

// type_list<...> comes from <iecoop/interface.hpp> (through lifecycle.hpp).

/// a + b, or LTIME::max() (which the scheduler treats as "never") if that would wrap.
constexpr LTIME add_saturated(LTIME a, LTIME b) noexcept { return b > LTIME::max() - a ? LTIME::max() : a + b; }

template <class List, class T>
struct push_unique;
template <class... Ts, class T>
struct push_unique<type_list<Ts...>, T> {
  using type = std::conditional_t<occurs_in<T, Ts...>, type_list<Ts...>, type_list<Ts..., T>>;
};
template <class List, class... Ts>
struct push_all {
  using type = List;
};
template <class List, class T, class... Ts>
struct push_all<List, T, Ts...> : push_all<typename push_unique<List, T>::type, Ts...> {};

// What an application entry is.
template <class E>
struct entry {
  static constexpr bool is_task = false, is_globals = false, is_image = false, is_capacity = false;
};
template <class... P>
struct entry<task<P...>> {
  static constexpr bool is_task = true, is_globals = false, is_image = false, is_capacity = false;
};
template <class... G>
struct entry<globals<G...>> {
  static constexpr bool is_task = false, is_globals = true, is_image = false, is_capacity = false;
};
template <class I>
struct entry<use_image<I>> {
  static constexpr bool is_task = false, is_globals = false, is_image = true, is_capacity = false;
};
template <std::size_t N>
struct entry<retain_capacity<N>> {
  static constexpr bool is_task = false, is_globals = false, is_image = false, is_capacity = true;
};

template <class E>
constexpr void check_entry() {
  using e = entry<E>;
  if constexpr (!(e::is_task || e::is_globals || e::is_image || e::is_capacity)) {
    static_assert(!program_type<E>,
                  "iecoop: a PROGRAM is assigned to no task; name it in a task (task<PRG>{\"Main\", cyclic{\"T#10ms\"_iec}, 1}) — "
                  "a program that only other POUs call is declared as an ordinary variable");
    static_assert(program_type<E>,
                  "iecoop: an application is made of task<...>{...}, globals<...>{}, use_image<...>{} and retain_capacity<N>{}");
  }
}

// The instances an application owns: its global variable lists first, then every program of
// its tasks, each once, in order of first mention.
template <class List, class E>
struct add_globals {
  using type = List;
};
template <class List, class... G>
struct add_globals<List, globals<G...>> : push_all<List, G...> {};
template <class List, class E>
struct add_programs {
  using type = List;
};
template <class List, class... P>
struct add_programs<List, task<P...>> : push_all<List, P...> {};

template <template <class, class> class Step, class List, class... Es>
struct fold_entries {
  using type = List;
};
template <template <class, class> class Step, class List, class E, class... Es>
struct fold_entries<Step, List, E, Es...> : fold_entries<Step, typename Step<List, E>::type, Es...> {};

template <class List, class E>
struct add_task {
  using type = List;
};
template <class... Ts, class... P>
struct add_task<type_list<Ts...>, task<P...>> {
  using type = type_list<Ts..., task<P...>>;
};

template <class Default, class... Es>
struct image_of {
  using type = Default;
};
template <class Default, class I, class... Es>
struct image_of<Default, use_image<I>, Es...> {
  using type = I;
};
template <class Default, class E, class... Es>
struct image_of<Default, E, Es...> : image_of<Default, Es...> {};

template <std::size_t Default, class... Es>
struct retain_capacity_of : std::integral_constant<std::size_t, Default> {};
template <std::size_t Default, std::size_t N, class... Es>
struct retain_capacity_of<Default, retain_capacity<N>, Es...> : std::integral_constant<std::size_t, N> {};
template <std::size_t Default, class E, class... Es>
struct retain_capacity_of<Default, E, Es...> : retain_capacity_of<Default, Es...> {};

template <class T>
struct instance_slot {
  alignas(T) std::byte bytes[sizeof(T)];
};

/// Raw storage for the application's instances, constructed and destroyed as a whole.
template <class List>
class instance_store;
template <class... Ts>
class instance_store<type_list<Ts...>> {
 public:
  template <class T>
  [[nodiscard]] T& get() noexcept {
    return *std::launder(reinterpret_cast<T*>(std::get<instance_slot<T>>(slots_).bytes));
  }
  void construct_all() { (std::construct_at(reinterpret_cast<Ts*>(std::get<instance_slot<Ts>>(slots_).bytes)), ...); }
  void destroy_all() { destroy_reversed(std::make_index_sequence<sizeof...(Ts)>{}); }

  /// Where each instance lives, for saving and restoring its retained variables.
  [[nodiscard]] std::array<retained_object, sizeof...(Ts)> objects() const noexcept {
    return {retained_object{std::get<instance_slot<Ts>>(slots_).bytes, sizeof(Ts)}...};
  }

 private:
  template <std::size_t... I>
  void destroy_reversed(std::index_sequence<I...>) {
    using types = std::tuple<Ts...>;
    (std::destroy_at(&get<std::tuple_element_t<sizeof...(Ts) - 1 - I, types>>()), ...);
  }

  std::tuple<instance_slot<Ts>...> slots_;
};

template <class Store, class Task>
struct task_programs;
template <class Store, class... P>
struct task_programs<Store, task<P...>> {
  static void run(Store& store) { (store.template get<P>()(), ...); }
};

template <class Image, class... Objects>
struct located_check;
template <class Image, class... Objects>
struct located_check<Image, type_list<Objects...>> {
  template <auto... Members>
  static constexpr bool in_image(pins<Members...>) noexcept {
    return (std::is_same_v<typename located_type_of<Members>::image_type, Image> && ...);
  }
  static constexpr void run() {
    check_located<Objects...>();
    using list = all_located_t<Objects...>;
    if constexpr (all_located(list{})) {
      static_assert(in_image(list{}),
                    "iecoop: a located variable of the application's programs or global variable lists lies in another "
                    "process image than the application's; give it the application's image: located<T, \"%...\", Image>, "
                    "with Image as in use_image<Image>{}");
    }
  }
};

}  // namespace detail

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
  static constexpr bool entries_valid = ((detail::check_entry<Entries>(), true) && ...);
  static_assert((0 + ... + (detail::entry<Entries>::is_image ? 1 : 0)) <= 1,
                "iecoop: an application has one process image; give use_image<...>{} once");
  static_assert((0 + ... + (detail::entry<Entries>::is_capacity ? 1 : 0)) <= 1,
                "iecoop: an application has one retain memory; give retain_capacity<N>{} once");
  using globals_list = typename detail::fold_entries<detail::add_globals, detail::type_list<>, Entries...>::type;
  using owned_list = typename detail::fold_entries<detail::add_programs, globals_list, Entries...>::type;
  using task_list = typename detail::fold_entries<detail::add_task, detail::type_list<>, Entries...>::type;
  using store_type = detail::instance_store<owned_list>;

  template <class List>
  struct count;
  template <class... Ts>
  struct count<detail::type_list<Ts...>> : std::integral_constant<std::size_t, sizeof...(Ts)> {};
  static constexpr std::size_t task_count_ = count<task_list>::value;
  static_assert(task_count_ > 0, "iecoop: an application needs at least one task; add task<PRG>{...}");

  template <class List>
  struct run_table;
  template <class... Tasks>
  struct run_table<detail::type_list<Tasks...>> {
    static constexpr std::array<void (*)(store_type&), sizeof...(Tasks)> value{&detail::task_programs<store_type, Tasks>::run...};
  };

  template <class T, class List>
  struct owns;
  template <class T, class... Ts>
  struct owns<T, detail::type_list<Ts...>> : std::bool_constant<detail::occurs_in<T, Ts...>> {};

 public:
  /// The process image the tasks latch and write.
  using image = typename detail::image_of<default_process_image, Entries...>::type;
  /// Bytes of retain memory.
  static constexpr std::size_t retain_bytes = detail::retain_capacity_of<1024, Entries...>::value;

  explicit application(Entries... entries) {
    static_assert(entries_valid);
    detail::located_check<image, owned_list>::run();
    std::size_t i = 0;
    (
        [&] {
          if constexpr (detail::entry<Entries>::is_task) tasks_[i++].settings_ = entries.settings();
        }(),
        ...);
    for (const task_state& t : tasks_) has_event_tasks_ = has_event_tasks_ || t.settings_.kind == task_kind::event;
  }
  application(const application&) = delete;
  application& operator=(const application&) = delete;
  /// Stops the application (FB_Exit of every instance, retained data saved) if it runs.
  ~application() { stop(); }

  // --- Lifecycle --------------------------------------------------------------------

  /**
   * Starts the tasks. If the instances do not exist yet (first start, or after stop()), they
   * are constructed first — FB_Init runs for each, with bInitRetains = FALSE if retained data
   * was found (in the retain memory from this application's last stop, else in the attached
   * storage) and TRUE otherwise — and the retained values are restored (`mode` says which). After a reset,
   * start() continues with the existing instances; cyclic and freewheeling tasks are released
   * from now() on. On a running application it does nothing. Returns FALSE in the exception
   * state (reset first).
   */
  bool start(start_mode mode = start_mode::restart) {
    if (state_ == application_state::exception) return false;
    if (state_ == application_state::running) return true;
    if (state_ == application_state::stopped) load(mode);
    state_ = application_state::running;
    for (task_state& t : tasks_) {
      if (t.settings_.kind != task_kind::event) t.next_release_ = now_;
    }
    return true;
  }

  /// Stops the tasks and ends the instances: saves the RETAIN and PERSISTENT values (to the
  /// retain memory and the attached storage), then FB_Exit of every instance. The next
  /// start() is a controller restart.
  void stop() {
    if (state_ == application_state::stopped) return;
    const std::size_t size = save(retain_kinds::both);
    retain_size_ = size;
    if (size > 0 && storage_.object != nullptr &&
        !storage_.save(storage_.object, std::span<const std::byte>(retain_memory_.data(), size))) {
      fault(fault_kind::invalid_value, "the storage did not save the RETAIN/PERSISTENT data; a restart in another process starts without it (or with older data)");
    }
    {
      detail::lifecycle_scope exiting({true, false, false, false});
      store_.destroy_all();
    }
    clear_schedules();
    faulted_task_ = nullptr;
    state_ = application_state::stopped;
  }

  /**
   * Resets the application as CODESYS's Reset warm / cold / origin: FB_Exit of every
   * instance, then FB_Init (bInitRetains = FALSE for warm, TRUE otherwise); a warm reset
   * keeps RETAIN and PERSISTENT values, a cold one PERSISTENT values, origin none. The
   * process image is cleared, the task statistics start afresh, an exception is cleared,
   * and the application is halted: start() runs the tasks again. Does nothing when stopped.
   */
  void reset(reset_kind kind) {
    if (state_ == application_state::stopped) return;
    const retain_kinds keep = kept_over(kind == reset_kind::warm   ? retain_event::warm_reset
                                        : kind == reset_kind::cold ? retain_event::cold_reset
                                                                   : retain_event::origin_reset);
    const std::size_t size = save(keep);
    {
      detail::lifecycle_scope exiting({true, false, false, false});
      store_.destroy_all();
    }
    construct(kind != reset_kind::warm);
    if (size > 0) restore(keep, size);
    restart_tasks();
    state_ = application_state::halted;
  }

  [[nodiscard]] application_state state() const noexcept { return state_; }

  // --- Simulated time ---------------------------------------------------------------

  /// The simulated time: how long the application has run since it was created.
  [[nodiscard]] LTIME now() const noexcept { return now_; }

  /// Runs every task that is due in [now(), now() + duration), in priority order, and
  /// leaves now() at the end of that span. Time passes also while the tasks do not run.
  void run_for(LTIME duration) { run_until(detail::add_saturated(now_, duration)); }

  /// Runs every task that is due before `until` (see run_for).
  void run_until(LTIME until) {
    if (until <= now_) return;
    while (state_ == application_state::running) {
      process_instant();
      const LTIME next = next_instant();
      if (next >= until || state_ != application_state::running) break;
      advance_to(next);
    }
    advance_to(until);
  }

  /// Runs `n` base cycles: n times the shortest cyclic interval (1 ms without cyclic tasks).
  void run_cycles(std::uint64_t n) { run_for(base_cycle() * n); }

  /// The shortest interval of a cyclic task, or 1 ms without one.
  [[nodiscard]] LTIME base_cycle() const noexcept {
    LTIME base = LTIME::max();
    for (const task_state& t : tasks_) {
      if (t.settings_.kind == task_kind::cyclic && t.settings_.interval < base) base = t.settings_.interval;
    }
    return base == LTIME::max() ? LTIME(TIME(1)) : base;
  }

  // --- Tasks and instances ----------------------------------------------------------

  [[nodiscard]] static constexpr std::size_t task_count() noexcept { return task_count_; }
  /// The task at `index` in the configuration; an index out of range reports
  /// fault_kind::invalid_value and yields the first task.
  [[nodiscard]] task_state& task(std::size_t index) noexcept { return tasks_[checked_index(index)]; }
  [[nodiscard]] const task_state& task(std::size_t index) const noexcept { return tasks_[checked_index(index)]; }
  /// The task called `name`; an unknown name reports fault_kind::invalid_value and yields the first task.
  [[nodiscard]] task_state& task(std::string_view name) noexcept {
    for (task_state& t : tasks_) {
      if (name == t.settings_.name) return t;
    }
    fault(fault_kind::invalid_value, "no task of this name in the application; the first task stands in");
    return tasks_[0];
  }
  [[nodiscard]] std::span<task_state, task_count_> tasks() noexcept { return tasks_; }
  [[nodiscard]] std::span<const task_state, task_count_> tasks() const noexcept { return tasks_; }

  /// The task whose watchdog stopped the application, or nullptr.
  [[nodiscard]] const task_state* faulted_task() const noexcept { return faulted_task_; }

  /// The application's instance of program or global variable list T. Before start() (or
  /// after stop()) it reports fault_kind::invalid_value and yields a scratch instance.
  template <class T>
  [[nodiscard]] T& get() {
    static_assert(owns<T, owned_list>::value,
                  "iecoop: the application owns no instance of this type; name the program in a task, or the list in globals<...>");
    if (state_ != application_state::stopped) return store_.template get<T>();
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

  // --- I/O, storage, settings ------------------------------------------------------------

  /// Uses `driver` for the I/O from now on: its inputs are latched at the start of each task
  /// cycle, the outputs a cycle changed are written at its end. The driver must outlive its use.
  template <IoDriver D>
  void connect(D& driver) noexcept {
    io_ = callback_io{[](std::span<std::byte> in, void* d) { static_cast<D*>(d)->read_inputs(in); },
                      [](std::span<const std::byte> out, void* d) { static_cast<D*>(d)->write_outputs(out); }, &driver};
  }

  /// Saves retained data to `storage` at stop() and reads it at the start() that constructs
  /// the instances (a controller restart, possibly of another process). Must outlive its use.
  template <RetainStorage S>
  void use_storage(S& storage) noexcept {
    storage_.object = &storage;
    storage_.save = [](void* s, std::span<const std::byte> data) { return static_cast<S*>(s)->save(data); };
    storage_.load = [](void* s, std::span<std::byte> buffer) { return static_cast<std::size_t>(static_cast<S*>(s)->load(buffer)); };
  }

  /// Saves the RETAIN and PERSISTENT values to the attached storage now (as TwinCAT's
  /// FB_WritePersistentData). FALSE without storage, instances or room.
  bool save_retained() {
    if (storage_.object == nullptr || state_ == application_state::stopped) return false;
    const std::size_t size = save(retain_kinds::both);
    return size > 0 && storage_.save(storage_.object, std::span<const std::byte>(retain_memory_.data(), size));
  }

  /// The processor load freewheeling tasks may use, in percent (CODESYS: 80 by default).
  /// A freewheeling task pauses after each cycle for cycle time x (100 - L) / L, at least
  /// 1 ms, where L = min(100, percent) / 2 / (number of freewheeling tasks).
  void set_freewheeling_load(unsigned percent) noexcept { freewheeling_load_ = percent == 0 ? 1 : percent; }

  /// The outputs as last written to the driver (what the field sees).
  [[nodiscard]] std::span<const std::byte, image::output_bytes> published_outputs() const noexcept { return published_; }

 private:
  template <class>
  friend class realtime_runner;

  static constexpr std::size_t no_task = task_count_;

  static std::size_t checked_index(std::size_t index) noexcept {
    if (index < task_count_) return index;
    fault(fault_kind::invalid_value, "no task at this index in the application; the first task stands in");
    return 0;
  }
  static constexpr std::size_t output_bytes = image::output_bytes;

  struct storage_binding {
    void* object = nullptr;
    bool (*save)(void*, std::span<const std::byte>) = nullptr;
    std::size_t (*load)(void*, std::span<std::byte>) = nullptr;
  };
  // The outputs one cycle changed, to be written at its end.
  struct staged_outputs {
    std::array<std::byte, output_bytes> value{};
    std::array<std::byte, output_bytes> mask{};
  };

  // --- Lifecycle helpers ---

  void construct(bool init_retains) {
    image::clear();
    detail::lifecycle_scope initialising({init_retains, false, false, false});
    store_.construct_all();
    // What the constructors wrote to %Q (FB_Init, a located output's initial value) goes out
    // with the first cycle's outputs.
    if constexpr (output_bytes > 0) std::memcpy(published_.data(), image::outputs().data(), output_bytes);
  }

  void load(start_mode mode) {
    // The retain memory holds this application's last stop(): never older than the storage,
    // which may have failed to save it. A new application (a new process) has none yet.
    std::size_t size = retain_size_;
    if (size == 0 && storage_.object != nullptr) {
      size = storage_.load(storage_.object, retain_memory_);
      if (size > retain_memory_.size()) size = 0;
    }
    const retain_kinds keep =
        size == 0 ? retain_kinds::none : kept_over(mode == start_mode::restart ? retain_event::restart : retain_event::download);
    construct(!keep.contains(retain_kind::retain));
    if (size > 0) restore(keep, size);
    restart_tasks();
  }

  // The tasks as after a download: no cycle under way, statistics and event memories cleared.
  void restart_tasks() noexcept {
    clear_schedules();
    for (task_state& t : tasks_) {
      t.reset_statistics();
      t.watchdog_streak_ = 0;
      t.cycle_number_ = 0;
      t.event_previous_ = false;
    }
    running_ = no_task;
    faulted_task_ = nullptr;
  }

  std::size_t save(retain_kinds kinds) {
    const auto objects = store_.objects();
    if (kinds.empty() || detail::retained_count(objects, kinds) == 0) return 0;
    return detail::save_retained(objects, kinds, retain_memory_);
  }
  void restore(retain_kinds kinds, std::size_t size) {
    const auto objects = store_.objects();
    (void)detail::restore_retained(objects, kinds, std::span<const std::byte>(retain_memory_.data(), size));
  }

  // --- One task cycle ---

  /// A cycle starts: inputs latched, the cycle clock set, the programs called, the outputs
  /// they changed staged for the cycle's end.
  void begin_cycle(std::size_t index, LTIME now) {
    task_state& t = tasks_[index];
    t.released_ = false;
    t.active_ = true;
    ready_.begin(index, t.settings_.priority);
    t.start_time_ = now;
    t.remaining_ = t.cost_of(t.cycle_number_);
    ++t.cycle_number_;
    io_.read_inputs(image::inputs());
    cycle_clock::set(now);
    if constexpr (output_bytes == 0) {
      run_table<task_list>::value[index](store_);
    } else {
      const auto outputs = image::outputs();
      std::array<std::byte, output_bytes> before;
      std::memcpy(before.data(), outputs.data(), output_bytes);
      run_table<task_list>::value[index](store_);
      staged_outputs& staged = staged_[index];
      for (std::size_t b = 0; b < output_bytes; ++b) {
        staged.value[b] = outputs[b];
        staged.mask[b] = before[b] ^ outputs[b];
      }
    }
  }

  /// A cycle ends: its outputs written, the statistics and the watchdog updated.
  void end_cycle(std::size_t index, LTIME now) {
    task_state& t = tasks_[index];
    t.active_ = false;
    ready_.end(t.settings_.priority);
    t.remaining_ = LTIME{};
    staged_outputs& staged = staged_[index];
    for (std::size_t b = 0; b < output_bytes; ++b) {
      published_[b] = (published_[b] & ~staged.mask[b]) | (staged.value[b] & staged.mask[b]);
    }
    io_.write_outputs(published_);
    const LTIME cycle_time = now - t.start_time_;
    t.statistics_.record(t.start_time_ - t.release_time_, cycle_time);
    if (t.settings_.kind == task_kind::freewheeling) t.next_release_ = detail::add_saturated(now, freewheeling_pause(cycle_time));
    if (t.settings_.has_watchdog) check_watchdog(t, cycle_time);
  }

  void check_watchdog(task_state& t, LTIME cycle_time) {
    // The streak is kept apart from the statistics, which a user may reset at any time.
    task_statistics& s = t.statistics_;
    if (cycle_time <= t.settings_.watchdog_time) {
      t.watchdog_streak_ = 0;
      s.consecutive_watchdog_overruns = 0;
      return;
    }
    ++s.watchdog_overruns;
    s.consecutive_watchdog_overruns = ++t.watchdog_streak_;
    const unsigned sensitivity = t.settings_.watchdog_sensitivity;
    const LTIME watchdog_time = t.settings_.watchdog_time;
    const bool single_timeout =
        watchdog_time.count() <= LTIME::max().count() / sensitivity && cycle_time > watchdog_time * sensitivity;
    if (t.watchdog_streak_ >= sensitivity || single_timeout) {
      state_ = application_state::exception;
      faulted_task_ = &t;
      clear_schedules();
      fault(fault_kind::watchdog, "a task cycle overran its watchdog (time x sensitivity); the application stopped in exception");
    }
  }

  [[nodiscard]] LTIME freewheeling_pause(LTIME cycle_time) const noexcept {
    std::uint64_t freewheeling_tasks = 0;
    for (const task_state& t : tasks_) freewheeling_tasks += t.settings_.kind == task_kind::freewheeling ? 1 : 0;
    const std::uint64_t max_load = freewheeling_load_ < 100 ? freewheeling_load_ : 100;
    // L = max_load / 2 / n percent; pause = cycle x (100 - L) / L = cycle x (200 n - max_load) / max_load.
    const std::uint64_t numerator = 200 * freewheeling_tasks - max_load;
    const LTIME pause = LTIME::from_ticks(cycle_time.count() / max_load * numerator + cycle_time.count() % max_load * numerator / max_load);
    const LTIME minimum = LTIME(TIME(1));
    return pause < minimum ? minimum : pause;
  }

  // --- Releases and dispatch ---

  /// Releases every cyclic or freewheeling task due at `now` and every event task whose
  /// condition rose. A release that finds the previous cycle unfinished is skipped (an overrun).
  void release_due(LTIME now) {
    for (task_state& t : tasks_) {
      if (t.settings_.kind == task_kind::event || t.next_release_ > now) continue;
      release(static_cast<std::size_t>(&t - tasks_.data()), t.next_release_);
      if (t.settings_.kind == task_kind::cyclic) {
        t.next_release_ = detail::add_saturated(t.next_release_, t.settings_.interval);
        if (t.next_release_ <= now) {  // releases missed while late: omitted
          const std::uint64_t missed = (now - t.next_release_).count() / t.settings_.interval.count() + 1;
          t.statistics_.overruns += missed;
          t.statistics_.consecutive_overruns += static_cast<std::uint32_t>(missed);
          t.next_release_ = detail::add_saturated(t.next_release_, t.settings_.interval * missed);
        }
      } else {
        t.next_release_ = LTIME::max();  // freewheeling: released again when the cycle ends
      }
    }
    sample_events(now);
  }

  void sample_events(LTIME now) {
    if (!has_event_tasks_) return;
    for (task_state& t : tasks_) {
      if (t.settings_.kind != task_kind::event) continue;
      const bool value = static_cast<bool>(t.settings_.trigger.read());
      if (value && !t.event_previous_) release(static_cast<std::size_t>(&t - tasks_.data()), now);
      t.event_previous_ = value;
    }
  }

  void release(std::size_t index, LTIME at) noexcept {
    task_state& t = tasks_[index];
    if (t.busy()) {
      ++t.statistics_.overruns;
      ++t.statistics_.consecutive_overruns;
      return;
    }
    t.released_ = true;
    t.release_time_ = at;
    t.statistics_.consecutive_overruns = 0;
    ready_.release(index, t.settings_.priority, [this](std::size_t a, std::size_t b) {
      return tasks_[a].release_time_ < tasks_[b].release_time_ ||
             (tasks_[a].release_time_ == tasks_[b].release_time_ && a < b);
    });
  }

  /// The task that gets the processor: the highest priority among those released or under
  /// way; among equals, the one under way before those released, then the earlier release,
  /// then the first in the configuration. no_task if none. O(1): ready_ keeps the released
  /// tasks of each priority in that order.
  [[nodiscard]] std::size_t pick() const noexcept { return ready_.pick(); }

  // Forget every release and cycle under way (a stop, a reset, an exception).
  void clear_schedules() noexcept {
    for (task_state& t : tasks_) t.clear_schedule();
    ready_.clear();
    running_ = no_task;
  }

  /// Everything that happens at now_: the running cycle ends if its time is used up, tasks
  /// are released, and the processor goes to the highest-priority task — whose cycle starts
  /// if it had not (and the choice is made again, as the cycle's code may have raised an
  /// event); cycles that take no time end at once.
  void process_instant() {
    if (running_ != no_task && tasks_[running_].remaining_ == LTIME{}) {
      const std::size_t done = running_;
      running_ = no_task;
      end_cycle(done, now_);
    }
    if (state_ != application_state::running) return;
    release_due(now_);
    while (state_ == application_state::running) {
      const std::size_t next = pick();
      if (next == no_task) break;
      task_state& t = tasks_[next];
      if (!t.active_) {
        begin_cycle(next, now_);
        sample_events(now_);  // its code may have raised an event of a higher-priority task:
        continue;             // that one preempts the cycle right away
      }
      if (t.remaining_ != LTIME{}) {
        running_ = next;
        return;
      }
      end_cycle(next, now_);
      sample_events(now_);  // a condition may read what the cycle's end wrote to the field
    }
    running_ = no_task;
  }

  /// Ends, at `now`, the cycles a simulation left under way (for a runner that takes over).
  void finish_cycles(LTIME now) {
    running_ = no_task;
    for (std::size_t i = 0; i < task_count_; ++i) {
      if (tasks_[i].active_ && state_ == application_state::running) end_cycle(i, now);
    }
  }

  /// The earliest release of a cyclic or freewheeling task (LTIME::max() if none is pending).
  [[nodiscard]] LTIME next_release() const noexcept {
    LTIME next = LTIME::max();
    for (const task_state& t : tasks_) {
      if (t.next_release_ < next) next = t.next_release_;
    }
    return next;
  }

  /// The next instant where something happens: the running cycle ends or a task is released.
  [[nodiscard]] LTIME next_instant() const noexcept {
    const LTIME release = next_release();
    if (running_ == no_task) return release;
    const LTIME end = detail::add_saturated(now_, tasks_[running_].remaining_);
    return end < release ? end : release;
  }

  void advance_to(LTIME t) noexcept {
    if (running_ != no_task) {
      task_state& r = tasks_[running_];
      const LTIME spent = t - now_;
      r.remaining_ = spent < r.remaining_ ? r.remaining_ - spent : LTIME{};
    }
    now_ = t;
  }

  store_type store_;
  std::array<task_state, task_count_> tasks_{};
  std::array<staged_outputs, task_count_> staged_{};
  std::array<std::byte, output_bytes> published_{};
  std::array<std::byte, retain_bytes> retain_memory_{};
  std::size_t retain_size_ = 0;
  callback_io io_{};  // the connected driver; without one, nothing is read or written
  storage_binding storage_{};
  LTIME now_{};
  std::size_t running_ = no_task;
  detail::ready_queues<task_count_> ready_{};
  const task_state* faulted_task_ = nullptr;
  unsigned freewheeling_load_ = 80;
  bool has_event_tasks_ = false;
  application_state state_ = application_state::stopped;
};

template <class... Entries>
application(Entries...) -> application<Entries...>;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
