// SPDX-License-Identifier: MIT
// iecoop/exchange/modbus_server.hpp — a Modbus TCP server (slave) on the process image, as CODESYS's
// "Modbus TCP Slave Device": an HMI or SCADA writes holding registers and coils, which the
// program reads as inputs (%IW, %IX), and reads input registers and discrete inputs, which the
// program writes as outputs (%QW, %QX). Served by libmodbus (Debian: libmodbus-dev) in a
// thread of its own; link the CMake target iecoop::modbus.
//
//     modbus_server<> hmi{{.port = 1502, .holding_registers = 16, .holding_image = "%IW8", .input_registers = 16}};
//     if (const char* error = hmi.start()) { std::puts(error); return 1; }
//     plc.connect(hmi);                            // or io_chain{card, hmi}
//
// The holding registers (and coils) go to %I, where a local card's inputs may lie too: their
// place is given, never assumed (CODESYS places a device's I/O mapping after the others').
//
// Consistency, as the process image's: a task cycle sees the holding registers as they were
// at its start (a client's multi-register write is all there or not at all), and the clients
// read the outputs as one cycle left them at its end (a DINT in two input registers is never
// half of one cycle and half of another). The server thread and the cycles exchange
// snapshots through triple buffers: the cycle never waits for the network, and a slow, broken
// or malicious client delays no task. For Linux and other POSIX systems; not part of
// <iecoop/iecoop.hpp>.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <iecoop/config.hpp>
#include <iecoop/detail/chrono.hpp>  // std::chrono's durations and clocks
#include <iecoop/exchange/image_window.hpp>
#include <iecoop/exchange/modbus_library.hpp>
#include <iecoop/exchange/triple_buffer.hpp>
#include <iecoop/io/address.hpp>
#include <iecoop/io/process_image.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * The configuration of a Modbus TCP server, as CODESYS's Modbus TCP Slave Device's "General"
 * tab gives it. Addresses are the process image's (checked by start()); `*_start` are the
 * Modbus data model's first addresses (PDU addressing, from 0: mbpoll's `-r 1` is 0).
 */
