// SPDX-License-Identifier: MIT
// iecoop/exchange/modbus_client.hpp — remote I/O over Modbus TCP: a Modbus client (master) that polls
// a list of devices — I/O couplers, drives, meters — and maps their registers and bits into the
// process image, as CODESYS's "Modbus TCP Master" with its "Modbus TCP Slave" devices and their
// channels. Built on libmodbus (Debian: libmodbus-dev); link the CMake target iecoop::modbus.
//
//     modbus_device_config coupler;
//     coupler.name = "Coupler1";
//     coupler.host = "192.168.0.20";
//     coupler.reads = {{.table = modbus_table::input_registers, .remote = 0, .count = 4, .image = "%IW10"}};
//     coupler.writes = {{.table = modbus_table::coils, .remote = 0, .count = 8, .image = "%QX2.0"}};
//     modbus_client<> remote_io{{coupler}};
//     if (const char* error = remote_io.start()) { std::puts(error); return 1; }
//     plc.connect(remote_io);                        // or io_chain{card, remote_io}
//     ... remote_io.status(0).xError ...             // the device's diagnostics, latched with its inputs
//
// Each device is polled by a thread of its own, every poll_interval, outside the task cycles:
// its read channels into its input snapshot, then the newest outputs a cycle published to its
// write channels. A cycle's start latches every device's newest snapshot — data and status of
// the same poll — and its end publishes the outputs: through triple buffers, so a slow or dead
// device never delays a task. A channel that fails (no response in time, an exception response,
// the connection lost) counts in the device's status, its inputs take their error values
// (CODESYS's channel "error handling": set to a safe value, or keep the last value), and a lost
// connection is made again by itself, with back-off. For Linux and other POSIX systems; not
// part of <iecoop/iecoop.hpp>.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include <arpa/inet.h>
#include <netinet/in.h>

#include <iecoop/config.hpp>
#include <iecoop/detail/chrono.hpp>  // std::chrono's durations and clocks
#include <iecoop/exchange/image_window.hpp>
#include <iecoop/exchange/modbus_library.hpp>
#include <iecoop/exchange/triple_buffer.hpp>
#include <iecoop/io/address.hpp>
#include <iecoop/io/process_image.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// The four tables of Modbus's data model.
enum class modbus_table : std::uint8_t {
  coils,              ///< bits, read (FC 1) and written (FC 15)
  discrete_inputs,    ///< bits, read only (FC 2)
  holding_registers,  ///< 16-bit registers, read (FC 3) and written (FC 16)
  input_registers,    ///< 16-bit registers, read only (FC 4)
};

/// What a read channel's inputs show while it fails (CODESYS: the channel's "error handling").
enum class modbus_error_value : std::uint8_t {
  safe_value,  ///< the channel's `safe` values (0 where none is given): CODESYS "Set to ZERO", generalised
  keep_last,   ///< the last values read: CODESYS "Keep last value"
};

/// A channel: a run of one table of the device, and where it lies in the process image.
struct modbus_channel {
  modbus_table table = modbus_table::holding_registers;
  std::uint16_t remote = 0;  ///< the device's first address of the run (PDU addressing, from 0)
  std::uint16_t count = 1;   ///< registers (at most 125 read, 123 written) or bits (2000, 1968)
  /// The first image address, which must be given: %IW/%IX for a read channel, %QW/%QX for a
  /// write channel (as the channel's I/O mapping shows it in CODESYS).
  std::string image{};
  modbus_error_value on_error = modbus_error_value::safe_value;  ///< read channels
  std::vector<std::uint16_t> safe{};  ///< read channels: the safe value of each register (of each bit: != 0), 0 beyond
};

