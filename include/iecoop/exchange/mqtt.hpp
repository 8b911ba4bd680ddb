// SPDX-License-Identifier: MIT
// iecoop/exchange/mqtt.hpp — an MQTT bridge, as CODESYS's IIoT Libraries' MQTT client or TwinCAT's
// Tc3_IotBase: named variables (the channels of a trace, <iecoop/trace/channels.hpp>) published
// to a broker on change and/or cyclically, as JSON, with the controller's online/offline status
// as last will; and commands: variables an HMI, a cloud service or another controller writes
// through `<prefix>/<name>/set`, checked, queued and written at the start of a task cycle.
// Built on libmosquitto (Debian: libmosquitto-dev); link the CMake target iecoop::mqtt.
//
//     mqtt_bridge<> mqtt{{.host = "broker.local", .client_id = "line1-plc", .topic_prefix = "plant/line1"}};
//     mqtt.add("IO_PRG.bStart", io.bStart);              // plant/line1/IO_PRG/bStart
//     mqtt.add_pins("IO_PRG.fbConveyor", io.fbConveyor);  // plant/line1/IO_PRG/fbConveyor/xEnable, ...
//     mqtt.command("IO_PRG.iSpeed", io.iSpeed, 0, 3000); // plant/line1/IO_PRG/iSpeed/set
//     mqtt.attach(plc.task("Fast"));                      // captured after, commands before each cycle
//     if (const char* error = mqtt.start()) { std::puts(error); return 1; }
//     ...
//     mqtt.stop();                                        // publishes "offline", disconnects
//
// A value is published as `{"value":<v>,"type":"<IEC type>","cycle":<n>}` on
// `<prefix>/<scope/name>` (the channel's name with '/' for '.'), retained by default: BOOL as
// true/false, integers and bit strings as decimal numbers, REAL and LREAL as the shortest
// number that reads back (NaN and infinities as null), TIME, LTIME, dates, times of day and
// enumerations as strings of their IEC text ("T#1s500ms", "Run"). `<prefix>/status` is
// "online" (retained) from every connect on, and "offline" after stop() or, as last will,
// when the controller vanishes without disconnecting.
//
// A command's payload is a bare JSON scalar or IEC literal (`true`, `FALSE`, `42`, `16#FF`,
// `-3.5`, `T#2s`), a JSON string holding one (`"T#2s"`, `"Run"`), or `{"value": ...}` with
// either; it is parsed as ST parses the variable's type (its range too, and the command's
// min/max). A command that is malformed, out of range, names no command or is a retained message
// replayed at a subscription is not written: it is counted, and `<topic>/rejected` (not retained,
// always valid JSON) says why. Accepted commands
// queue (command_queue of them; one more is dropped, counted) and are written in order at the
// start of the attached task's next cycles, after the inputs were latched and before the
// programs run; a second command for a variable waits for the next cycle, so that the program
// sees TRUE then FALSE for a cycle each.
//
// Threads. The task's side — after each cycle of the attached task a copy of every channel's
// value into a snapshot, before each cycle the queued commands written — takes no lock, makes
// no system call and allocates nothing: snapshots go to the bridge through a triple buffer, commands
// come through a single-producer single-consumer ring of fixed size; neither side ever waits
// for the other. The bridge's own thread (one, started by start()) runs libmosquitto's network
// loop, connects and reconnects (with back-off), formats and publishes, parses commands and
// allocates as it likes. It looks for a new snapshot every `check_interval`: a value that
// changes and changes back between two looks is not published (changes are coalesced; the
// newest value always is). For Linux and other POSIX systems; not part of <iecoop/iecoop.hpp>.
//
// Sparkplug B (Eclipse Tahu's topics and protobuf payloads) is not implemented: it needs
// protobuf, which iecoop does not depend on.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include <iecoop/config.hpp>
#include <iecoop/detail/chrono.hpp>  // std::chrono's durations and clocks
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/exchange/detail/mqtt_commands.hpp>
#include <iecoop/exchange/detail/mqtt_json.hpp>
#include <iecoop/exchange/mqtt_library.hpp>
#include <iecoop/exchange/triple_buffer.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/io/located.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/runtime/cycle_observer.hpp>
#include <iecoop/runtime/scheduler.hpp>
#include <iecoop/trace/channels.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * The configuration of an MQTT bridge, as the CODESYS IIoT Libraries' MQTTClient gives it
 * (sHostname, uiPort, sClientId, sUsername, sPassword, uiKeepAlive, xCleanSession) and what it
 * publishes.
 */