struct modbus_server_config {
  std::string
      bind_address{};  ///< the local address to listen on; empty: every address (CODESYS: not bound to an adapter)
  std::uint16_t port = 502;  ///< 0: a free port the system chooses (port() tells)
  /// Holding registers (FC 3, 6, 16, 22, 23): written, and read back, by the clients; the
  /// program reads them at %IW (CODESYS: "Holding registers (%IW)"), from `holding_image`,
  /// which must be given ("%IW8", the first word as CODESYS's I/O mapping shows it): no default
  /// lands on another driver's inputs unasked.
  std::uint16_t holding_registers = 10;
  std::string holding_image{};
  std::uint16_t holding_start = 0;
  /// Input registers (FC 4): read by the clients; the program writes them at %QW.
  std::uint16_t input_registers = 10;
  std::string input_image = "%QW0";
  std::uint16_t input_start = 0;
  /// Coils (FC 1, 5, 15) and discrete inputs (FC 2): 0 (CODESYS's default) addresses the bits
  /// of the registers' data — coil n is bit n % 16 of holding register n / 16, discrete input n
  /// likewise of the input registers; a count gives them a bit area of their own ("Discrete
  /// Bit Areas"): coils at %IX, from `coil_image` (which must then be given, "%IX32.0"),
  /// discrete inputs at %QX.
  std::uint16_t coils = 0;
  std::string coil_image{};
  std::uint16_t coil_start = 0;
  std::uint16_t discrete_inputs = 0;
  std::string discrete_image = "%QX0.0";
  std::uint16_t discrete_start = 0;
  /// CODESYS's "Watchdog": when no request has been answered without exception for this long,
  /// the holding registers and coils (what the program reads) go to 0. 0: off.
  LTIME watchdog{0};
  /// CODESYS's "Closing the TCP socket": when the watchdog expires, the connections are closed
  /// too (a client that hangs on a half-open connection connects anew).
  bool watchdog_closes_connections = false;
  /// How many clients may be connected at once. One more takes the place of the connection
  /// idle longest, if that one has been idle for client_timeout at least; otherwise it is
  /// refused (closed at once).
  int max_clients = 8;
  /// A request must arrive in full within this of its first byte; otherwise the connection is
  /// closed (a stalled or dribbling client). A client that does not read its replies is closed
  /// as soon as they no longer fit its socket's buffer.
  LTIME client_timeout{500'000'000};
  /// A connection on which no request arrives for this long is closed (as Beckhoff's Modbus TCP
  /// bus controllers close a connection unused for about 10 s): connections that send nothing
  /// hold no place for long. 0: never.
  LTIME idle_timeout{10'000'000'000};
  /// A client whose requests this many times in a row are answered with an exception (a
  /// function or address this server does not serve) is closed; 0: never.
  std::uint32_t max_exceptions_in_a_row = 16;
};

/// What a Modbus server did since start(); read any time, from any thread.
struct modbus_server_statistics {
  std::uint64_t requests = 0;           ///< answered, with data or with an exception
  std::uint64_t exceptions = 0;         ///< answered with an exception (illegal function, address, value)
  std::uint64_t bad_requests = 0;       ///< broken off (malformed, incomplete in time); the connection was closed
  std::uint64_t connections = 0;        ///< accepted
  std::uint64_t refused = 0;            ///< refused: max_clients were connected, none idle
  std::uint64_t closed_idle = 0;        ///< closed after idle_timeout, or to make room for a new client
  std::uint64_t closed_exceptions = 0;  ///< closed after max_exceptions_in_a_row exceptions
  std::uint64_t watchdog_expiries = 0;  ///< times the watchdog set the holding data to 0
  std::uint32_t clients = 0;            ///< connected now
};

/**
 * A Modbus TCP server on the process image `Image`, and the I/O driver that connects it to the
 * task cycles (IoDriver: read_inputs latches what the clients wrote, write_outputs publishes
 * what they read). Not copyable; stop() (or the destructor) ends its thread.
 */
template <class Image = default_process_image>
class modbus_server {
  static_assert(detail::is_process_image<Image>::value,
                "iecoop: modbus_server<Image> serves a process_image<...>; give the application's image");
  using input_area = std::array<std::byte, Image::input_bytes>;
  using output_area = std::array<std::byte, Image::output_bytes>;

 public:
  using image_type = Image;

  /// The configuration is checked against the image here; start() reports what is wrong.
  explicit modbus_server(modbus_server_config config = {})
      : config_(std::move(config)), config_error_(make_windows()) {}
  modbus_server(const modbus_server&) = delete;
  modbus_server& operator=(const modbus_server&) = delete;
  ~modbus_server() { stop(); }

  /// Checks the configuration, listens and starts serving. nullptr when it serves; otherwise
  /// why not ("iecoop: ..."), and it does not serve. Call it once (again after stop()).
  [[nodiscard]] const char* start() {
    if (thread_.joinable()) return "iecoop: the Modbus server is serving already; stop() it first";
    if (config_error_ != nullptr) return config_error_;
    if (const char* error = listen()) return error;
    stop_requested_.store(false);
    thread_ = std::thread([this] { serve(); });
    return nullptr;
  }

  /// Stops serving: closes every connection and the listening socket. What the program reads
  /// keeps the clients' last values, and so does the data model: start() serves them again.
  void stop() noexcept {
    if (thread_.joinable()) {
      stop_requested_.store(true);
      const char wake = 1;
      [[maybe_unused]] const ssize_t written = ::write(wake_[1], &wake, 1);
      thread_.join();
    }
    close_all();
  }

  [[nodiscard]] bool serving() const noexcept { return thread_.joinable(); }

  /// The port it listens on (the one the system chose, for port 0).
  [[nodiscard]] std::uint16_t port() const noexcept { return port_; }

  [[nodiscard]] modbus_server_statistics statistics() const noexcept {
    modbus_server_statistics s;
    s.requests = requests_.load(std::memory_order_relaxed);
    s.exceptions = exceptions_.load(std::memory_order_relaxed);
    s.bad_requests = bad_requests_.load(std::memory_order_relaxed);
    s.connections = connections_.load(std::memory_order_relaxed);
    s.refused = refused_.load(std::memory_order_relaxed);
    s.closed_idle = closed_idle_.load(std::memory_order_relaxed);
    s.closed_exceptions = closed_exceptions_.load(std::memory_order_relaxed);
    s.watchdog_expiries = watchdog_expiries_.load(std::memory_order_relaxed);
    s.clients = clients_.load(std::memory_order_relaxed);
    return s;
  }

