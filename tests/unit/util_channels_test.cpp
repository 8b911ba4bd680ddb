// The Util library's blocks as a trace recorder (and so the MQTT bridge and the watch list,
// which take the same channels) names and reads them: add_pins gives each pin under the
// block's scope, with its IEC type; CHARCURVE's VAR_IN_OUT ARRAY is left out, GEN's GEN_MODE
// is an enumeration shown by its component's name.
#include "iecoop_test.hpp"

#include <string_view>

#include <iecoop/trace.hpp>

#include "standard_blocks_test.hpp"

using namespace iecoop;
using iecoop_test::at_ms;

TEST_SUITE("util: channels") {
  TEST_CASE("PID's pins: inputs then outputs, by their IEC names, with their values") {
    PID pid;
    trace_recorder<4096> trace;
    REQUIRE(trace.add_pins("TEMP_PRG.fbPID", pid));
    const auto channels = trace.channels();
    REQUIRE(channels.size() == 14);
    const std::string_view names[] = {"ACTUAL", "SET_POINT", "KP",     "TN",    "TV", "Y_MANUAL",      "Y_OFFSET",
                                      "Y_MIN",  "Y_MAX",     "MANUAL", "RESET", "Y",  "LIMITS_ACTIVE", "OVERFLOW"};
    for (std::size_t i = 0; i < channels.size(); ++i) {
      CHECK(channels[i].scope == "TEMP_PRG.fbPID");
      CHECK(channels[i].name == names[i]);
    }
    CHECK(channels[0].type->name == "REAL");
    CHECK(channels[13].type->name == "BOOL");
    trace.start();
    at_ms(0);
    pid("ACTUAL"_ = REAL(20.0F), "SET_POINT"_ = REAL(80.0F), "KP"_ = REAL(2.0F), "Y_OFFSET"_ = REAL(5.0F));
    trace.sample();
    at_ms(100);
    pid();
    trace.sample();
    const trace_view view = trace.view();
    REQUIRE(view.size() == 2);
    CHECK(view.value(0, trace.find("TEMP_PRG.fbPID.Y")).number() == 5.0);    // Y_OFFSET at first
    CHECK(view.value(1, trace.find("TEMP_PRG.fbPID.Y")).number() == 125.0);  // 2 x 60 + 5
  }

  TEST_CASE("the other blocks' pins") {
    trace_recorder<8192, 64> trace;
    RAMP_REAL ramp;
    GEN gen;
    CHARCURVE curve;
    FREQ_MEASURE freq;
    HYSTERESIS hyst;
    STATISTICS_INT stat;
    UNPACK bits;
    REQUIRE(trace.add_pins("PRG.fbRamp", ramp));
    REQUIRE(trace.add_pins("PRG.fbGen", gen));
    REQUIRE(trace.add_pins("PRG.fbCurve", curve));
    REQUIRE(trace.add_pins("PRG.fbFreq", freq));
    REQUIRE(trace.add_pins("PRG.fbHyst", hyst));
    REQUIRE(trace.add_pins("PRG.fbStat", stat));
    REQUIRE(trace.add_pins("PRG.fbBits", bits));
    CHECK(trace.find("PRG.fbRamp.TIMEBASE") < trace.channel_count());
    CHECK(trace.find("PRG.fbRamp.OUT") < trace.channel_count());
    CHECK(trace.find("PRG.fbGen.MODE") < trace.channel_count());
    CHECK(trace.channels()[trace.find("PRG.fbGen.MODE")].type->kind == trace_kind::enumeration);
    CHECK(trace.find("PRG.fbCurve.N") < trace.channel_count());
    CHECK(trace.find("PRG.fbCurve.ERR") < trace.channel_count());
    CHECK(trace.find("PRG.fbCurve.P") == trace.channel_count());  // an ARRAY of STRUCTs: left out
    CHECK(trace.find("PRG.fbFreq.VALID") < trace.channel_count());
    CHECK(trace.find("PRG.fbHyst.OUT") < trace.channel_count());
    CHECK(trace.find("PRG.fbStat.AVG") < trace.channel_count());
    CHECK(trace.find("PRG.fbBits.B7") < trace.channel_count());
    trace.start();
    gen("MODE"_ = GEN_MODE::RECTANGLE, "CYCLES"_ = INT(2), "AMPLITUDE"_ = INT(3));
    stat("IN"_ = INT(-4));
    trace.sample();
    const trace_view view = trace.view();
    CHECK(view.value(0, trace.find("PRG.fbGen.OUT")).number() == -3.0);
    CHECK(view.value(0, trace.find("PRG.fbStat.MN")).number() == -4.0);
  }
}
