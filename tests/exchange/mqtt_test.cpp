// The MQTT bridge (<iecoop/exchange/mqtt.hpp>) against a real broker: each test case starts its
// own mosquitto on a free port, with mosquitto_sub and mosquitto_pub as the other clients. The
// application runs in simulated time in the test's thread (plc.run_for), the bridge's network
// side in its own thread: the tests wait for what crosses with exchange_test::eventually().
#include <doctest/doctest.h>

#include <iecoop/exchange/mqtt.hpp>
#include <iecoop/iecoop.hpp>
#include <iecoop/testing.hpp>

#include "broker.hpp"
#include "peer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace iecoop;
using namespace std::chrono_literals;

namespace mqtt_test {
enum class E_Mode : INT::rep { Off, Manual, Auto };
}  // namespace mqtt_test
template <>
inline constexpr auto iecoop::enum_components<mqtt_test::E_Mode> =
    iecoop::components<mqtt_test::E_Mode::Off, mqtt_test::E_Mode::Manual, mqtt_test::E_Mode::Auto>{};

namespace mqtt_test {
namespace {

using exchange_test::broker;
using exchange_test::eventually;
using exchange_test::peer;

// FUNCTION_BLOCK FB_Axis: a VAR_INPUT a command writes (a plain member), a VAR_OUTPUT.
struct FB_Axis : function_block<FB_Axis> {
  BOOL xEnable;
  LREAL lrVelocity;
  BOOL xActive;
  using VAR_INPUT = pins<&FB_Axis::xEnable, &FB_Axis::lrVelocity>;
  using VAR_OUTPUT = pins<&FB_Axis::xActive>;
  void body() { xActive = xEnable; }
};

// PROGRAM IO_PRG: values of each kind the bridge publishes, and what the program saw of the
// commanded variables in its last cycle.
struct IO_PRG : program<IO_PRG> {
  BOOL bStart;
  var<INT> iCount;
  var<REAL> rTemp;
  var<LREAL> lrRatio;
  var<TIME> tRun;
  var<E_Mode> eMode;
  var<WORD> wStatus;
  TON tDelay;
  FB_Axis fbAxis;
  RAMP_REAL fbRamp;  // a Util block: its pins published as a standard block's are
  // Commanded.
  var<INT> iSetpoint;
  BOOL bPulse;
  var<LTIME> ltWait;
  var<UDINT> udiLimit;
  // What this cycle's programs saw of them (written before the programs run).
  var<INT> iSeenSetpoint;
  BOOL bSeenPulse;
  var<DINT> diPulseCycles;
  void body() {
    tDelay("IN"_ = bStart, "PT"_ = "T#1s500ms"_iec);
    fbRamp("IN"_ = REAL(0.0F), "ASCEND"_ = REAL(10.0F), "DESCEND"_ = REAL(10.0F), "TIMEBASE"_ = "T#1s"_iec);
    fbAxis();
    iSeenSetpoint = iSetpoint;
    bSeenPulse = bPulse;
    if (bPulse) diPulseCycles = diPulseCycles + 1;
  }
};

LTIME ms(std::uint64_t n) { return LTIME::from_ticks(n * 1'000'000U); }

/// mosquitto_sub on `filter`, printing "topic payload" lines, for up to 25 s; ready once
/// subscribed.
class subscriber {
 public:
  subscriber(const broker& b, const std::string& filter)
      : id_("iecoop-sub-" + std::to_string(++count_)),
        process_(
            {IECOOP_MOSQUITTO_SUB, "-h", "127.0.0.1", "-p", b.port_text(), "-i", id_, "-v", "-W", "25", "-t", filter}) {
    REQUIRE(b.wait_for_log(id_ + " 0 " + filter));  // the broker's log of the subscription
  }
  [[nodiscard]] std::string output() const { return process_.output(); }
  bool wait_for(const std::string& text, std::chrono::milliseconds timeout = 5s) const {
    return process_.wait_for_output(text, timeout);
  }
  /// How many lines are messages on `topic`.
  [[nodiscard]] std::size_t count(const std::string& topic) const {
    const std::string text = output();
    std::size_t n = 0;
    for (std::size_t at = text.find(topic + " "); at != std::string::npos; at = text.find(topic + " ", at + 1)) {
      if (at == 0 || text[at - 1] == '\n') ++n;
    }
    return n;
  }