  [[nodiscard]] const modbus_server_config& config() const noexcept { return config_; }

  /// The input bits read_inputs() writes: the holding registers' window and the coils' (none
  /// while the configuration is wrong). An io_chain checks them against its other drivers'.
  [[nodiscard]] std::span<const image_window> input_footprint() const noexcept { return written_; }
  /// The output bits write_outputs() serves: the input registers' window and the discrete inputs'.
  [[nodiscard]] std::span<const image_window> output_footprint() const noexcept { return served_; }

  /// IoDriver: the cycle's start. The holding registers and coils as the clients last wrote
  /// them, into their %I windows (the rest of the inputs is left alone).
  void read_inputs(std::span<std::byte> inputs) noexcept {
    if (inputs.size() < Image::input_bytes) return;
    from_clients_.refresh();
    const input_area& latest = from_clients_.read_slot();
    copy_window(inputs, latest, holding_window_);
    copy_window(inputs, latest, coil_window_);
  }

  /// IoDriver: the cycle's end. The %Q windows of the input registers and discrete inputs, for
  /// the clients' next reads.
  void write_outputs(std::span<const std::byte> outputs) noexcept {
    if (outputs.size() < Image::output_bytes) return;
    output_area& slot = to_clients_.write_slot();
    copy_window(slot, outputs, input_window_);
    copy_window(slot, outputs, discrete_window_);
    to_clients_.publish();
  }

 private:
  using clock = std::chrono::steady_clock;

  [[nodiscard]] bool shared_bits() const noexcept { return config_.coils == 0; }
  [[nodiscard]] bool shared_discretes() const noexcept { return config_.discrete_inputs == 0; }

  // The image windows, checked against the image.
  const char* make_windows() noexcept {
    if (config_.client_timeout.count() < 1'000'000) {
      return "iecoop: a Modbus server's client_timeout is at least 1 ms (0 would wait for a stalled client forever)";
    }
    if (config_.holding_image.empty()) {
      return "iecoop: a Modbus server's holding_image is not given; the holding registers are inputs (%IW), where "
             "other drivers' inputs may lie: give their first word, as CODESYS's I/O mapping shows it "
             "(holding_image = \"%IW8\")";
    }
    const window_parse holding = register_window(config_.holding_image, config_.holding_registers, io_area::input,
                                                 Image::mode, Image::input_bytes);
    if (!holding) return holding.error;
    const window_parse input = register_window(config_.input_image, config_.input_registers, io_area::output,
                                               Image::mode, Image::output_bytes);
    if (!input) return input.error;
    holding_window_ = *holding;
    input_window_ = *input;
    coil_window_ = {};
    discrete_window_ = {};
    if (!shared_bits()) {
      if (config_.coil_image.empty()) {
        return "iecoop: a Modbus server's coil_image is not given; coils of their own are inputs (%IX), where other "
               "drivers' inputs may lie: give the first bit (coil_image = \"%IX32.0\"), or 0 coils to address the "
               "holding registers' bits";
      }
      const window_parse coil =
          bit_window(config_.coil_image, config_.coils, io_area::input, Image::mode, Image::input_bytes);
      if (!coil) return coil.error;
      if (coil.window.overlaps(holding_window_)) {
        return "iecoop: the coils' bits overlap the holding registers' words; give them bits of their own, or 0 "
               "coils to address the registers' bits";
      }
      coil_window_ = *coil;
    }
    if (!shared_discretes()) {
      const window_parse discrete = bit_window(config_.discrete_image, config_.discrete_inputs, io_area::output,
                                               Image::mode, Image::output_bytes);
      if (!discrete) return discrete.error;
      if (discrete.window.overlaps(input_window_)) {
        return "iecoop: the discrete inputs' bits overlap the input registers' words; give them bits of their own, "
               "or 0 discrete inputs to address the registers' bits";
      }
      discrete_window_ = *discrete;
    }
    written_ = {holding_window_, coil_window_};
    served_ = {input_window_, discrete_window_};
    return nullptr;
  }

