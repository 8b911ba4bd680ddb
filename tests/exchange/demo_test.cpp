// The demo's --modbus and --mqtt (examples/demo.cpp): the conveyor, run in real time, watched with
// mbpoll and mosquitto_sub and given a batch size with mosquitto_pub, as the README shows.
// Built where the examples are (IECOOP_DEMO: the demo's path).
#include <doctest/doctest.h>

#include <csignal>
#include <string>
#include <thread>

#include "broker.hpp"
#include "peer.hpp"

#ifdef IECOOP_DEMO

using namespace exchange_test;

TEST_CASE("demo: --modbus and --mqtt let mbpoll and mosquitto watch the conveyor, and set its batch size") {
  broker mqtt;
  const std::uint16_t modbus_port = free_port();
  peer demo({IECOOP_DEMO, "--realtime", "60", "--motor", "vfd", "--modbus", std::to_string(modbus_port), "--mqtt",
             "127.0.0.1:" + mqtt.port_text()});
  REQUIRE_MESSAGE(demo.wait_for_output("modbus   serving on port " + std::to_string(modbus_port), 20s), demo.output());
  REQUIRE(wait_for_port(modbus_port, 5s));

  // The scenario starts the belt after 0.5 s: the drive enable (%QX0.0, bit 0 of input
  // register 0) and a speed reference (%QW1, input register 1) that is not 0.
  REQUIRE(eventually(
      [&] {
        const run_result r = run({IECOOP_MBPOLL, "-m", "tcp", "-p", std::to_string(modbus_port), "-1", "-t", "3", "-r",
                                  "1", "-c", "2", "127.0.0.1"});
        return r.exit_code == 0 && r.output.find("[1]: \t1") != std::string::npos &&
               r.output.find("[2]: \t0\n") == std::string::npos;
      },
      10s));

  // The values are retained under iecoop/demo/: a subscriber that comes now gets them.
  const run_result values =
      run({IECOOP_MOSQUITTO_SUB, "-h", "127.0.0.1", "-p", mqtt.port_text(), "-t", "iecoop/demo/#", "-v", "-W", "2"});
  CHECK(values.output.find("iecoop/demo/status online") != std::string::npos);
  CHECK(values.output.find("iecoop/demo/GVL_IO/qxMotor {\"value\":true,\"type\":\"BOOL\"") != std::string::npos);
  CHECK(values.output.find("iecoop/demo/IO_PRG/fbConveyor/tJam/PT {\"value\":\"T#2s\",\"type\":\"TIME\"") !=
        std::string::npos);

  // A batch size of 12, and one out of range (rejected).
  CHECK(run({IECOOP_MOSQUITTO_PUB, "-h", "127.0.0.1", "-p", mqtt.port_text(), "-t",
             "iecoop/demo/GVL_Config/wBatchSize/set", "-m", "12"})
            .exit_code == 0);
  CHECK(run({IECOOP_MOSQUITTO_PUB, "-h", "127.0.0.1", "-p", mqtt.port_text(), "-t",
             "iecoop/demo/GVL_Config/wBatchSize/set", "-m", "500"})
            .exit_code == 0);
  std::this_thread::sleep_for(500ms);

  // Ctrl-C: the demo stops, says goodbye to the broker and prints its summary.
  demo.kill(SIGINT);
  const std::string out = demo.output();
  CHECK(out.find("runner:  stopped by Ctrl-C") != std::string::npos);
  CHECK(out.find("(of 12)") != std::string::npos);
  CHECK(out.find("1 commands applied (1 rejected)") != std::string::npos);
  CHECK(out.find("iecoop fault") == std::string::npos);
  const run_result status = run({IECOOP_MOSQUITTO_SUB, "-h", "127.0.0.1", "-p", mqtt.port_text(), "-t",
                                 "iecoop/demo/status", "-C", "1", "-W", "5"});
  CHECK(status.output == "offline\n");
}

#endif