struct mqtt_bridge_config {
  std::string host = "localhost";  ///< the broker's name or address
  std::uint16_t port = 1883;
  /// The client identifier, unique on the broker (a second client with the same one takes
  /// over the session: the first is disconnected). Empty: libmosquitto makes a random one.
  std::string client_id{};
  std::string username{};  ///< empty: none
  std::string password{};
  /// The topics' root: `plant/line1` gives `plant/line1/IO_PRG/bStart`, `plant/line1/status`.
  std::string topic_prefix = "iecoop";
  int qos = 1;                    ///< QoS of the values, the status and the rejections: 0, 1 or 2
  bool retain = true;             ///< values retained: a client that subscribes later gets the newest at once
  int command_qos = 1;            ///< QoS of the subscriptions to the commands' `/set` topics (2: exactly once)
  bool publish_on_change = true;  ///< a value that differs from the one last published
  LTIME publish_period{0};        ///< every channel, every period (0: not cyclically)
  /// How often the bridge's thread looks for a new snapshot (and the longest it may take to
  /// notice a stop()): changes between two looks are coalesced.
  LTIME check_interval{10'000'000};
  std::uint16_t keepalive = 10;  ///< seconds (libmosquitto: at least 5); a silent broker is given up within 2 x this
  LTIME reconnect_min{1'000'000'000};   ///< the first wait after a failed or lost connection
  LTIME reconnect_max{30'000'000'000};  ///< the wait doubles after each failed attempt, up to this
  std::size_t command_queue = 64;       ///< commands accepted and not yet written; one more is dropped
  LTIME stop_timeout{1'000'000'000};    ///< how long stop() waits for the broker to take "offline"
};

/// What an MQTT bridge did since start(); read any time, from any thread.
struct mqtt_bridge_statistics {
  std::uint64_t published = 0;          ///< messages handed to the connection (values, status, rejections)
  std::uint64_t publish_errors = 0;     ///< messages libmosquitto refused (the connection went meanwhile)
  std::uint64_t snapshots = 0;          ///< cycles captured by the task's side
  std::uint64_t commands_accepted = 0;  ///< valid, queued for a cycle's start
  std::uint64_t commands_applied = 0;   ///< written at a cycle's start
  std::uint64_t commands_rejected = 0;  ///< invalid: not written (a `/set/rejected` message says why)
  std::uint64_t commands_dropped = 0;   ///< valid, but the queue was full: not written
  std::uint64_t connects = 0;           ///< connections the broker accepted
  std::uint64_t disconnects = 0;        ///< connections lost or closed
  std::uint64_t refused = 0;            ///< connections the broker refused (credentials, client id)
  bool connected = false;               ///< connected now
};

// A command's parsing (exchange/detail/mqtt_commands.hpp) and the JSON and topics the bridge
// writes (exchange/detail/mqtt_json.hpp).

/**
 * An MQTT bridge for up to MaxChannels published values (add, add_pins, add_located, as a
 * trace's channels) and MaxCommands commands. attach() it to the task whose variables it
 * publishes and writes; start() connects (and keeps reconnecting), stop() or the destructor
 * says goodbye. Channels and commands are fixed while attached or started.
 */
template <std::size_t MaxChannels = 64, std::size_t MaxCommands = 16>
class mqtt_bridge : public trace_channels<MaxChannels>, private cycle_observer {
  static_assert(MaxCommands > 0 && MaxCommands <= 65535,
                "iecoop: an MQTT bridge has 1 to 65535 commands; give MaxCommands");

 public:
  explicit mqtt_bridge(mqtt_bridge_config config = {})
      : cycle_observer(
            [](cycle_observer& self, LTIME, std::uint64_t cycle) {
              static_cast<mqtt_bridge&>(self).capture_cycle(cycle);
            },
            [](cycle_observer& self, LTIME, std::uint64_t) { static_cast<mqtt_bridge&>(self).apply_commands(); }),
        config_(std::move(config)),
        queue_(std::max<std::size_t>(config_.command_queue, 1)) {}
  mqtt_bridge(const mqtt_bridge&) = delete;
  mqtt_bridge& operator=(const mqtt_bridge&) = delete;
  ~mqtt_bridge() {
    cycle_observer::detach();
    stop();
  }

  /// Captures the channels after each cycle of `task` and writes the commands before each.
  void attach(task_state& task) noexcept {
    task.attach(*this);
    lock();
  }
  void detach() noexcept {
    cycle_observer::detach();
    lock();
  }
  [[nodiscard]] bool attached() const noexcept { return cycle_observer::attached(); }

  /// Lets the broker's clients write `variable` through `<prefix>/<name as path>/set`: a BOOL,
  /// an integer or bit string, a REAL, LREAL, TIME, LTIME or enumeration, as a plain variable
  /// (a VAR_INPUT of a block, a member of a global variable list), a var<> (or retain<>)
  /// wrapper, or a %Q/%M located variable. FALSE (and a fault) when all MaxCommands are taken,
  /// the name is taken or invalid, or while attached or started.
  template <class V>
  bool command(std::string_view name, V&& variable) {
    check_target<V>();
    using W = std::remove_cvref_t<V>;
    if constexpr (writable<V>) {
      return add_command<W, detail::mqtt_value_t<W>>(name, variable, nullptr, nullptr);
    } else {
      return false;
    }
  }

  /// The same, accepting only values from `min` to `max` (a number or a duration).
  template <class V>
  bool command(std::string_view name, V&& variable,
               const std::type_identity_t<detail::mqtt_value_t<std::remove_cvref_t<V>>>& min,
               const std::type_identity_t<detail::mqtt_value_t<std::remove_cvref_t<V>>>& max) {
    check_target<V>();
    using W = std::remove_cvref_t<V>;
    using T = detail::mqtt_value_t<W>;
    static_assert(!std::is_same_v<T, BOOL> && !Enumeration<T>,
                  "iecoop: a command's range (min, max) limits a number or a duration; register a BOOL or an "
                  "enumeration command without one");
    if constexpr (writable<V> && !std::is_same_v<T, BOOL> && !Enumeration<T>) {
      if (detail::mqtt_number(max) < detail::mqtt_number(min)) {
        fault(fault_kind::invalid_value,
              "iecoop: a command's range has its maximum below its minimum; give min <= max");
        return false;
      }
      return add_command<W, T>(name, variable, &min, &max);
    } else {
      return false;
    }
  }

  [[nodiscard]] std::size_t command_count() const noexcept { return command_count_; }

  /// Checks the configuration and the names, and starts the bridge's thread, which connects
  /// (and reconnects after a failure or a loss, by itself). nullptr when it runs, otherwise why
  /// not ("iecoop: ..."). A broker that cannot be reached is no error: statistics().connected
  /// tells. Call it once (again after stop()).
  [[nodiscard]] const char* start() {
    if (thread_.joinable()) return "iecoop: the MQTT bridge runs already; stop() it first";
    if (const char* error = check_config()) return error;
    if (detail::mosquitto_library() != MOSQ_ERR_SUCCESS) return "iecoop: libmosquitto could not be initialised";
    make_topics();
    client_.reset(::mosquitto_new(config_.client_id.empty() ? nullptr : config_.client_id.c_str(), true, this));
    if (!client_) return "iecoop: libmosquitto could not make a client; check client_id (at most 65535 bytes of UTF-8)";
    int no_delay = 1;
    ::mosquitto_int_option(client_.get(), MOSQ_OPT_TCP_NODELAY, no_delay);
    if (!config_.username.empty() &&
        ::mosquitto_username_pw_set(client_.get(), config_.username.c_str(),
                                    config_.password.empty() ? nullptr : config_.password.c_str()) !=
            MOSQ_ERR_SUCCESS) {
      client_.reset();
      return "iecoop: libmosquitto refused the username or password; give UTF-8 text";
    }
    static constexpr std::string_view offline = "offline";
    if (::mosquitto_will_set(client_.get(), status_topic_.c_str(), static_cast<int>(offline.size()), offline.data(),
                             status_qos(), true) != MOSQ_ERR_SUCCESS) {
      client_.reset();
      return "iecoop: libmosquitto refused the last will's topic; check topic_prefix";
    }
    ::mosquitto_connect_callback_set(client_.get(), &on_connect);
    ::mosquitto_disconnect_callback_set(client_.get(), &on_disconnect);
    ::mosquitto_message_callback_set(client_.get(), &on_message);
    ::mosquitto_publish_callback_set(client_.get(), &on_publish);
    published_.assign(this->channel_count(), std::uint64_t{0});
    ever_published_.assign(this->channel_count(), false);
    stop_requested_.store(false);
    running_.store(true);
    thread_ = std::thread([this] { run(); });
    lock();
    return nullptr;
  }

  /// Publishes "offline" on `<prefix>/status` (waiting up to stop_timeout for the broker to
  /// take it), disconnects and ends the bridge's thread. Commands still queued are written by
  /// the next cycles.
  void stop() noexcept {
    if (thread_.joinable()) {
      {
        const std::lock_guard<std::mutex> guard(wake_mutex_);
        stop_requested_.store(true);
      }
      wake_.notify_one();
      thread_.join();
    }
    client_.reset();
    connected_.store(false);
    running_.store(false);
    lock();
  }

  [[nodiscard]] bool running() const noexcept { return running_.load(); }

  [[nodiscard]] mqtt_bridge_statistics statistics() const noexcept {
    mqtt_bridge_statistics s;
    s.published = published_count_.load(std::memory_order_relaxed);
    s.publish_errors = publish_errors_.load(std::memory_order_relaxed);
    s.snapshots = snapshots_taken_.load(std::memory_order_relaxed);
    s.commands_accepted = accepted_.load(std::memory_order_relaxed);
    s.commands_applied = applied_.load(std::memory_order_relaxed);
    s.commands_rejected = rejected_.load(std::memory_order_relaxed);
    s.commands_dropped = dropped_.load(std::memory_order_relaxed);
    s.connects = connects_.load(std::memory_order_relaxed);
    s.disconnects = disconnects_.load(std::memory_order_relaxed);
    s.refused = refused_.load(std::memory_order_relaxed);
    s.connected = connected_.load(std::memory_order_relaxed);
    return s;
  }

  [[nodiscard]] const mqtt_bridge_config& config() const noexcept { return config_; }

 private:
  using clock = std::chrono::steady_clock;
  static constexpr std::size_t values_capacity = (MaxChannels + 7) / 8 + MaxChannels * 8;

  struct snapshot {
    alignas(8) std::array<std::byte, values_capacity> values{};
    std::uint64_t cycle = 0;
    bool valid = false;
  };

  struct command_slot {
    std::string_view name;
    void* variable = nullptr;
    std::string_view type_name;
    /// The payload's literal as the value's bytes: nullptr, or why not.
    const char* (*parse)(const command_slot&, std::string_view, std::byte*) = nullptr;
    void (*apply)(void*, const std::byte*) = nullptr;
    std::array<std::byte, 8> min{}, max{};
    bool ranged = false;
  };

  struct queued_command {
    std::uint16_t command = 0;
    alignas(8) std::array<std::byte, 8> value{};
  };

  // --- registration ---------------------------------------------------------------------

  template <class V>
  static constexpr bool writable =
      std::is_lvalue_reference_v<V> && !std::is_const_v<std::remove_reference_t<V>> &&
      (detail::mqtt_target_of<std::remove_cvref_t<V>>() == detail::mqtt_target_kind::plain ||
       detail::mqtt_target_of<std::remove_cvref_t<V>>() == detail::mqtt_target_kind::wrapper);

  template <class V>
  static constexpr void check_target() {
    using W = std::remove_cvref_t<V>;
    static_assert(std::is_lvalue_reference_v<V> && !std::is_const_v<std::remove_reference_t<V>>,
                  "iecoop: a command writes a variable, not a value or a constant; give the variable itself, e.g. "
                  "mqtt.command(\"PRG.iSpeed\", prg.iSpeed)");
    constexpr detail::mqtt_target_kind kind = detail::mqtt_target_of<W>();
    static_assert(kind != detail::mqtt_target_kind::located_input,
                  "iecoop: a %I located variable is written by the I/O driver at each cycle's start, so a command "
                  "cannot write it; command a variable the program reads instead (a VAR_INPUT, a var<>), or a %Q/%M "
                  "located variable");
    static_assert(kind != detail::mqtt_target_kind::in_out,
                  "iecoop: a VAR_IN_OUT refers to a variable only during a call; command the variable it is bound to");
    static_assert(kind != detail::mqtt_target_kind::property,
                  "iecoop: a command writes a variable, not a PROPERTY; command the variable its Set writes");
    static_assert(kind != detail::mqtt_target_kind::read_only,
                  "iecoop: a read_only variable (a standard block's VAR_OUTPUT) is written by its block only; command "
                  "an input of the block instead");
    static_assert(kind != detail::mqtt_target_kind::unsupported,
                  "iecoop: a command writes a BOOL, an integer or bit string, REAL, LREAL, TIME, LTIME or an "
                  "enumeration, as a plain variable, a var<> wrapper or a %Q/%M located variable; command a STRING, "
                  "ARRAY or STRUCT element by element (a date or time of day is not commanded)");
  }

  template <class W, class T>
  bool add_command(std::string_view name, W& variable, const T* min, const T* max) {
    static_assert(sizeof(T) <= 8 && std::is_trivially_copyable_v<T>);
    if (locked_) {
      fault(fault_kind::invalid_value,
            "iecoop: an MQTT bridge's commands change only while it is stopped and detached; stop() and detach() "
            "it, add the commands, then attach and start it again");
      return false;
    }
    if (command_count_ == MaxCommands) {
      fault(fault_kind::invalid_value,
            "iecoop: an MQTT bridge's commands are all taken; give it more (its MaxCommands template argument)");
      return false;
    }
    if (!detail::mqtt_valid_name(name)) {
      fault(fault_kind::invalid_value,
            "iecoop: a command's name must be a valid topic: not empty, parts between dots not empty, no '/', '+' "
            "or '#'; name it as the variable, e.g. \"IO_PRG.iSpeed\"");
      return false;
    }
    for (std::size_t c = 0; c < command_count_; ++c) {
      if (commands_[c].name == name) {
        fault(fault_kind::invalid_value,
              "iecoop: an MQTT bridge has a command of this name already; give each its own");
        return false;
      }
    }
    command_slot& slot = commands_[command_count_];
    slot = command_slot{};
    slot.name = name;
    slot.variable = static_cast<void*>(&variable);
    slot.type_name = trace_type_of<T>.name;
    slot.parse = &parse_command<T>;
    slot.apply = &apply_command<W, T>;
    if (min != nullptr && max != nullptr) {
      std::memcpy(slot.min.data(), static_cast<const void*>(min), sizeof(T));
      std::memcpy(slot.max.data(), static_cast<const void*>(max), sizeof(T));
      slot.ranged = true;
    }
    ++command_count_;
    return true;
  }

  template <class T>
  static T load(const std::byte* bytes) noexcept {
    T value{};
    std::memcpy(static_cast<void*>(&value), bytes, sizeof(T));
    return value;
  }

  template <class T>
  static const char* parse_command(const command_slot& slot, std::string_view text, std::byte* out) noexcept {
    T value{};
    if (const char* error = detail::mqtt_parse(text, value)) return error;
    if constexpr (!std::is_same_v<T, BOOL> && !Enumeration<T>) {
      if (slot.ranged) {
        if (detail::mqtt_number(value) < detail::mqtt_number(load<T>(slot.min.data()))) {
          return "below the command's minimum";
        }
        if (detail::mqtt_number(load<T>(slot.max.data())) < detail::mqtt_number(value)) {
          return "above the command's maximum";
        }
      }
    }
    std::memcpy(static_cast<void*>(out), static_cast<const void*>(&value), sizeof(T));
    return nullptr;
  }

  template <class W, class T>
  static void apply_command(void* variable, const std::byte* bytes) {
    const T value = load<T>(bytes);
    W& target = *static_cast<W*>(variable);
    if constexpr (std::is_same_v<W, T>) {
      detail::copy_value(target, value);
    } else {
      target = value;
    }
  }

  /// The status (and the last will) goes at least with QoS 1: it must arrive.
  [[nodiscard]] int status_qos() const noexcept { return std::max(config_.qos, 1); }

  void lock() noexcept {
    locked_ = attached() || thread_.joinable();
    this->lock_channels(locked_);
  }

  // --- the task's side ------------------------------------------------------------------

  // After the cycle's programs: every channel into the newest snapshot.
  void capture_cycle(std::uint64_t cycle) {
    snapshot& s = snapshots_.write_slot();
    this->capture(s.values.data());
    s.cycle = cycle;
    s.valid = true;
    snapshots_.publish();
    // The task's thread is the only writer: a plain load and store, no locked read-modify-write
    // in the cyclic call (other threads only read the counter).
    snapshots_taken_.store(snapshots_taken_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  }

  // Before the cycle's programs: the queued commands in order, each variable at most once.
  void apply_commands() {
    ++generation_;
    std::uint64_t head = queue_head_.load(std::memory_order_relaxed);
    const std::uint64_t tail = queue_tail_.load(std::memory_order_acquire);
    std::uint64_t applied = 0;
    while (head != tail) {
      const queued_command& entry = queue_[static_cast<std::size_t>(head % queue_.size())];
      if (written_in_[entry.command] == generation_) break;  // the next cycle writes it (and what follows)
      written_in_[entry.command] = generation_;
      const command_slot& slot = commands_[entry.command];
      slot.apply(slot.variable, entry.value.data());
      ++head;
      ++applied;
    }
    if (applied != 0) {
      queue_head_.store(head, std::memory_order_release);
      applied_.store(applied_.load(std::memory_order_relaxed) + applied, std::memory_order_relaxed);  // (one writer)
    }
  }

  // --- the bridge's thread ----------------------------------------------------------------

  [[nodiscard]] const char* check_config() const noexcept {
    const std::string_view prefix = config_.topic_prefix;
    if (prefix.empty() || prefix.front() == '/' || prefix.back() == '/' ||
        prefix.find_first_of("+#") != std::string_view::npos || prefix.find("//") != std::string_view::npos ||
        prefix.find('\0') != std::string_view::npos) {
      return "iecoop: topic_prefix must be topic levels without wildcards (+, #), empty levels or a '/' at either "
             "end; give e.g. \"plant/line1\"";
    }
    if (config_.qos < 0 || config_.qos > 2 || config_.command_qos < 0 || config_.command_qos > 2) {
      return "iecoop: an MQTT QoS is 0, 1 or 2; give qos and command_qos one of them";
    }
    if (config_.keepalive < 5) return "iecoop: libmosquitto's keepalive is at least 5 seconds; give keepalive >= 5";
    if (config_.host.empty()) return "iecoop: the MQTT bridge needs the broker's host; give host";
    if (config_.check_interval.count() == 0) return "iecoop: check_interval must be greater than 0; give e.g. T#10ms";
    if (config_.reconnect_min.count() == 0 || config_.reconnect_max < config_.reconnect_min) {
      return "iecoop: the reconnect delays must be 0 < reconnect_min <= reconnect_max; give e.g. T#1s and T#30s";
    }
    if (!config_.publish_on_change && config_.publish_period.count() == 0 && this->channel_count() != 0) {
      return "iecoop: the MQTT bridge would publish its channels only when it connects; turn publish_on_change on, "
             "or give a publish_period";
    }
    for (const trace_channel& channel : this->channels()) {
      if ((!channel.scope.empty() && !detail::mqtt_valid_name(channel.scope)) ||
          !detail::mqtt_valid_name(channel.name)) {
        return "iecoop: a channel's name is no valid topic (empty, an empty part between dots, or '/', '+', '#'); "
               "name it as the variable, e.g. \"IO_PRG.bStart\"";
      }
      const std::string_view last = channel.name.substr(channel.name.rfind('.') + 1);
      if (last == "set" || (channel.scope.empty() && channel.name == "status")) {
        return "iecoop: a channel named `status`, or whose last part is `set`, would take the bridge's own topics; "
               "rename it";
      }
    }
    return nullptr;
  }

  void make_topics() {
    const std::string& prefix = config_.topic_prefix;
    status_topic_ = prefix + "/status";
    topics_.clear();
    for (const trace_channel& channel : this->channels()) {
      std::string topic = prefix;
      topic += '/';
      put_channel_name(channel, [&](std::string_view part) { detail::mqtt_append_topic_name(topic, part); });
      topics_.push_back(std::move(topic));
    }
    // One filter per depth up to the deepest command's: a command of a name no command has
    // reaches the bridge too, and is rejected with its reason.
    filters_.clear();
    std::size_t deepest = 0;
    for (std::size_t c = 0; c < command_count_; ++c)
      deepest = std::max(deepest, detail::mqtt_levels(commands_[c].name));
    for (std::size_t depth = 1; depth <= deepest; ++depth) {
      std::string filter = prefix;
      for (std::size_t d = 0; d < depth; ++d) filter += "/+";
      filter += "/set";
      filters_.push_back(std::move(filter));
    }
  }

  [[nodiscard]] LTIME backoff() const noexcept {
    std::uint64_t delay = config_.reconnect_min.count();
    for (unsigned n = 0; n < failed_attempts_ && delay < config_.reconnect_max.count(); ++n) delay *= 2;
    return LTIME::from_ticks(std::min<std::uint64_t>(delay, config_.reconnect_max.count()));
  }

  static clock::duration to_duration(LTIME t) noexcept {
    return std::chrono::duration_cast<clock::duration>(std::chrono::nanoseconds(static_cast<std::int64_t>(t.count())));
  }

  void schedule_attempt() noexcept {
    next_attempt_ = clock::now() + to_duration(backoff());
    if (failed_attempts_ < 64) ++failed_attempts_;
  }

  void run() {
    struct mosquitto* const m = client_.get();
    bool first = true;
    bool had_socket = false;
    next_attempt_ = clock::now();
    failed_attempts_ = 0;
    next_periodic_ = clock::now();
    const int loop_ms =
        static_cast<int>(std::clamp<std::uint64_t>(config_.check_interval.count() / 1'000'000u, 1, 1000));
    while (!stop_requested_.load()) {
      if (::mosquitto_socket(m) < 0) {
        if (had_socket) {  // lost, refused or failed: the next attempt after the back-off
          had_socket = false;
          schedule_attempt();
        }
        if (clock::now() >= next_attempt_) {
          const int rc = first ? ::mosquitto_connect_async(m, config_.host.c_str(), config_.port, config_.keepalive)
                               : ::mosquitto_reconnect_async(m);
          if (rc != MOSQ_ERR_INVAL) first = false;  // the host and port are kept from here on
          if (::mosquitto_socket(m) >= 0) {
            had_socket = true;
          } else {
            schedule_attempt();
          }
        }
        if (::mosquitto_socket(m) < 0) {
          std::unique_lock<std::mutex> guard(wake_mutex_);
          const auto until = std::min(next_attempt_, clock::now() + to_duration(config_.check_interval));
          wake_.wait_until(guard, until, [this] { return stop_requested_.load(); });
        }
      } else {
        ::mosquitto_loop(m, loop_ms, 1);
      }
      publish_values();
    }
    goodbye();
  }

  // The connection's end: "offline", acknowledged (up to stop_timeout), then DISCONNECT.
  void goodbye() {
    struct mosquitto* const m = client_.get();
    const auto until = clock::now() + to_duration(config_.stop_timeout);
    if (connected_.load()) {
      static constexpr std::string_view offline = "offline";
      int mid = 0;
      offline_mid_.store(-1);
      offline_acknowledged_ = false;
      if (publish(status_topic_, offline, true, &mid)) {
        offline_mid_.store(mid);
        while (!offline_acknowledged_ && connected_.load() && clock::now() < until) ::mosquitto_loop(m, 10, 1);
      }
      ::mosquitto_disconnect(m);
      while (::mosquitto_socket(m) >= 0 && clock::now() < until) ::mosquitto_loop(m, 10, 1);
    }
    if (connected_.exchange(false)) disconnects_.fetch_add(1, std::memory_order_relaxed);
  }

  bool publish(const std::string& topic, std::string_view payload, bool retain, int* mid = nullptr) {
    const int qos = topic == status_topic_ ? status_qos() : config_.qos;
    const int rc = ::mosquitto_publish(client_.get(), mid, topic.c_str(), static_cast<int>(payload.size()),
                                       payload.data(), qos, retain);
    if (rc != MOSQ_ERR_SUCCESS) {
      publish_errors_.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    published_count_.fetch_add(1, std::memory_order_relaxed);
    return true;
  }

  // The newest snapshot's values that changed (or all of them: on connect, every period).
  void publish_values() {
    const bool fresh = snapshots_.refresh();
    if (!connected_.load(std::memory_order_relaxed)) return;
    const snapshot& s = snapshots_.read_slot();
    if (!s.valid) return;
    const auto now = clock::now();
    bool all = republish_;
    if (config_.publish_period.count() != 0 && now >= next_periodic_) all = true;
    if (!all && !(fresh && config_.publish_on_change)) return;
    if (all) {
      republish_ = false;
      if (config_.publish_period.count() != 0) next_periodic_ = now + to_duration(config_.publish_period);
    }
    const auto channels = this->channels();
    std::string payload;
    char cycle[24];
    const auto cycle_end = std::to_chars(cycle, cycle + sizeof cycle, s.cycle).ptr;
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const trace_channel& channel = channels[c];
      const std::uint64_t bits = detail::mqtt_bits(*channel.type, s.values.data(), channel.offset);
      if (!all && ever_published_[c] && published_[c] == bits) continue;
      payload.assign("{\"value\":");
      detail::mqtt_append_json_value(payload, *channel.type, s.values.data(), channel.offset);
      payload += ",\"type\":";
      detail::mqtt_append_json_string(payload, channel.type->name);
      payload += ",\"cycle\":";
      payload.append(cycle, cycle_end);
      payload += '}';
      if (publish(topics_[c], payload, config_.retain)) {
        published_[c] = bits;
        ever_published_[c] = true;
      }
    }
  }

  void reject(const char* topic, std::string_view payload, const char* reason, std::string_view type_name = {}) {
    rejected_.fetch_add(1, std::memory_order_relaxed);
    publish_rejection(topic, payload, reason, type_name);
  }

  void publish_rejection(const char* topic, std::string_view payload, const char* reason, std::string_view type_name) {
    std::string text;
    detail::mqtt_rejection_message(text, reason, type_name, payload);
    publish(std::string(topic) + "/rejected", text, false);
  }

  // A message on a `/set` topic: checked, and queued for the next cycle's start.
  void command_received(const struct mosquitto_message& message) {
    const std::string_view topic = message.topic;
    const std::string_view payload(static_cast<const char*>(message.payload),
                                   message.payload == nullptr ? 0 : static_cast<std::size_t>(message.payloadlen));
    const std::string_view prefix = config_.topic_prefix;
    static constexpr std::string_view set = "/set";
    if (topic.size() <= prefix.size() + 1 + set.size() || !topic.starts_with(prefix) || topic[prefix.size()] != '/' ||
        !topic.ends_with(set)) {
      return;  // not a command's topic
    }
    const std::string_view path = topic.substr(prefix.size() + 1, topic.size() - prefix.size() - 1 - set.size());
    std::size_t index = command_count_;
    for (std::size_t c = 0; c < command_count_; ++c) {
      if (detail::mqtt_topic_names(path, commands_[c].name)) {
        index = c;
        break;
      }
    }
    if (index == command_count_) return reject(message.topic, payload, "no command of this name");
    const command_slot& slot = commands_[index];
    if (message.retain) {
      // A retained message replayed at a subscription (every connect): a command is an event,
      // not a state. Its first, live delivery has the flag cleared (MQTT 3.1.1, 3.3.1.3) and
      // was written as any command.
      return reject(message.topic, payload, "a retained command is not written; publish commands without retain",
                    slot.type_name);
    }
    if (payload.size() > detail::mqtt_max_payload) return reject(message.topic, payload, "the payload is too long");
    char buffer[detail::mqtt_max_payload];
    const detail::mqtt_literal literal = detail::mqtt_command_literal(payload, buffer, sizeof buffer);
    if (literal.error != nullptr) return reject(message.topic, payload, literal.error, slot.type_name);
    queued_command entry;
    entry.command = static_cast<std::uint16_t>(index);
    if (const char* error = slot.parse(slot, literal.text, entry.value.data())) {
      return reject(message.topic, payload, error, slot.type_name);
    }
    const std::uint64_t tail = queue_tail_.load(std::memory_order_relaxed);
    if (tail - queue_head_.load(std::memory_order_acquire) == queue_.size()) {
      dropped_.fetch_add(1, std::memory_order_relaxed);
      publish_rejection(message.topic, payload, "the command queue is full; the command is dropped", slot.type_name);
      return;
    }
    queue_[static_cast<std::size_t>(tail % queue_.size())] = entry;
    queue_tail_.store(tail + 1, std::memory_order_release);
    accepted_.fetch_add(1, std::memory_order_relaxed);
  }

  // libmosquitto's callbacks, in the bridge's thread (inside mosquitto_loop).
  static mqtt_bridge& self(void* object) noexcept { return *static_cast<mqtt_bridge*>(object); }

  static void on_connect(struct mosquitto* m, void* object, int rc) {
    mqtt_bridge& bridge = self(object);
    if (rc != 0) {
      bridge.refused_.fetch_add(1, std::memory_order_relaxed);
      return;
    }
    bridge.connected_.store(true);
    bridge.connects_.fetch_add(1, std::memory_order_relaxed);
    bridge.failed_attempts_ = 0;
    static constexpr std::string_view online = "online";
    bridge.publish(bridge.status_topic_, online, true);
    for (const std::string& filter : bridge.filters_) {
      ::mosquitto_subscribe(m, nullptr, filter.c_str(), bridge.config_.command_qos);
    }
    bridge.republish_ = true;  // the retained values may be gone (a broker without persistence)
  }

  static void on_disconnect(struct mosquitto*, void* object, int) {
    mqtt_bridge& bridge = self(object);
    if (bridge.connected_.exchange(false)) bridge.disconnects_.fetch_add(1, std::memory_order_relaxed);
  }

  static void on_message(struct mosquitto*, void* object, const struct mosquitto_message* message) {
    if (message != nullptr && message->topic != nullptr) self(object).command_received(*message);
  }

  static void on_publish(struct mosquitto*, void* object, int mid) {
    mqtt_bridge& bridge = self(object);
    if (mid == bridge.offline_mid_.load()) bridge.offline_acknowledged_ = true;
  }

  mqtt_bridge_config config_;

  // Registration (fixed while attached or started).
  std::array<command_slot, MaxCommands> commands_{};
  std::size_t command_count_ = 0;
  bool locked_ = false;

  // Task -> bridge: the snapshots.
  triple_buffer<snapshot> snapshots_{};
  // Bridge -> task: the commands, a single-producer single-consumer ring.
  std::vector<queued_command> queue_;
  std::atomic<std::uint64_t> queue_head_{0};  // the next to apply (the task owns it)
  std::atomic<std::uint64_t> queue_tail_{0};  // the next free (the bridge's)
  // The task's: which cycle (its generation) wrote each command's variable last.
  std::array<std::uint64_t, MaxCommands> written_in_{};
  std::uint64_t generation_ = 0;

  // The bridge's thread's.
  detail::mosquitto_handle client_;
  std::string status_topic_;
  std::vector<std::string> topics_;
  std::vector<std::string> filters_;
  std::vector<std::uint64_t> published_;
  std::vector<bool> ever_published_;
  clock::time_point next_attempt_{};
  clock::time_point next_periodic_{};
  unsigned failed_attempts_ = 0;
  bool republish_ = false;
  bool offline_acknowledged_ = false;
  std::atomic<int> offline_mid_{-1};

  std::thread thread_;
  std::mutex wake_mutex_;
  std::condition_variable wake_;
  std::atomic<bool> stop_requested_{false};
  std::atomic<bool> running_{false};
  std::atomic<bool> connected_{false};
  std::atomic<std::uint64_t> published_count_{0}, publish_errors_{0}, snapshots_taken_{0}, accepted_{0}, applied_{0},
      rejected_{0}, dropped_{0}, connects_{0}, disconnects_{0}, refused_{0};
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