  // The context, the data model and the listening socket.
  const char* listen() {
    close_all();
    in_addr parsed{};
    if (!config_.bind_address.empty() && ::inet_pton(AF_INET, config_.bind_address.c_str(), &parsed) != 1) {
      return "iecoop: bind_address is no IPv4 address; give one such as 127.0.0.1, or none to listen on every address";
    }
    context_.reset(modbus_new_tcp(config_.bind_address.empty() ? nullptr : config_.bind_address.c_str(), config_.port));
    if (!context_) return "iecoop: libmodbus could not make a TCP context; check bind_address (an IPv4 address)";
    const int bits = shared_bits() ? config_.holding_registers * 16 : config_.coils;
    const int input_bits = shared_discretes() ? config_.input_registers * 16 : config_.discrete_inputs;
    if (!mapping_) {  // made once: a restart serves the values the clients wrote before
      mapping_.reset(modbus_mapping_new_start_address(
          config_.coil_start, static_cast<unsigned>(bits), config_.discrete_start, static_cast<unsigned>(input_bits),
          config_.holding_start, config_.holding_registers, config_.input_start, config_.input_registers));
    }
    if (!mapping_) return "iecoop: libmodbus could not allocate the server's data model";
    listen_socket_ = modbus_tcp_listen(context_.get(), config_.max_clients);
    if (listen_socket_ < 0) {
      std::snprintf(error_text_, sizeof error_text_, "iecoop: the Modbus server cannot listen on port %u: %s",
                    static_cast<unsigned>(config_.port), std::strerror(errno));
      close_all();
      return error_text_;
    }
    sockaddr_in bound{};
    socklen_t length = sizeof bound;
    ::getsockname(listen_socket_, reinterpret_cast<sockaddr*>(&bound), &length);
    port_ = ntohs(bound.sin_port);
    if (::pipe(wake_) != 0) {
      close_all();
      return "iecoop: the Modbus server could not make its wake-up pipe";
    }
    // What the clients read starts as the outputs published so far (all 0 before the first cycle).
    to_clients_.refresh();
    load_outputs(to_clients_.read_slot());
    last_valid_ = clock::now();
    zeroed_ = false;
    return nullptr;
  }

  void close_all() noexcept {
    for (const client& c : clients_list_) ::close(c.socket);
    clients_list_.clear();
    clients_.store(0);
    if (listen_socket_ >= 0) ::close(listen_socket_);
    listen_socket_ = -1;
    for (int& end : wake_) {
      if (end >= 0) ::close(end);
      end = -1;
    }
    context_.reset();
  }

  // One connection, as the server thread keeps it: the request being read (bytes arrive as they
  // may; nothing waits for them), its deadline, and what the connection did.
  struct client {
    int socket = -1;
    std::array<std::uint8_t, MODBUS_TCP_MAX_ADU_LENGTH> frame{};
    std::size_t have = 0;              // bytes of the request being read
    std::size_t want = 7;              // the MBAP header, then the whole frame it announces
    clock::time_point deadline{};      // the request in full by then (from its first byte)
    clock::time_point last_request{};  // the connection's start, then each request's end
    std::uint32_t exceptions_in_a_row = 0;
  };

  // The server thread: one poll over the wake-up pipe, the listening socket and the clients.
  // Nothing in it waits for a client: a request is read as its bytes come, a reply is sent
  // without blocking, so no client (slow, idle, dribbling, flooding) delays the others.
  void serve() {
    std::vector<pollfd> polled;
    polled.reserve(static_cast<std::size_t>(config_.max_clients) + 2);
    while (!stop_requested_.load()) {
      polled.clear();
      polled.push_back({wake_[0], POLLIN, 0});
      polled.push_back({listen_socket_, POLLIN, 0});
      for (const client& c : clients_list_) polled.push_back({c.socket, POLLIN, 0});
      const int ready = ::poll(polled.data(), polled.size(), poll_timeout_ms());
      if (check_watchdog()) continue;  // (the connections closed: `polled` names sockets that are gone)
      if (ready > 0) {
        if ((polled[0].revents & POLLIN) != 0) break;
        // Each ready client once per round, one request each: a flood waits its turn.
        for (std::size_t i = 2; i < polled.size(); ++i) {
          if (polled[i].revents != 0) serve_client(polled[i].fd);
        }
        if ((polled[1].revents & POLLIN) != 0) accept_client();
      }
      close_overdue();
    }
  }