 private:
  static inline int count_ = 0;
  std::string id_;
  peer process_;
};

/// The retained messages under `filter` a client that subscribes now gets.
/// (Up to `count` of them, and within `seconds`: it ends at the first message that is not
/// retained.)
std::string retained(const broker& b, const std::string& filter, int count, int seconds = 3) {
  return exchange_test::run({IECOOP_MOSQUITTO_SUB, "-h", "127.0.0.1", "-p", b.port_text(), "-v", "--retained-only",
                             "-C", std::to_string(count), "-W", std::to_string(seconds), "-t", filter},
                            10s)
      .output;
}

/// mosquitto_pub: one message (QoS 1), or, with several payloads, one message per payload over
/// one connection (in that order).
void publish(const broker& b, const std::string& topic, const std::vector<std::string>& payloads, bool retain = false) {
  if (payloads.size() == 1) {
    std::vector<std::string> argv{
        IECOOP_MOSQUITTO_PUB, "-h", "127.0.0.1", "-p", b.port_text(), "-q", "1", "-t", topic, "-m", payloads[0]};
    if (retain) argv.push_back("-r");
    REQUIRE(exchange_test::run(argv, 10s).exit_code == 0);
    return;
  }
  std::string lines;
  for (const std::string& p : payloads) lines += p + "\n";
  const std::string script = "printf '%s' \"$0\" | " + std::string(IECOOP_MOSQUITTO_PUB) + " -h 127.0.0.1 -p " +
                             b.port_text() + " -q 1 -l -t " + topic;
  REQUIRE(exchange_test::run({"/bin/sh", "-c", script, lines}, 10s).exit_code == 0);
}

mqtt_bridge_config test_config(const broker& b, std::string prefix, std::string client_id) {
  mqtt_bridge_config config;
  config.host = "127.0.0.1";
  config.port = b.port();
  config.client_id = std::move(client_id);
  config.topic_prefix = std::move(prefix);
  config.keepalive = 5;
  config.check_interval = ms(5);
  config.reconnect_min = ms(100);
  config.reconnect_max = ms(400);
  config.command_queue = 16;
  return config;
}

/// Runs one cycle of task Fast (10 ms).
template <class Application>
void cycle(Application& plc) {
  plc.run_for(ms(10));
}

}  // namespace
}  // namespace mqtt_test

using namespace mqtt_test;

