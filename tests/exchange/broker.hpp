// A mosquitto broker for the data exchange's tests (Debian's mosquitto), on a free port of
// localhost, bounded as every peer is (peer.hpp).
#pragma once

#include <doctest/doctest.h>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "peer.hpp"

namespace exchange_test {

/// A mosquitto broker on a free port of 127.0.0.1, without persistence (a restart forgets
/// the retained messages), logging connections and subscriptions to a file of its own.
class broker {
 public:
  explicit broker(bool anonymous = true)
      : port_(free_port()),
        log_("/tmp/iecoop-mqtt-" + std::to_string(port_) + ".log"),
        config_(write_config(port_, log_, anonymous)),
        process_({IECOOP_MOSQUITTO, "-c", config_}) {
    REQUIRE(wait_for_port(port_, 5s));
  }
  ~broker() {
    process_.kill(SIGKILL);
    std::remove(config_.c_str());
    std::remove(log_.c_str());
  }
  [[nodiscard]] std::uint16_t port() const { return port_; }
  [[nodiscard]] std::string port_text() const { return std::to_string(port_); }
  void kill() { process_.kill(SIGKILL); }
  void restart() {
    process_.start();
    REQUIRE(wait_for_port(port_, 5s));
  }
  /// What it logged so far (a file log is written line by line).
  [[nodiscard]] std::string log() const {
    std::ifstream in(log_);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  bool wait_for_log(const std::string& text, std::chrono::milliseconds timeout = 5s) const {
    return eventually([&] { return log().find(text) != std::string::npos; }, timeout);
  }

 private:
  static std::string write_config(std::uint16_t port, const std::string& log, bool anonymous) {
    std::remove(log.c_str());
    const std::string path = "/tmp/iecoop-mqtt-" + std::to_string(port) + ".conf";
    std::ofstream out(path);
    out << "listener " << port << " 127.0.0.1\nallow_anonymous " << (anonymous ? "true" : "false")
        << "\npersistence false\nlog_dest file " << log
        << "\nlog_type error\nlog_type warning\nlog_type notice\nlog_type information\nlog_type subscribe\n";
    return path;
  }
  std::uint16_t port_;
  std::string log_;
  std::string config_;
  peer process_;
};

}  // namespace exchange_test