  // Until the watchdog expires, the earliest request deadline or idle time: poll's timeout.
  [[nodiscard]] int poll_timeout_ms() const noexcept {
    clock::time_point due = clock::time_point::max();
    if (config_.watchdog.count() != 0 && !zeroed_)
      due = last_valid_ + std::chrono::nanoseconds(config_.watchdog.count());
    for (const client& c : clients_list_) due = std::min(due, next_due(c));
    if (due == clock::time_point::max()) return -1;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(due - clock::now()).count();
    return static_cast<int>(std::clamp<long long>(left + 1, 0, 1000));
  }

  // When `c` is overdue: its request's deadline, or the end of its idle time.
  [[nodiscard]] clock::time_point next_due(const client& c) const noexcept {
    if (c.have > 0) return c.deadline;
    if (config_.idle_timeout.count() == 0) return clock::time_point::max();
    return c.last_request + std::chrono::nanoseconds(config_.idle_timeout.count());
  }

  // Closes the connections whose request did not arrive in full in time, and the idle ones.
  void close_overdue() noexcept {
    const auto now = clock::now();
    for (std::size_t i = clients_list_.size(); i-- > 0;) {
      const client& c = clients_list_[i];
      if (now < next_due(c)) continue;
      (c.have > 0 ? bad_requests_ : closed_idle_).fetch_add(1, std::memory_order_relaxed);
      drop_client(c.socket);
    }
  }

