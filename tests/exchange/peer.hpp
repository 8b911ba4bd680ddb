// Real peers for the data exchange's tests: Debian's mbpoll, python3-pymodbus, mosquitto and
// its clients, started on localhost as child processes. Every child is bounded: it dies with
// the test program (PR_SET_PDEATHSIG), and the peer's destructor kills what still runs.
#pragma once

#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace exchange_test {

using namespace std::chrono_literals;

/// A child process whose stdout and stderr go to a file of its own.
class peer {
 public:
  explicit peer(std::vector<std::string> argv) : argv_(std::move(argv)) { start(); }
  peer(const peer&) = delete;
  peer& operator=(const peer&) = delete;
  ~peer() {
    kill(SIGKILL);
    if (!log_path_.empty()) ::unlink(log_path_.c_str());
  }

  /// Starts it (again, after it was killed): the same command line, a fresh log.
  void start() {
    kill(SIGKILL);
    if (!log_path_.empty()) ::unlink(log_path_.c_str());
    char path[] = "/tmp/iecoop-peer-XXXXXX";
    const int log = ::mkstemp(path);
    log_path_ = path;
    // Everything the child needs is made before fork(): between fork and exec a child of a
    // program with threads may only make async-signal-safe calls (no malloc).
    std::vector<char*> args;
    for (std::string& a : argv_) args.push_back(a.data());
    args.push_back(nullptr);
    const int null = ::open("/dev/null", O_RDONLY);
    const pid_t parent = ::getpid();
    pid_ = ::fork();
    if (pid_ == 0) {
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (::getppid() != parent) ::_exit(127);
      ::dup2(log, 1);
      ::dup2(log, 2);
      ::dup2(null, 0);
      ::execvp(args[0], args.data());
      ::_exit(127);
    }
    ::close(log);
    ::close(null);
  }

  /// Sends `signal` and waits until it has ended (SIGKILL: at once; else up to 5 s, then SIGKILL).
  void kill(int signal = SIGTERM) {
    if (pid_ <= 0) return;
    ::kill(pid_, signal);
    if (wait(5s) == still_running) {
      ::kill(pid_, SIGKILL);
      wait(5s);
    }
    pid_ = -1;
  }

  static constexpr int still_running = -1000;

  /// Waits up to `timeout` for it to end: its exit code (128 + the signal that killed it), or
  /// still_running.
  int wait(std::chrono::milliseconds timeout) {
    if (pid_ <= 0) return exit_code_;
    const auto until = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      int status = 0;
      const pid_t r = ::waitpid(pid_, &status, WNOHANG);
      if (r == pid_) {
        exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        pid_ = -1;
        return exit_code_;
      }
      if (std::chrono::steady_clock::now() >= until) return still_running;
      std::this_thread::sleep_for(2ms);
    }
  }

  [[nodiscard]] bool running() { return pid_ > 0 && wait(0ms) == still_running; }

  /// What it printed so far.
  [[nodiscard]] std::string output() const {
    std::ifstream in(log_path_);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /// Waits up to `timeout` until its output contains `text`.
  bool wait_for_output(const std::string& text, std::chrono::milliseconds timeout) const {
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < until) {
      if (output().find(text) != std::string::npos) return true;
      std::this_thread::sleep_for(5ms);
    }
    return output().find(text) != std::string::npos;
  }

 private:
  std::vector<std::string> argv_;
  std::string log_path_;
  pid_t pid_ = -1;
  int exit_code_ = still_running;
};

/// Runs a command to its end (at most `timeout`, then it is killed): its exit code and output.
struct run_result {
  int exit_code;
  std::string output;
};
inline run_result run(std::vector<std::string> argv, std::chrono::milliseconds timeout = 20s) {
  peer p(std::move(argv));
  const int code = p.wait(timeout);
  std::string output = p.output();
  return {code, output};
}

/// A TCP port that was free a moment ago on 127.0.0.1.
inline std::uint16_t free_port() {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address);
  socklen_t length = sizeof address;
  ::getsockname(s, reinterpret_cast<sockaddr*>(&address), &length);
  ::close(s);
  return ntohs(address.sin_port);
}

/// A connected socket to 127.0.0.1:port, or -1.
inline int connect_to(std::uint16_t port) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    ::close(s);
    return -1;
  }
  return s;
}

/// Waits up to `timeout` until something accepts connections on 127.0.0.1:port.
inline bool wait_for_port(std::uint16_t port, std::chrono::milliseconds timeout) {
  const auto until = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < until) {
    if (const int s = connect_to(port); s >= 0) {
      ::close(s);
      return true;
    }
    std::this_thread::sleep_for(10ms);
  }
  return false;
}

/// Polls `condition` every millisecond for up to `timeout`.
template <class Condition>
bool eventually(Condition condition, std::chrono::milliseconds timeout = 10s) {
  const auto until = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < until) {
    if (condition()) return true;
    std::this_thread::sleep_for(1ms);
  }
  return condition();
}

}  // namespace exchange_test