TEST_SUITE("MQTT bridge") {
  TEST_CASE("values are published on change, as JSON, on the channels' topics, retained") {
    broker b;
    subscriber sub(b, "plant/line1/#");
    application plc{task<IO_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.start();
    IO_PRG& io = plc.get<IO_PRG>();
    io.bStart = TRUE;
    io.iCount = -5;
    io.rTemp = REAL(21.5);
    io.lrRatio = LREAL(std::numeric_limits<double>::quiet_NaN());
    io.tRun = "T#1s500ms"_iec;
    io.eMode = E_Mode::Auto;
    io.wStatus = WORD(255);
    mqtt_bridge<24, 2> mqtt{test_config(b, "plant/line1", "mqtt-test-values")};
    CHECK(mqtt.add("IO_PRG.bStart", io.bStart));
    CHECK(mqtt.add("IO_PRG", "iCount", io.iCount));
    CHECK(mqtt.add("IO_PRG.rTemp", io.rTemp));
    CHECK(mqtt.add("IO_PRG.lrRatio", io.lrRatio));
    CHECK(mqtt.add("IO_PRG.tRun", io.tRun));
    CHECK(mqtt.add("IO_PRG.eMode", io.eMode));
    CHECK(mqtt.add("IO_PRG.wStatus", io.wStatus));
    CHECK(mqtt.add_pins("IO_PRG.tDelay", io.tDelay));  // IN, PT, Q, ET
    CHECK(mqtt.add_pins("IO_PRG.fbRamp", io.fbRamp));  // IN, ASCEND, DESCEND, TIMEBASE, RESET, OUT
    mqtt.attach(plc.task("Fast"));
    REQUIRE(mqtt.start() == nullptr);
    REQUIRE(eventually([&] { return mqtt.statistics().connected; }));
    CHECK(sub.wait_for("plant/line1/status online"));
    cycle(plc);  // cycle 0
    CHECK(sub.wait_for("plant/line1/IO_PRG/tDelay/ET "));
    CHECK(sub.wait_for(
        "plant/line1/IO_PRG/fbRamp/OUT {\"value\":0"));  // the last pin of the last channel: all of cycle 0 is in
    const std::string first = sub.output();
    CHECK(first.find("plant/line1/IO_PRG/bStart {\"value\":true,\"type\":\"BOOL\",\"cycle\":0}\n") !=
          std::string::npos);
    CHECK(first.find("plant/line1/IO_PRG/iCount {\"value\":-5,\"type\":\"INT\",\"cycle\":0}\n") != std::string::npos);
    CHECK(first.find("plant/line1/IO_PRG/rTemp {\"value\":21.5,\"type\":\"REAL\",\"cycle\":0}\n") != std::string::npos);
    CHECK(first.find("plant/line1/IO_PRG/lrRatio {\"value\":null,\"type\":\"LREAL\",\"cycle\":0}\n") !=
          std::string::npos);
    CHECK(first.find("plant/line1/IO_PRG/tRun {\"value\":\"T#1s500ms\",\"type\":\"TIME\",\"cycle\":0}\n") !=
          std::string::npos);
    CHECK(first.find("plant/line1/IO_PRG/eMode {\"value\":\"Auto\",\"type\":\"E_Mode\",\"cycle\":0}\n") !=
          std::string::npos);
    CHECK(first.find("plant/line1/IO_PRG/wStatus {\"value\":255,\"type\":\"WORD\",\"cycle\":0}\n") !=
          std::string::npos);
    CHECK(first.find("plant/line1/IO_PRG/tDelay/PT {\"value\":\"T#1s500ms\",\"type\":\"TIME\",\"cycle\":0}\n") !=
          std::string::npos);
    CHECK(first.find("plant/line1/IO_PRG/tDelay/ET {\"value\":\"T#0ms\",\"type\":\"TIME\",\"cycle\":0}\n") !=
          std::string::npos);
    CHECK(first.find("plant/line1/IO_PRG/fbRamp/TIMEBASE {\"value\":\"T#1s\",\"type\":\"TIME\",\"cycle\":0}\n") !=
          std::string::npos);
    CHECK(first.find("plant/line1/IO_PRG/fbRamp/OUT {\"value\":0") != std::string::npos);

    // A change is published; what did not change is not.
    io.iCount = 7;
    io.eMode = E_Mode::Manual;
    cycle(plc);  // cycle 1: the timer's ET runs too
    CHECK(sub.wait_for("plant/line1/IO_PRG/iCount {\"value\":7,\"type\":\"INT\",\"cycle\":1}\n"));
    CHECK(sub.wait_for("plant/line1/IO_PRG/eMode {\"value\":\"Manual\",\"type\":\"E_Mode\",\"cycle\":1}\n"));
    CHECK(sub.wait_for("plant/line1/IO_PRG/tDelay/ET {\"value\":\"T#10ms\",\"type\":\"TIME\",\"cycle\":1}\n"));
    for (int i = 0; i < 5; ++i) cycle(plc);  // only ET changes
    CHECK(sub.wait_for("plant/line1/IO_PRG/tDelay/ET {\"value\":\"T#60ms\",\"type\":\"TIME\",\"cycle\":6}\n"));
    std::this_thread::sleep_for(100ms);
    CHECK(sub.count("plant/line1/IO_PRG/bStart") == 1);
    CHECK(sub.count("plant/line1/IO_PRG/iCount") == 2);
    CHECK(sub.count("plant/line1/IO_PRG/rTemp") == 1);
    CHECK(sub.count("plant/line1/IO_PRG/lrRatio") == 1);  // NaN is NaN: unchanged
    CHECK(sub.count("plant/line1/IO_PRG/tDelay/IN") == 1);
    CHECK(sub.count("plant/line1/IO_PRG/fbRamp/OUT") == 1);  // IN 0: OUT stays 0

    // Retained: a client that subscribes later gets the newest of each at once.
    const std::string late = retained(b, "plant/line1/#", 18);
    CHECK(late.find("plant/line1/status online\n") != std::string::npos);
    CHECK(late.find("plant/line1/IO_PRG/iCount {\"value\":7,\"type\":\"INT\",\"cycle\":1}\n") != std::string::npos);
    CHECK(late.find("plant/line1/IO_PRG/tDelay/ET {\"value\":\"T#60ms\",\"type\":\"TIME\",\"cycle\":6}\n") !=
          std::string::npos);
    CHECK(late.find("plant/line1/IO_PRG/bStart {\"value\":true,\"type\":\"BOOL\",\"cycle\":0}\n") != std::string::npos);
    const mqtt_bridge_statistics s = mqtt.statistics();
    CHECK(s.connects == 1);
    CHECK(s.snapshots == 7);
    CHECK(s.publish_errors == 0);
    // "online", 17 values, 3 changes, then ET's 5 changes, of which the bridge may have seen
    // fewer: changes between two of its looks are coalesced (the newest is published).
    CHECK(s.published >= 1 + 17 + 3 + 1);
    CHECK(s.published <= 1 + 17 + 3 + 5);
  }

  TEST_CASE("cyclic publication: every channel every period, changed or not, not retained when told") {
    broker b;
    subscriber sub(b, "cyclic/#");
    application plc{task<IO_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.start();
    IO_PRG& io = plc.get<IO_PRG>();
    io.iCount = 3;
    mqtt_bridge_config config = test_config(b, "cyclic", "mqtt-test-cyclic");
    config.publish_on_change = false;
    config.publish_period = ms(100);
    config.retain = false;
    config.qos = 0;
    mqtt_bridge<4, 1> mqtt{config};
    CHECK(mqtt.add("IO_PRG.iCount", io.iCount));
    CHECK(mqtt.add("IO_PRG.bStart", io.bStart));
    mqtt.attach(plc.task("Fast"));
    REQUIRE(mqtt.start() == nullptr);
    cycle(plc);
    REQUIRE(sub.wait_for("cyclic/IO_PRG/iCount {\"value\":3,\"type\":\"INT\",\"cycle\":0}"));
    const auto start = std::chrono::steady_clock::now();
    CHECK(eventually([&] { return sub.count("cyclic/IO_PRG/iCount") >= 6 && sub.count("cyclic/IO_PRG/bStart") >= 6; },
                     5s));
    const auto took = std::chrono::steady_clock::now() - start;
    CHECK(took >= 300ms);  // 5 more periods of 100 ms (the first may have been seen late)
    // Changes alone are not published (publish_on_change off): a value that changes every
    // cycle for a while is published once per period, not once per change.
    const std::size_t before = sub.count("cyclic/IO_PRG/iCount");
    const auto changes_from = std::chrono::steady_clock::now();
    for (int i = 0; i < 30; ++i) {
      io.iCount = io.iCount + 1;
      cycle(plc);
      std::this_thread::sleep_for(10ms);  // twice the check interval: with on-change, each one published
    }
    const auto periods = (std::chrono::steady_clock::now() - changes_from) / 100ms;
    std::this_thread::sleep_for(20ms);  // the last ones on their way
    const std::size_t published = sub.count("cyclic/IO_PRG/iCount") - before;
    CHECK(published >= 1);
    CHECK(published <= static_cast<std::size_t>(periods) + 2);
    CHECK(sub.wait_for("cyclic/IO_PRG/iCount {\"value\":33,\"type\":\"INT\",\"cycle\":30}"));  // the period's
    // Not retained: a late subscriber gets the status only.
    CHECK(retained(b, "cyclic/#", 3) == "cyclic/status online\n");
  }

  TEST_CASE("start() checks the configuration and the names") {
    broker b;
    application plc{task<IO_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.start();
    IO_PRG& io = plc.get<IO_PRG>();
    {
      mqtt_bridge_config config = test_config(b, "plant/#", "x");
      mqtt_bridge<4, 1> mqtt{config};
      const char* error = mqtt.start();
      REQUIRE(error != nullptr);
      CHECK(std::string_view(error).starts_with("iecoop: topic_prefix"));
      CHECK_FALSE(mqtt.running());
    }
    {
      mqtt_bridge_config config = test_config(b, "p", "x");
      config.qos = 3;
      mqtt_bridge<4, 1> mqtt{config};
      CHECK(mqtt.start() != nullptr);
    }
    {
      mqtt_bridge_config config = test_config(b, "p", "x");
      config.publish_on_change = false;
      mqtt_bridge<4, 1> mqtt{config};
      CHECK(mqtt.add("IO_PRG.iCount", io.iCount));
      CHECK(mqtt.start() != nullptr);  // it would publish only at connect
    }
    {
      mqtt_bridge<4, 1> mqtt{test_config(b, "p", "x")};
      CHECK(mqtt.add("IO_PRG.status.set", io.iCount));
      CHECK(mqtt.start() != nullptr);  // would take a command's topic
    }
    {
      mqtt_bridge<4, 1> mqtt{test_config(b, "p", "x")};
      CHECK(mqtt.add("IO_PRG.i+", io.iCount));
      CHECK(mqtt.start() != nullptr);  // a wildcard in a topic
    }
    {
      testing::expect_faults faults;  // the test kit's: faults recorded, not failing the case
      mqtt_bridge<4, 1> mqtt{test_config(b, "p", "x")};
      CHECK(mqtt.command("IO_PRG.iSetpoint", io.iSetpoint));
      CHECK_FALSE(mqtt.command("IO_PRG.bPulse", io.bPulse));  // MaxCommands is 1
      CHECK(faults.count() == 1);
      mqtt_bridge<4, 4> other{test_config(b, "p", "x")};
      CHECK_FALSE(other.command("IO_PRG..x", io.bPulse));           // an empty part
      CHECK_FALSE(other.command("IO_PRG/x", io.bPulse));            // a level separator
      CHECK_FALSE(other.command("IO_PRG.x", io.iSetpoint, 10, 0));  // max < min
      CHECK(other.command("IO_PRG.x", io.bPulse));
      CHECK_FALSE(other.command("IO_PRG.x", io.iSetpoint));  // the name is taken
      CHECK(faults.count() == 5);
      other.attach(plc.task("Fast"));
      CHECK_FALSE(other.command("IO_PRG.y", io.iSetpoint));  // attached: fixed
      CHECK_FALSE(other.add("IO_PRG.y", io.iSetpoint));
      CHECK(faults.count() == 7);
      other.detach();
      CHECK(other.command("IO_PRG.y", io.iSetpoint));
    }
  }

  TEST_CASE("status: online at connect, offline at stop(), a clean disconnect") {
    broker b;
    subscriber sub(b, "stop/#");
    application plc{task<IO_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.start();
    mqtt_bridge<4, 1> mqtt{test_config(b, "stop", "mqtt-test-stop")};
    CHECK(mqtt.add("IO_PRG.iCount", plc.get<IO_PRG>().iCount));
    mqtt.attach(plc.task("Fast"));
    REQUIRE(mqtt.start() == nullptr);
    CHECK(mqtt.running());
    CHECK(sub.wait_for("stop/status online\n"));
    cycle(plc);
    CHECK(sub.wait_for("stop/IO_PRG/iCount "));
    mqtt.stop();
    CHECK_FALSE(mqtt.running());
    const mqtt_bridge_statistics s = mqtt.statistics();
    CHECK_FALSE(s.connected);
    CHECK(s.connects == 1);
    CHECK(s.disconnects == 1);
    CHECK(sub.wait_for("stop/status offline\n"));
    CHECK(retained(b, "stop/status", 1) == "stop/status offline\n");
    // The broker saw a DISCONNECT (not a lost connection, which would send the will).
    CHECK(eventually([&] { return b.log().find("Client mqtt-test-stop disconnected.") != std::string::npos; }, 2s));
    CHECK(b.log().find("Client mqtt-test-stop closed its connection") == std::string::npos);
    // The task goes on without it; a start() connects again.
    cycle(plc);
    REQUIRE(mqtt.start() == nullptr);
    CHECK(eventually([&] { return mqtt.statistics().connects == 2; }));
    CHECK(eventually([&] { return retained(b, "stop/status", 1) == "stop/status online\n"; }, 5s));
  }

  TEST_CASE("last will: a controller that dies without disconnecting is offline") {
    broker b;
    subscriber sub(b, "child/#");
    peer child({IECOOP_MQTT_CHILD, b.port_text(), "child"});
    REQUIRE(child.wait_for_output("connected", 5s));
    CHECK(sub.wait_for("child/status online\n"));
    CHECK(sub.wait_for("child/CHILD_PRG/iCount {\"value\":"));
    CHECK(sub.count("child/status") == 1);
    child.kill(SIGKILL);
    CHECK(sub.wait_for("child/status offline\n"));
    const std::string out = sub.output();
    CHECK(out.find("child/status online\n") < out.find("child/status offline\n"));
    CHECK(retained(b, "child/status", 1) == "child/status offline\n");
    // The broker saw the connection end without a DISCONNECT (what the stop() test rules out).
    CHECK(b.wait_for_log("Client iecoop-mqtt-child closed its connection"));
  }

  TEST_CASE("commands are written at the start of the next cycle, in order, one per variable and cycle") {
    broker b;
    subscriber sub(b, "cmd/#");
    application plc{task<IO_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.start();
    IO_PRG& io = plc.get<IO_PRG>();
    mqtt_bridge<8, 8> mqtt{test_config(b, "cmd", "mqtt-test-commands")};
    CHECK(mqtt.add("IO_PRG.iSetpoint", io.iSetpoint));
    CHECK(mqtt.command("IO_PRG.iSetpoint", io.iSetpoint, 0, 3000));  // a var<INT>
    CHECK(mqtt.command("IO_PRG.bPulse", io.bPulse));                 // a plain BOOL
    CHECK(mqtt.command("IO_PRG.tRun", io.tRun));
    CHECK(mqtt.command("IO_PRG.ltWait", io.ltWait));
    CHECK(mqtt.command("IO_PRG.eMode", io.eMode));
    CHECK(mqtt.command("IO_PRG.rTemp", io.rTemp));
    CHECK(mqtt.command("IO_PRG.fbAxis.lrVelocity", io.fbAxis.lrVelocity));  // a block's VAR_INPUT
    CHECK(mqtt.command("IO_PRG.wStatus", io.wStatus));
    mqtt.attach(plc.task("Fast"));
    REQUIRE(mqtt.start() == nullptr);
    REQUIRE(sub.wait_for("cmd/status online\n"));
    cycle(plc);
    REQUIRE(sub.wait_for("cmd/IO_PRG/iSetpoint {\"value\":0,"));

    SUBCASE("accepted, written before the programs of the next cycle, and not before it") {
      publish(b, "cmd/IO_PRG/iSetpoint/set", {"1234"});
      REQUIRE(eventually([&] { return mqtt.statistics().commands_accepted == 1; }));
      std::this_thread::sleep_for(50ms);
      CHECK(io.iSetpoint == 0);  // queued: no cycle ran
      CHECK(mqtt.statistics().commands_applied == 0);
      cycle(plc);
      CHECK(io.iSeenSetpoint == 1234);  // the programs saw it in the very cycle
      CHECK(mqtt.statistics().commands_applied == 1);
      // ... and the new value is published.
      CHECK(sub.wait_for("cmd/IO_PRG/iSetpoint {\"value\":1234,\"type\":\"INT\",\"cycle\":1}\n"));
    }

    SUBCASE("every payload form: JSON scalars, IEC literals, JSON strings, {\"value\": ...}") {
      publish(b, "cmd/IO_PRG/iSetpoint/set", {"16#FF"});
      publish(b, "cmd/IO_PRG/bPulse/set", {"true"});
      publish(b, "cmd/IO_PRG/tRun/set", {"\"T#2s\""});
      publish(b, "cmd/IO_PRG/ltWait/set", {"LTIME#1ms500us"});
      publish(b, "cmd/IO_PRG/eMode/set", {"\"Auto\""});
      publish(b, "cmd/IO_PRG/rTemp/set", {"{\"value\": -3.5}"});
      publish(b, "cmd/IO_PRG/fbAxis/lrVelocity/set", {" { \"value\" : \"1.25E2\" } "});
      publish(b, "cmd/IO_PRG/wStatus/set", {"WORD#2#1010"});
      REQUIRE(eventually([&] { return mqtt.statistics().commands_accepted == 8; }));
      cycle(plc);
      CHECK(mqtt.statistics().commands_applied == 8);
      CHECK(io.iSetpoint == 255);
      CHECK(io.bSeenPulse == TRUE);
      CHECK(io.tRun == "T#2s"_iec);
      CHECK(io.ltWait == LTIME::from_ticks(1'500'000));
      CHECK(io.eMode == E_Mode::Auto);
      CHECK(io.rTemp == REAL(-3.5));
      CHECK(io.fbAxis.lrVelocity == LREAL(125.0));
      CHECK(io.wStatus == WORD(10));
      publish(b, "cmd/IO_PRG/bPulse/set", {"FALSE"});
      publish(b, "cmd/IO_PRG/eMode/set", {"E_Mode#Manual"});
      publish(b, "cmd/IO_PRG/tRun/set", {"{\"value\":\"T#1m\"}"});
      REQUIRE(eventually([&] { return mqtt.statistics().commands_accepted == 11; }));
      cycle(plc);
      CHECK(io.bSeenPulse == FALSE);
      CHECK(io.eMode == E_Mode::Manual);
      CHECK(io.tRun == "T#1m"_iec);
      CHECK(mqtt.statistics().commands_rejected == 0);
    }

    SUBCASE("in order; a second command for a variable waits for the next cycle: a pulse is seen") {
      publish(b, "cmd/IO_PRG/bPulse/set", {"TRUE", "FALSE"});
      publish(b, "cmd/IO_PRG/iSetpoint/set", {"1", "2", "3"});
      REQUIRE(eventually([&] { return mqtt.statistics().commands_accepted == 5; }));
      cycle(plc);
      CHECK(io.bSeenPulse == TRUE);
      CHECK(io.iSeenSetpoint == 0);  // queued behind bPulse's FALSE, which waits for this cycle's end
      cycle(plc);
      CHECK(io.bSeenPulse == FALSE);
      CHECK(io.iSeenSetpoint == 1);
      // Each value is published (waiting for it: changes faster than the bridge looks are
      // coalesced).
      CHECK(sub.wait_for("cmd/IO_PRG/iSetpoint {\"value\":1,"));
      cycle(plc);
      CHECK(io.iSeenSetpoint == 2);
      CHECK(sub.wait_for("cmd/IO_PRG/iSetpoint {\"value\":2,"));
      cycle(plc);
      CHECK(io.iSeenSetpoint == 3);
      CHECK(sub.wait_for("cmd/IO_PRG/iSetpoint {\"value\":3,"));
      CHECK(io.diPulseCycles == 1);  // TRUE for exactly one cycle
      CHECK(mqtt.statistics().commands_applied == 5);
      const std::string out = sub.output();
      CHECK(out.find("cmd/IO_PRG/iSetpoint {\"value\":1,") < out.find("cmd/IO_PRG/iSetpoint {\"value\":2,"));
      CHECK(out.find("cmd/IO_PRG/iSetpoint {\"value\":2,") < out.find("cmd/IO_PRG/iSetpoint {\"value\":3,"));
    }

    SUBCASE("rejected: counted, not written, the reason on .../set/rejected") {
      struct bad {
        std::string topic;
        std::string payload;
        std::string reason;
      };
      const std::vector<bad> cases{
          {"cmd/IO_PRG/iSetpoint/set", "abc", "a digit was expected"},
          {"cmd/IO_PRG/iSetpoint/set", "70000", "the value does not fit the type"},
          {"cmd/IO_PRG/iSetpoint/set", "4000", "above the command's maximum"},
          {"cmd/IO_PRG/iSetpoint/set", "-1", "below the command's minimum"},
          {"cmd/IO_PRG/iSetpoint/set", "12.5", "unexpected characters after the literal"},
          {"cmd/IO_PRG/iSetpoint/set", "{\"value\":", "malformed JSON"},
          {"cmd/IO_PRG/iSetpoint/set", "{\"value\":1,\"x\":2}", "a command object has one member"},
          {"cmd/IO_PRG/iSetpoint/set", "\"12", "a JSON string without its closing quote"},
          {"cmd/IO_PRG/iSetpoint/set", "null", "null is no value"},
          {"cmd/IO_PRG/bPulse/set", "2", "a digit was expected"},
          {"cmd/IO_PRG/tRun/set", "2s", "the literal needs its type prefix"},
          {"cmd/IO_PRG/tRun/set", "LTIME#2s", "the type prefix names another type"},
          {"cmd/IO_PRG/eMode/set", "\"Stop\"", "no component of the enumeration has this name"},
          {"cmd/IO_PRG/eMode/set", "7", "no component of the enumeration has this value"},
          {"cmd/IO_PRG/rTemp/set", "1e39", "the value does not fit the type"},
          {"cmd/IO_PRG/iUnknown/set", "1", "no command of this name"},
          {"cmd/IO_PRG/fbAxis/xEnable/set", "TRUE", "no command of this name"},
      };
      for (std::size_t i = 0; i < cases.size(); ++i) {
        CAPTURE(cases[i].payload);
        publish(b, cases[i].topic, {cases[i].payload});
        CHECK(eventually([&] { return mqtt.statistics().commands_rejected == i + 1; }));
        CHECK(sub.wait_for(cases[i].topic + "/rejected {\"reason\":\"" + cases[i].reason));
      }
      // A retained command reaches a subscription made before it without the retain flag
      // (MQTT 3.1.1, 3.3.1.3): a live command, written; its replay at a later connect is
      // refused (the next test case).
      publish(b, "cmd/IO_PRG/iSetpoint/set", {"5"}, true);
      REQUIRE(eventually([&] { return mqtt.statistics().commands_accepted == 1; }));
      CHECK(mqtt.statistics().commands_rejected == cases.size());
      for (int i = 0; i < 3; ++i) cycle(plc);
      CHECK(io.iSetpoint == 5);
      CHECK(io.bPulse == FALSE);
      CHECK(io.tRun == TIME{});
      CHECK(io.eMode == E_Mode::Off);
      CHECK(io.rTemp == REAL(0.0));
      const mqtt_bridge_statistics s = mqtt.statistics();
      CHECK(s.commands_applied == 1);
      CHECK(s.commands_dropped == 0);
      // Rejections are not retained.
      const std::string late = retained(b, "cmd/#", 10, 1);
      CHECK(late.find("cmd/status online\n") != std::string::npos);
      CHECK(late.find("/rejected") == std::string::npos);
    }
  }

  TEST_CASE("a retained command: written once, when it is published, never when it is replayed") {
    // MQTT 3.1.1 section 3.3.1.3: a broker delivers a message published with retain to the
    // clients subscribed at that moment with the retain flag cleared (the bridge cannot tell
    // it from any other command: written), and again, flagged, at every later subscription
    // (every connect and reconnect: rejected, so a stale set-point is never written again).
    broker b;
    subscriber sub(b, "replay/#");
    application plc{task<IO_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.start();
    IO_PRG& io = plc.get<IO_PRG>();
    mqtt_bridge<4, 1> mqtt{test_config(b, "replay", "mqtt-test-replay")};
    CHECK(mqtt.command("IO_PRG.iSetpoint", io.iSetpoint));
    mqtt.attach(plc.task("Fast"));

    SUBCASE("published retained before the bridge connects: replayed at connect, rejected") {
      publish(b, "replay/IO_PRG/iSetpoint/set", {"77"}, true);
      REQUIRE(mqtt.start() == nullptr);
      CHECK(eventually([&] { return mqtt.statistics().commands_rejected == 1; }));
      CHECK(sub.wait_for("replay/IO_PRG/iSetpoint/set/rejected {\"reason\":\"a retained command is not written"));
      cycle(plc);
      CHECK(io.iSetpoint == 0);
      CHECK(mqtt.statistics().commands_accepted == 0);
    }

    SUBCASE("published retained while the bridge is connected: written once, rejected on every reconnect") {
      REQUIRE(mqtt.start() == nullptr);
      REQUIRE(sub.wait_for("replay/status online\n"));
      publish(b, "replay/IO_PRG/iSetpoint/set", {"55"}, true);
      REQUIRE(eventually([&] { return mqtt.statistics().commands_accepted == 1; }));
      cycle(plc);
      CHECK(io.iSetpoint == 55);  // live: written, as any command
      CHECK(mqtt.statistics().commands_rejected == 0);
      io.iSetpoint = 0;  // the program moves on
      const std::uint64_t accepted = mqtt.statistics().commands_accepted;
      // A reconnect subscribes again; the broker replays the retained message, flagged.
      mqtt.stop();
      REQUIRE(mqtt.start() == nullptr);
      CHECK(eventually([&] { return mqtt.statistics().commands_rejected == 1; }));
      CHECK(sub.wait_for("replay/IO_PRG/iSetpoint/set/rejected {\"reason\":\"a retained command is not written"));
      cycle(plc);
      cycle(plc);
      CHECK(io.iSetpoint == 0);  // not written again
      CHECK(mqtt.statistics().commands_accepted == accepted);
    }
    publish(b, "replay/IO_PRG/iSetpoint/set", {""}, true);  // clear the retained message
  }

  TEST_CASE("a broker that refuses the connection: counted, tried again after the back-off") {
    broker b(false);  // no anonymous clients
    application plc{task<IO_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.start();
    mqtt_bridge<4, 1> mqtt{test_config(b, "refused", "mqtt-test-refused")};
    CHECK(mqtt.add("IO_PRG.iCount", plc.get<IO_PRG>().iCount));
    mqtt.attach(plc.task("Fast"));
    REQUIRE(mqtt.start() == nullptr);  // not an error: the bridge keeps trying
    const auto from = std::chrono::steady_clock::now();
    CHECK(eventually([&] { return mqtt.statistics().refused >= 3; }, 5s));
    // 100, 200 and 400 ms between the attempts (reconnect_min 100 ms, reconnect_max 400 ms): the
    // third refusal comes 300 ms after the first, which may have been under way at `from`.
    CHECK(std::chrono::steady_clock::now() - from >= 250ms);
    cycle(plc);
    const mqtt_bridge_statistics s = mqtt.statistics();
    CHECK_FALSE(s.connected);
    CHECK(s.connects == 0);
    CHECK(s.published == 0);
  }

  TEST_CASE("a full command queue drops the command, counted") {
    broker b;
    subscriber sub(b, "queue/#");
    application plc{task<IO_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.start();
    IO_PRG& io = plc.get<IO_PRG>();
    mqtt_bridge_config config = test_config(b, "queue", "mqtt-test-queue");
    config.command_queue = 4;
    mqtt_bridge<4, 1> mqtt{config};
    CHECK(mqtt.command("IO_PRG.iSetpoint", io.iSetpoint));
    mqtt.attach(plc.task("Fast"));
    REQUIRE(mqtt.start() == nullptr);
    REQUIRE(eventually([&] { return mqtt.statistics().connected; }));
    REQUIRE(b.wait_for_log("mqtt-test-queue 1 queue/+/+/set"));  // subscribed
    publish(b, "queue/IO_PRG/iSetpoint/set", {"1", "2", "3", "4", "5", "6"});
    REQUIRE(eventually([&] { return mqtt.statistics().commands_dropped == 2; }));
    CHECK(mqtt.statistics().commands_accepted == 4);
    CHECK(mqtt.statistics().commands_rejected == 0);
    CHECK(sub.wait_for("queue/IO_PRG/iSetpoint/set/rejected {\"reason\":\"the command queue is full"));
    CHECK(sub.count("queue/IO_PRG/iSetpoint/set/rejected") == 2);
    std::vector<int> seen;
    for (int i = 0; i < 6; ++i) {
      cycle(plc);
      seen.push_back(io.iSeenSetpoint.get().value());
    }
    CHECK(seen == std::vector<int>{1, 2, 3, 4, 4, 4});
    // Room again.
    publish(b, "queue/IO_PRG/iSetpoint/set", {"9"});
    REQUIRE(eventually([&] { return mqtt.statistics().commands_accepted == 5; }));
    cycle(plc);
    CHECK(io.iSeenSetpoint == 9);
  }

  TEST_CASE("broker restart: reconnects by itself, republishes, commands work again, the task never waits") {
    broker b;
    application plc{task<IO_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.start();
    IO_PRG& io = plc.get<IO_PRG>();
    mqtt_bridge<8, 2> mqtt{test_config(b, "restart", "mqtt-test-restart")};
    CHECK(mqtt.add("IO_PRG.iCount", io.iCount));
    CHECK(mqtt.add("IO_PRG.iSetpoint", io.iSetpoint));
    CHECK(mqtt.command("IO_PRG.iSetpoint", io.iSetpoint));
    mqtt.attach(plc.task("Fast"));
    REQUIRE(mqtt.start() == nullptr);
    REQUIRE(eventually([&] { return mqtt.statistics().connected; }));
    io.iCount = 1;
    cycle(plc);
    CHECK(eventually([&] { return retained(b, "restart/IO_PRG/iCount", 1).find("\"value\":1,") != std::string::npos; },
                     5s));

    b.kill();
    REQUIRE(eventually([&] { return !mqtt.statistics().connected; }));
    CHECK(mqtt.statistics().disconnects == 1);
    // The task runs on while the broker is away, and while the bridge tries to reconnect.
    std::chrono::steady_clock::duration longest{}, total{};
    const auto until = std::chrono::steady_clock::now() + 600ms;
    int cycles = 0;
    while (std::chrono::steady_clock::now() < until) {
      io.iCount = io.iCount + 1;
      const auto t0 = std::chrono::steady_clock::now();
      cycle(plc);
      const auto took = std::chrono::steady_clock::now() - t0;
      longest = std::max(longest, took);
      total += took;
      ++cycles;
      std::this_thread::sleep_for(1ms);
    }
    CHECK(cycles > 20);
    // A cycle with a capture and the commands takes microseconds, and never waits for the
    // network (a reconnect attempt, a lock the bridge's thread holds while in libmosquitto):
    // on average far below a millisecond; the longest allows for the system's preemption on a
    // machine busy with other tests (CI runs them in parallel, some under ThreadSanitizer).
    CHECK(total / cycles < 1ms);
    CHECK(longest < 250ms);
    CHECK(mqtt.statistics().connects == 1);

    b.restart();  // the same port, no retained messages (no persistence)
    REQUIRE(eventually([&] { return mqtt.statistics().connects == 2; }, 5s));
    CHECK(mqtt.statistics().connected);
    const std::string count = "\"value\":" + std::to_string(io.iCount.get().value()) + ",";
    CHECK(eventually([&] { return retained(b, "restart/status", 1) == "restart/status online\n"; }, 5s));
    CHECK(eventually([&] { return retained(b, "restart/IO_PRG/iCount", 1).find(count) != std::string::npos; }, 5s));
    CHECK(retained(b, "restart/IO_PRG/iSetpoint", 1).find("\"value\":0,") != std::string::npos);
    // Subscribed again.
    publish(b, "restart/IO_PRG/iSetpoint/set", {"42"});
    REQUIRE(eventually([&] { return mqtt.statistics().commands_accepted == 1; }));
    cycle(plc);
    CHECK(io.iSeenSetpoint == 42);
    CHECK(eventually(
        [&] { return retained(b, "restart/IO_PRG/iSetpoint", 1).find("\"value\":42,") != std::string::npos; }, 5s));
  }
}