  void accept_client() {
    const int socket = ::accept4(listen_socket_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (socket < 0) return;
    const auto now = clock::now();
    if (clients_list_.size() >= static_cast<std::size_t>(config_.max_clients)) {
      // Room for the new one where a connection has been idle (no request, none under way) for
      // client_timeout at least: the one idle longest goes.
      const auto idle =
          std::min_element(clients_list_.begin(), clients_list_.end(), [](const client& a, const client& b) {
            return (a.have == 0 ? a.last_request : clock::time_point::max()) <
                   (b.have == 0 ? b.last_request : clock::time_point::max());
          });
      if (idle == clients_list_.end() || idle->have > 0 ||
          now - idle->last_request < std::chrono::nanoseconds(config_.client_timeout.count())) {
        ::close(socket);
        refused_.fetch_add(1, std::memory_order_relaxed);
        return;
      }
      closed_idle_.fetch_add(1, std::memory_order_relaxed);
      drop_client(idle->socket);
    }
    const int yes = 1;
    ::setsockopt(socket, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
    client c;
    c.socket = socket;
    c.last_request = now;
    clients_list_.push_back(c);
    connections_.fetch_add(1, std::memory_order_relaxed);
    clients_.store(static_cast<std::uint32_t>(clients_list_.size()), std::memory_order_relaxed);
  }

  void drop_client(int socket) noexcept {
    ::close(socket);
    clients_list_.erase(
        std::find_if(clients_list_.begin(), clients_list_.end(), [&](const client& c) { return c.socket == socket; }));
    clients_.store(static_cast<std::uint32_t>(clients_list_.size()), std::memory_order_relaxed);
  }

  void serve_client(int socket) {
    const auto found =
        std::find_if(clients_list_.begin(), clients_list_.end(), [&](const client& c) { return c.socket == socket; });
    if (found == clients_list_.end()) return;  // made room for a new client in this round
    client& c = *found;
    const frame_read read = read_frame(c);
    if (read == frame_read::partial) return;  // the rest when it comes, within the deadline
    if (read == frame_read::closed) {         // between two requests: the client is done
      drop_client(socket);
      return;
    }
    if (read == frame_read::broken || !pdu_fits(c.frame.data() + 7, c.have - 7)) {
      // No Modbus/TCP frame, or one whose length does not fit its function: the stream is out
      // of step, closed.
      bad_requests_.fetch_add(1, std::memory_order_relaxed);
      drop_client(socket);
      return;
    }
    const std::size_t size = c.have;
    c.have = 0;
    c.want = 7;
    c.last_request = clock::now();
    if (to_clients_.refresh()) load_outputs(to_clients_.read_slot());
    const std::uint8_t function = c.frame[7];
    const std::uint8_t exception = exception_for(c.frame.data() + 7, size - 7);
    bool sent = false;
    bool excepted = exception != 0;
    if (excepted) {
      sent = send_exception(socket, c.frame, exception);
    } else {
      modbus_set_socket(context_.get(), socket);
      const int length = modbus_reply(context_.get(), c.frame.data(), static_cast<int>(size), mapping_.get());
      sent = length >= 0;
      // An exception response is the MBAP header, the function code | 0x80 and the exception
      // code; every other response to a request libmodbus serves is longer.
      excepted = length == 9;
    }
    requests_.fetch_add(1, std::memory_order_relaxed);
    if (!sent) {  // the reply could not leave: the client does not read its replies, or is gone
      bad_requests_.fetch_add(1, std::memory_order_relaxed);
      drop_client(socket);
      return;
    }
    if (excepted) {
      exceptions_.fetch_add(1, std::memory_order_relaxed);
      if (config_.max_exceptions_in_a_row != 0 && ++c.exceptions_in_a_row >= config_.max_exceptions_in_a_row) {
        closed_exceptions_.fetch_add(1, std::memory_order_relaxed);
        drop_client(socket);
      }
      return;
    }
    c.exceptions_in_a_row = 0;
    last_valid_ = clock::now();
    zeroed_ = false;  // the watchdog watches again
    if (writes(function)) {
      sync_after_write(function);
      publish_inputs();
    }
  }

  enum class frame_read : std::uint8_t { complete, partial, closed, broken };

  // Reads what has arrived of `c`'s request, without waiting: the 7 bytes of the MBAP header
  // (transaction, protocol 0, length, unit), then the PDU its length announces. Never more than
  // the request: a request pipelined behind it stays in the socket for the next round. Its
  // deadline runs from its first byte (a deadline, not a gap between bytes: a client that
  // dribbles its request is closed at it; close_overdue()).
  frame_read read_frame(client& c) noexcept {
    while (c.have < c.want) {
      const ssize_t n = ::recv(c.socket, c.frame.data() + c.have, c.want - c.have, MSG_DONTWAIT);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return frame_read::partial;
      if (n <= 0) return c.have == 0 ? frame_read::closed : frame_read::broken;
      if (c.have == 0) c.deadline = clock::now() + std::chrono::nanoseconds(config_.client_timeout.count());
      c.have += static_cast<std::size_t>(n);
      if (c.have == 7 && c.want == 7) {
        const unsigned protocol = (static_cast<unsigned>(c.frame[2]) << 8) | c.frame[3];
        const unsigned length = (static_cast<unsigned>(c.frame[4]) << 8) | c.frame[5];  // unit identifier + PDU
        if (protocol != 0 || length < 2 || length > MODBUS_MAX_PDU_LENGTH + 1u) return frame_read::broken;
        c.want = 6 + length;
      }
    }
    return frame_read::complete;
  }

  // The exception a request is answered with (1: illegal function, 2: illegal data address,
  // 3: illegal data value), 0 where libmodbus serves it with data. Answered here, before
  // libmodbus sees the request: libmodbus answers an unserved function, and a quantity out
  // of range, by sleeping its response timeout and flushing the socket, which would stall
  // every client for half a second and drop the requests pipelined behind. The checks are
  // libmodbus's own (modbus_reply), in its order.
  [[nodiscard]] std::uint8_t exception_for(const std::uint8_t* pdu, std::size_t n) const noexcept {
    const modbus_mapping_t& m = *mapping_;
    const auto word = [&](std::size_t at) -> unsigned {
      return at + 1 < n ? (static_cast<unsigned>(pdu[at]) << 8) | pdu[at + 1] : 0U;
    };
    const auto outside = [](unsigned address, unsigned count, int start, int size) {
      const long first = static_cast<long>(address) - start;
      return first < 0 || first + static_cast<long>(count) > size;
    };
    constexpr std::uint8_t illegal_function = 1, illegal_address = 2, illegal_value = 3;
    switch (pdu[0]) {
      case 0x01:
      case 0x02: {
        const unsigned count = word(3);
        if (count < 1 || count > MODBUS_MAX_READ_BITS) return illegal_value;
        const bool coils = pdu[0] == 0x01;
        return outside(word(1), count, coils ? m.start_bits : m.start_input_bits, coils ? m.nb_bits : m.nb_input_bits)
                   ? illegal_address
                   : 0;
      }
      case 0x03:
      case 0x04: {
        const unsigned count = word(3);
        if (count < 1 || count > MODBUS_MAX_READ_REGISTERS) return illegal_value;
        const bool holding = pdu[0] == 0x03;
        return outside(word(1), count, holding ? m.start_registers : m.start_input_registers,
                       holding ? m.nb_registers : m.nb_input_registers)
                   ? illegal_address
                   : 0;
      }
      case 0x05:
        if (outside(word(1), 1, m.start_bits, m.nb_bits)) return illegal_address;
        return word(3) == 0xFF00 || word(3) == 0x0000 ? 0 : illegal_value;
      case 0x06: return outside(word(1), 1, m.start_registers, m.nb_registers) ? illegal_address : 0;
      case 0x0F: {
        const unsigned count = word(3);
        if (count < 1 || count > MODBUS_MAX_WRITE_BITS || n < 6 || pdu[5] * 8u < count) return illegal_value;
        return outside(word(1), count, m.start_bits, m.nb_bits) ? illegal_address : 0;
      }
      case 0x10: {
        const unsigned count = word(3);
        if (count < 1 || count > MODBUS_MAX_WRITE_REGISTERS || n < 6 || pdu[5] != count * 2) return illegal_value;
        return outside(word(1), count, m.start_registers, m.nb_registers) ? illegal_address : 0;
      }
      case 0x11: return 0;  // report server id
      case 0x16: return outside(word(1), 1, m.start_registers, m.nb_registers) ? illegal_address : 0;
      case 0x17: {
        const unsigned to_read = word(3);
        const unsigned to_write = word(7);
        if (to_write < 1 || to_write > MODBUS_MAX_WR_WRITE_REGISTERS || to_read < 1 ||
            to_read > MODBUS_MAX_WR_READ_REGISTERS || n < 10 || pdu[9] != to_write * 2) {
          return illegal_value;
        }
        return outside(word(1), to_read, m.start_registers, m.nb_registers) ||
                       outside(word(5), to_write, m.start_registers, m.nb_registers)
                   ? illegal_address
                   : 0;
      }
      default: return illegal_function;
    }
  }

  // An exception response, sent without waiting: the request's transaction and unit, the
  // function code | 0x80, the exception code. FALSE if it could not leave at once.
  static bool send_exception(int socket, const std::array<std::uint8_t, MODBUS_TCP_MAX_ADU_LENGTH>& request,
                             std::uint8_t exception) noexcept {
    const std::uint8_t response[9] = {
        request[0], request[1], 0, 0, 0, 3, request[6], static_cast<std::uint8_t>(request[7] | 0x80U), exception};
    for (;;) {
      const ssize_t n = ::send(socket, response, sizeof response, MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n < 0 && errno == EINTR) continue;
      return n == static_cast<ssize_t>(sizeof response);
    }
  }

  // The PDU's length fits its function (as libmodbus reads a request of that function); a
  // function libmodbus does not serve may have any length (its answer is exception 1).
  static bool pdu_fits(const std::uint8_t* pdu, std::size_t n) noexcept {
    switch (pdu[0]) {
      case 0x01:
      case 0x02:
      case 0x03:
      case 0x04:
      case 0x05:
      case 0x06: return n == 5;
      case 0x0F:
      case 0x10: return n >= 6 && n == 6u + pdu[5];
      case 0x11: return n == 1;
      case 0x16: return n == 7;
      case 0x17: return n >= 10 && n == 10u + pdu[9];
      default: return true;
    }
  }

  static constexpr bool writes(std::uint8_t function) noexcept {
    return function == 0x05 || function == 0x06 || function == 0x0F || function == 0x10 || function == 0x16 ||
           function == 0x17;
  }
  static constexpr bool writes_bits(std::uint8_t function) noexcept { return function == 0x05 || function == 0x0F; }

  // Coils that address the holding registers' bits: the other view follows the one written.
  void sync_after_write(std::uint8_t function) noexcept {
    if (!shared_bits()) return;
    modbus_mapping_t& m = *mapping_;
    for (int r = 0; r < m.nb_registers; ++r) {
      std::uint8_t* const bits = m.tab_bits + static_cast<std::ptrdiff_t>(r) * 16;
      if (writes_bits(function)) {
        unsigned value = 0;
        for (unsigned b = 0; b < 16; ++b) value |= (bits[b] != 0 ? 1U : 0U) << b;
        m.tab_registers[r] = static_cast<std::uint16_t>(value);
      } else {
        for (unsigned b = 0; b < 16; ++b) bits[b] = static_cast<std::uint8_t>((m.tab_registers[r] >> b) & 1U);
      }
    }
  }

  // What the program reads: the holding registers and coils as the data model holds them.
  void publish_inputs() noexcept {
    input_area& slot = from_clients_.write_slot();
    const modbus_mapping_t& m = *mapping_;
    for (std::uint32_t r = 0; r < holding_window_.registers(); ++r) {
      store_register(slot, holding_window_, r, m.tab_registers[r]);
    }
    for (std::uint32_t b = 0; b < coil_window_.bits; ++b) {
      store_bit(slot, coil_window_, b, m.tab_bits[b] != 0);
    }
    from_clients_.publish();
  }

  // What the clients read: the input registers and discrete inputs from the published outputs.
  void load_outputs(const output_area& outputs) noexcept {
    modbus_mapping_t& m = *mapping_;
    for (std::uint32_t r = 0; r < input_window_.registers(); ++r) {
      m.tab_input_registers[r] = load_register(outputs, input_window_, r);
      if (shared_discretes()) {
        for (unsigned b = 0; b < 16; ++b) {
          m.tab_input_bits[r * 16 + b] = static_cast<std::uint8_t>((m.tab_input_registers[r] >> b) & 1U);
        }
      }
    }
    for (std::uint32_t b = 0; b < discrete_window_.bits; ++b) {
      m.tab_input_bits[b] = load_bit(outputs, discrete_window_, b) ? 1 : 0;
    }
  }

  // TRUE if it closed the connections.
  bool check_watchdog() noexcept {
    if (config_.watchdog.count() == 0 || zeroed_) return false;
    if (clock::now() - last_valid_ < std::chrono::nanoseconds(config_.watchdog.count())) return false;
    zeroed_ = true;
    watchdog_expiries_.fetch_add(1, std::memory_order_relaxed);
    // CODESYS: "the incoming data is set to zero": the data model's, so that a client that only
    // reads afterwards does not bring the old set-points back.
    modbus_mapping_t& m = *mapping_;
    std::fill_n(m.tab_registers, m.nb_registers, std::uint16_t{0});
    std::fill_n(m.tab_bits, m.nb_bits, std::uint8_t{0});
    publish_inputs();
    if (!config_.watchdog_closes_connections || clients_list_.empty()) return false;
    for (const client& c : clients_list_) ::close(c.socket);
    clients_list_.clear();
    clients_.store(0, std::memory_order_relaxed);
    return true;
  }

  modbus_server_config config_;
  image_window holding_window_{}, input_window_{}, coil_window_{}, discrete_window_{};
  std::array<image_window, 2> written_{}, served_{};  // the footprints: set once the configuration is right
  const char* config_error_ = nullptr;                // what make_windows() found wrong
  triple_buffer<input_area> from_clients_{};          // server thread -> cycle start
  triple_buffer<output_area> to_clients_{};           // cycle end -> server thread

  // The server thread's.
  detail::modbus_context context_;
  detail::modbus_mapping mapping_;
  int listen_socket_ = -1;
  int wake_[2] = {-1, -1};
  std::vector<client> clients_list_;
  clock::time_point last_valid_{};
  bool zeroed_ = false;
  std::uint16_t port_ = 0;
  char error_text_[160] = {};

  std::thread thread_;
  std::atomic<bool> stop_requested_{false};
  std::atomic<std::uint64_t> requests_{0}, exceptions_{0}, bad_requests_{0}, connections_{0}, refused_{0},
      closed_idle_{0}, closed_exceptions_{0}, watchdog_expiries_{0};
  std::atomic<std::uint32_t> clients_{0};
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