/// A remote device, as a "Modbus TCP Slave" under CODESYS's master.
struct modbus_device_config {
  std::string name = "Device";     ///< for messages
  std::string host = "127.0.0.1";  ///< an IPv4 address
  std::uint16_t port = 502;
  int unit_id = 1;                           ///< the unit identifier of the requests (0..247, or 255)
  LTIME poll_interval{100'000'000};          ///< from the start of one poll to the next (100 ms)
  LTIME response_timeout{1'000'000'000};     ///< a request without response in this time failed (1 s)
  LTIME reconnect_delay{100'000'000};        ///< the first wait before connecting again; doubled each failure...
  LTIME reconnect_delay_max{5'000'000'000};  ///< ... up to this
  std::vector<modbus_channel> reads{};       ///< polled into %I, in this order
  std::vector<modbus_channel> writes{};      ///< written from %Q after the reads, in this order
};

/**
 * A device's diagnostics, as the program sees them: latched at the cycle's start with the
 * inputs of the same poll (CODESYS shows such a device's state as its diagnostic bits and
 * counters). The counters wrap.
 */
struct modbus_device_status {
  BOOL xConnected;      ///< the TCP connection to the device is up
  BOOL xError;          ///< the last poll failed in at least one channel (its inputs hold their error values)
  BYTE byModbusError;   ///< the last exception code the device answered (1 illegal function, 2 address, ...; 0: none)
  UDINT udiPolls;       ///< polls made (each read and write of every channel)
  UDINT udiErrors;      ///< polls that failed in a channel, and connection attempts that failed
  UDINT udiTimeouts;    ///< requests the device did not answer in time
  UDINT udiExceptions;  ///< exception responses
  UDINT udiConnects;    ///< connections made: the first, and each one again after a loss
};

/**
 * The Modbus TCP client: devices polled in threads of their own, mapped into the process image
 * `Image`; the I/O driver of the task cycles (IoDriver). Not copyable; stop() (or the
 * destructor) ends its threads.
 */
template <class Image = default_process_image>
class modbus_client {
  static_assert(detail::is_process_image<Image>::value,
                "iecoop: modbus_client<Image> maps into a process_image<...>; give the application's image");
  using input_area = std::array<std::byte, Image::input_bytes>;
  using output_area = std::array<std::byte, Image::output_bytes>;

 public:
  using image_type = Image;

  explicit modbus_client(std::vector<modbus_device_config> devices) {
    for (modbus_device_config& config : devices) {
      devices_.push_back(std::make_unique<device>(std::move(config)));
      for (const channel_window& r : devices_.back()->reads) written_.push_back(r.window);
      for (const channel_window& w : devices_.back()->writes) sent_.push_back(w.window);
    }
  }
  modbus_client(const modbus_client&) = delete;
  modbus_client& operator=(const modbus_client&) = delete;
  ~modbus_client() { stop(); }

  /// Starts polling. nullptr when it polls; otherwise why not ("iecoop: ...", naming the device):
  /// what the constructor found wrong in a device's configuration or channels (checked against
  /// the image there, once), or two devices' read channels on the same input bits.
  [[nodiscard]] const char* start() {
    if (polling_) return "iecoop: the Modbus client is polling already; stop() it first";
    for (std::unique_ptr<device>& d : devices_) {
      if (d->error != nullptr) return d->error;
    }
    for (std::size_t a = 0; a < devices_.size(); ++a) {
      for (std::size_t b = a; b < devices_.size(); ++b) {
        if (devices_[a]->reads_overlap(*devices_[b], a == b)) {
          std::snprintf(error_text_, sizeof error_text_,
                        "iecoop: read channels of devices %s and %s write the same input bits; give each its own "
                        "%%I addresses",
                        devices_[a]->config.name.c_str(), devices_[b]->config.name.c_str());
          return error_text_;
        }
      }
    }
    for (std::unique_ptr<device>& d : devices_) d->launch();
    polling_ = true;
    return nullptr;
  }

  /// Stops polling: asks every device's thread to stop, then waits for them. A thread ends after
  /// the request under way, or the connection attempt under way (each at most its device's
  /// response_timeout). The inputs keep what was latched last.
  void stop() noexcept {
    for (std::unique_ptr<device>& d : devices_) d->request_stop();
    for (std::unique_ptr<device>& d : devices_) d->join();
    polling_ = false;
  }

  [[nodiscard]] bool polling() const noexcept { return polling_; }
  [[nodiscard]] std::size_t device_count() const noexcept { return devices_.size(); }
  [[nodiscard]] const modbus_device_config& config(std::size_t index) const noexcept { return devices_[index]->config; }

  /// Device `index`'s diagnostics as the current cycle latched them (read them in the task's
  /// programs, or between cycles).
  [[nodiscard]] const modbus_device_status& status(std::size_t index) const noexcept {
    return devices_[index]->latched;
  }

  /// The input bits read_inputs() writes: every device's read channels (those of a device whose
  /// configuration is wrong excepted). An io_chain checks them against its other drivers'.
  [[nodiscard]] std::span<const image_window> input_footprint() const noexcept { return written_; }
  /// The output bits write_outputs() sends: every device's write channels.
  [[nodiscard]] std::span<const image_window> output_footprint() const noexcept { return sent_; }

  /// IoDriver: each device's newest inputs (and status) into the image.
  void read_inputs(std::span<std::byte> inputs) noexcept {
    if (inputs.size() < Image::input_bytes) return;
    for (std::unique_ptr<device>& d : devices_) d->latch(inputs);
  }

  /// IoDriver: the outputs of every device's write channels, for its next poll.
  void write_outputs(std::span<const std::byte> outputs) noexcept {
    if (outputs.size() < Image::output_bytes) return;
    for (std::unique_ptr<device>& d : devices_) d->publish(outputs);
  }

 private:
  using clock = std::chrono::steady_clock;

  // What a poll hands the cycles: the inputs and the status of the same poll.
  struct input_snapshot {
    input_area data{};
    modbus_device_status status{};
  };
  struct output_snapshot {
    output_area data{};
    bool written = false;  // a cycle has published outputs
  };

  struct channel_window {
    const modbus_channel* channel = nullptr;
    image_window window{};
  };

  struct device {
    explicit device(modbus_device_config c) : config(std::move(c)) {
      error = check();
      if (error != nullptr) {
        reads.clear();
        writes.clear();
      }
    }

    modbus_device_config config;
    const char* error = nullptr;  // what check() found wrong in the configuration
    char error_text[256] = {};
    std::vector<channel_window> reads;  // made once, by the constructor: the cycles read them
    std::vector<channel_window> writes;
    triple_buffer<input_snapshot> to_cycles{};
    triple_buffer<output_snapshot> from_cycles{};
    modbus_device_status latched{};  // the cycles'

    // The poller's.
    std::thread thread;
    std::mutex mutex;
    std::condition_variable wake;
    bool stop_requested = false;
    input_snapshot polled{};
    std::array<std::uint16_t, MODBUS_MAX_READ_REGISTERS> registers{};
    std::array<std::uint8_t, MODBUS_MAX_READ_BITS> bit_values{};

    static bool is_bits(modbus_table t) noexcept {
      return t == modbus_table::coils || t == modbus_table::discrete_inputs;
    }

    const char* fail(const char* what) {
      std::snprintf(error_text, sizeof error_text, "%s (device %s)", what, config.name.c_str());
      return error_text;
    }

    // The configuration, and the channels' windows in the image.
    const char* check() {
      in_addr parsed{};
      if (::inet_pton(AF_INET, config.host.c_str(), &parsed) != 1) {
        return fail("iecoop: a Modbus device's host is an IPv4 address; give one such as 192.168.0.20");
      }
      // libmodbus sends unit identifiers 0..247 (the serial line's addresses) and 255.
      if (config.unit_id < 0 || (config.unit_id > 247 && config.unit_id != 255)) {
        return fail("iecoop: a Modbus unit identifier is 0..247 or 255; give the device's");
      }
      if (config.poll_interval.count() < 1'000'000 || config.response_timeout.count() < 1'000'000) {
        return fail("iecoop: a Modbus device's poll interval and response timeout are at least 1 ms");
      }
      for (const modbus_channel& c : config.reads) {
        if (c.image.empty()) {
          return fail(
              "iecoop: a read channel's image is not given; its registers or bits are inputs, where other "
              "drivers' inputs may lie: give the first address (.image = \"%IW10\" or \"%IX30.0\")");
        }
        const bool bits = is_bits(c.table);
        if (c.count > (bits ? MODBUS_MAX_READ_BITS : MODBUS_MAX_READ_REGISTERS)) {
          return fail("iecoop: a read channel holds at most 125 registers or 2000 bits (one request); split it");
        }
        const window_parse w = bits
                                   ? bit_window(c.image, c.count, io_area::input, Image::mode, Image::input_bytes)
                                   : register_window(c.image, c.count, io_area::input, Image::mode, Image::input_bytes);
        if (!w) return fail(w.error);
        reads.push_back({&c, *w});
      }
      for (const modbus_channel& c : config.writes) {
        if (c.table == modbus_table::discrete_inputs || c.table == modbus_table::input_registers) {
          return fail("iecoop: discrete inputs and input registers are read only; write coils or holding registers");
        }
        if (c.image.empty()) {
          return fail(
              "iecoop: a write channel's image is not given; give the first output address it sends "
              "(.image = \"%QW10\" or \"%QX30.0\")");
        }
        const bool bits = c.table == modbus_table::coils;
        if (c.count > (bits ? MODBUS_MAX_WRITE_BITS : MODBUS_MAX_WRITE_REGISTERS)) {
          return fail("iecoop: a write channel holds at most 123 registers or 1968 bits (one request); split it");
        }
        const window_parse w =
            bits ? bit_window(c.image, c.count, io_area::output, Image::mode, Image::output_bytes)
                 : register_window(c.image, c.count, io_area::output, Image::mode, Image::output_bytes);
        if (!w) return fail(w.error);
        writes.push_back({&c, *w});
      }
      return nullptr;
    }

    bool reads_overlap(const device& other, bool same) const noexcept {
      for (std::size_t i = 0; i < reads.size(); ++i) {
        for (std::size_t j = same ? i + 1 : 0; j < other.reads.size(); ++j) {
          if (reads[i].window.overlaps(other.reads[j].window)) return true;
        }
      }
      return false;
    }

    void launch() {
      // Until the first poll the inputs show their error values (no data yet).
      polled.status.xConnected = FALSE;
      for (const channel_window& r : reads) apply_error_value(r);
      hand_over();
      stop_requested = false;
      thread = std::thread([this] { poll_loop(); });
    }

    void request_stop() noexcept {
      {
        const std::lock_guard<std::mutex> lock(mutex);
        stop_requested = true;
      }
      wake.notify_all();
    }

    void join() noexcept {
      if (thread.joinable()) thread.join();
    }

    // The cycle's start: this device's newest poll, its read windows into the image.
    void latch(std::span<std::byte> inputs) noexcept {
      to_cycles.refresh();
      const input_snapshot& newest = to_cycles.read_slot();  // the cycles' until their next refresh()
      latched = newest.status;
      for (const channel_window& r : reads) copy_window(inputs, newest.data, r.window);
    }

    // The cycle's end: the write windows, for the next poll.
    void publish(std::span<const std::byte> outputs) noexcept {
      output_snapshot& slot = from_cycles.write_slot();
      for (const channel_window& w : writes) copy_window(slot.data, outputs, w.window);
      slot.written = true;
      from_cycles.publish();
    }

    // --- The poller -----------------------------------------------------------------

    void apply_error_value(const channel_window& r) noexcept {
      const modbus_channel& c = *r.channel;
      if (c.on_error == modbus_error_value::keep_last) return;
      auto safe = [&](std::uint32_t i) { return i < c.safe.size() ? c.safe[i] : std::uint16_t{0}; };
      if (is_bits(c.table)) {
        for (std::uint32_t i = 0; i < r.window.bits; ++i) store_bit(polled.data, r.window, i, safe(i) != 0);
      } else {
        for (std::uint32_t i = 0; i < r.window.registers(); ++i) store_register(polled.data, r.window, i, safe(i));
      }
    }

    // Sleeps until `until` or a stop request; TRUE if asked to stop.
    bool sleep_until(clock::time_point until) {
      std::unique_lock<std::mutex> lock(mutex);
      return wake.wait_until(lock, until, [this] { return stop_requested; });
    }

    bool stopping() {
      const std::lock_guard<std::mutex> lock(mutex);
      return stop_requested;
    }

    void poll_loop() {
      detail::modbus_context context(modbus_new_tcp(config.host.c_str(), config.port));
      if (!context) return;
      if (modbus_set_slave(context.get(), config.unit_id) != 0) return;  // (check() allows only what it takes)
      detail::set_modbus_timeout(context.get(), &modbus_set_response_timeout, config.response_timeout);
      detail::set_modbus_timeout(context.get(), &modbus_set_byte_timeout, config.response_timeout);
      bool connected = false;
      auto delay = std::chrono::nanoseconds(config.reconnect_delay.count());
      const auto delay_max = std::chrono::nanoseconds(config.reconnect_delay_max.count());
      modbus_device_status& s = polled.status;
      auto next = clock::now();
      while (!stopping()) {
        if (!connected) {
          if (modbus_connect(context.get()) != 0) {
            // No connection: the inputs show their error values, and the next try waits longer.
            s.xConnected = FALSE;
            s.xError = TRUE;
            s.udiErrors = s.udiErrors + 1;
            for (const channel_window& r : reads) apply_error_value(r);
            hand_over();
            if (sleep_until(clock::now() + delay)) break;
            delay = std::min(delay * 2, delay_max);
            next = clock::now();
            continue;
          }
          connected = true;
          delay = std::chrono::nanoseconds(config.reconnect_delay.count());
          s.xConnected = TRUE;
          s.udiConnects = s.udiConnects + 1;
        }
        next += std::chrono::nanoseconds(config.poll_interval.count());
        if (!poll_once(context.get())) {
          modbus_close(context.get());  // a lost or out-of-step connection: made again at the next poll
          connected = false;
          s.xConnected = FALSE;
        }
        hand_over();
        const auto now = clock::now();
        if (next < now) next = now;  // a late poll does not make up for lost time
        if (sleep_until(connected ? next : now + delay)) break;
      }
    }

    // One poll: every read channel, then every write channel. FALSE when the connection must
    // be made again (lost, or no response in time).
    bool poll_once(modbus_t* context) {
      modbus_device_status& s = polled.status;
      s.udiPolls = s.udiPolls + 1;
      bool failed = false;
      bool link_ok = true;
      for (const channel_window& r : reads) {
        if (stopping()) return true;  // stop() need not wait for the rest of the poll
        if (!link_ok) {
          apply_error_value(r);
          continue;
        }
        const modbus_channel& c = *r.channel;
        int got = -1;
        switch (c.table) {
          case modbus_table::coils: got = modbus_read_bits(context, c.remote, c.count, bit_values.data()); break;
          case modbus_table::discrete_inputs:
            got = modbus_read_input_bits(context, c.remote, c.count, bit_values.data());
            break;
          case modbus_table::holding_registers:
            got = modbus_read_registers(context, c.remote, c.count, registers.data());
            break;
          case modbus_table::input_registers:
            got = modbus_read_input_registers(context, c.remote, c.count, registers.data());
            break;
        }
        if (got == c.count) {
          if (is_bits(c.table)) {
            for (std::uint32_t i = 0; i < r.window.bits; ++i) store_bit(polled.data, r.window, i, bit_values[i] != 0);
          } else {
            for (std::uint32_t i = 0; i < r.window.registers(); ++i)
              store_register(polled.data, r.window, i, registers[i]);
          }
          continue;
        }
        failed = true;
        link_ok = count_failure(errno);
        apply_error_value(r);
      }
      from_cycles.refresh();
      const output_snapshot& out = from_cycles.read_slot();
      for (const channel_window& w : writes) {
        if (!link_ok || !out.written || stopping()) break;
        const modbus_channel& c = *w.channel;
        int put = -1;
        if (c.table == modbus_table::coils) {
          for (std::uint32_t i = 0; i < w.window.bits; ++i) bit_values[i] = load_bit(out.data, w.window, i) ? 1 : 0;
          put = modbus_write_bits(context, c.remote, c.count, bit_values.data());
        } else {
          for (std::uint32_t i = 0; i < w.window.registers(); ++i) registers[i] = load_register(out.data, w.window, i);
          put = modbus_write_registers(context, c.remote, c.count, registers.data());
        }
        if (put == c.count) continue;
        failed = true;
        link_ok = count_failure(errno);
      }
      s.xError = failed ? TRUE : FALSE;
      if (failed) s.udiErrors = s.udiErrors + 1;
      return link_ok;
    }

    // Counts a failed request by its errno; FALSE if the connection must be made again.
    bool count_failure(int failure) noexcept {
      modbus_device_status& s = polled.status;
      if (const std::uint8_t code = detail::modbus_exception_of(failure); code != 0) {
        s.udiExceptions = s.udiExceptions + 1;
        s.byModbusError = BYTE(code);
        return true;  // the device answered: the connection is fine
      }
      if (failure == ETIMEDOUT) s.udiTimeouts = s.udiTimeouts + 1;
      return false;
    }

    void hand_over() noexcept {
      to_cycles.write_slot() = polled;
      to_cycles.publish();
    }
  };

  std::vector<std::unique_ptr<device>> devices_;
  std::vector<image_window> written_, sent_;  // the footprints, made by the constructor
  bool polling_ = false;
  char error_text_[256] = {};  // start()'s message about overlapping devices
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
