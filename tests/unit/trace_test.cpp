// The trace recorder (<iecoop/trace.hpp>): channels of every type a trace records, a block's
// pins, PROPERTYs, VAR_IN_OUT and located variables; the ring buffer, on-change recording,
// triggers with pre- and post-trigger counts; sampling after each cycle of an application's
// task; and the VCD and CSV writers — the VCD read back by GTKWave's vcd2fst/fst2vcd, the CSV
// replayed by iecoop-replay's reader.
#include "iecoop_test.hpp"

#include <iecoop/runtime/application.hpp>
#include <iecoop/trace.hpp>

#include <unistd.h>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "replay.hpp"

using namespace iecoop;

namespace trace_test {

// TYPE E_Valve : (Closed, Opening := 5, Open); END_TYPE
enum class E_Valve : INT::rep { Closed, Opening = 5, Open };
// TYPE E_Signed : SINT (Low := -100, High := 100); END_TYPE
enum class E_Signed : SINT::rep { Low = -100, High = 100 };

}  // namespace trace_test

template <>
inline constexpr auto iecoop::enum_components<trace_test::E_Valve> =
    components<trace_test::E_Valve::Closed, trace_test::E_Valve::Opening, trace_test::E_Valve::Open>{};
template <>
inline constexpr auto iecoop::enum_components<trace_test::E_Signed> =
    components<trace_test::E_Signed::Low, trace_test::E_Signed::High>{};

namespace trace_test {
namespace {

LTIME ms(std::uint64_t n) { return LTIME::from_ticks(n * 1'000'000U); }

std::string text_of(const trace_view& view, std::size_t sample, std::size_t channel) {
  char text[64];
  return std::string(text, static_cast<std::size_t>(view.text(sample, channel, text) - text));
}

// FUNCTION_BLOCK FB_Dosing: a block with an input, an output, an in-out, a STRING pin (which
// a trace leaves out), a PROPERTY in each monitoring mode, and a VAR.
struct FB_Dosing : function_block<FB_Dosing> {
  BOOL bEnable;
  STRING<10> sRecipe;
  output<INT> iDosed;
  in_out<DINT> diTotal;
  using VAR_INPUT = pins<&FB_Dosing::bEnable, &FB_Dosing::sRecipe>;
  using VAR_OUTPUT = pins<&FB_Dosing::iDosed>;
  using VAR_IN_OUT = pins<&FB_Dosing::diTotal>;

  var<INT> iStep;
  int gets = 0;

  INT Rate_Get() {
    ++gets;
    return iStep * 10;
  }
  // {attribute 'monitoring' := 'call'}
  [[no_unique_address]] property<INT, &FB_Dosing::Rate_Get> Rate{this};

  REAL Level_monitor;
  REAL Level_Get() { return REAL(iStep) / REAL(4); }
  void Level_Set(REAL) {}
  // {attribute 'monitoring' := 'variable'}
  [[no_unique_address]] property<REAL, &FB_Dosing::Level_Get, &FB_Dosing::Level_Set,
                                 monitoring::variable<&FB_Dosing::Level_monitor>>
      Level{this};

  void body() {
    if (bEnable) {
      iStep = iStep + 1;
      iDosed = iStep;
      diTotal = diTotal + 1;
    }
  }
};

// A process image of the test's own, and a program with located variables.
struct trace_image_tag {};
using image = process_image<4, 4, 0, addressing::codesys, trace_image_tag>;
template <class T, fixed_string A>
using at_ = located<T, A, image>;

// PROGRAM PRG_Belt (Fast task): a belt runs while started; a part sensor counts parts.
struct PRG_Belt : program<PRG_Belt> {
  [[no_unique_address]] at_<BOOL, "%IX0.0"> bStart;
  [[no_unique_address]] at_<BOOL, "%QX0.0"> bMotor;
  [[no_unique_address]] at_<INT, "%QW1"> iParts;
  using LOCATED = pins<&PRG_Belt::bStart, &PRG_Belt::bMotor, &PRG_Belt::iParts>;

  var<INT> nCycles;
  var<BOOL> bLate;
  void body() {
    nCycles = nCycles + 1;
    bLate = nCycles >= 3;
    bMotor = bStart;
    if (bStart) iParts = iParts + 1;
  }
};
// PROGRAM PRG_Log (Slow task).
struct PRG_Log : program<PRG_Log> {
  var<INT> nCycles;
  void body() { nCycles = nCycles + 1; }
};

/// A test's own temporary file name.
std::string temp_file(std::string_view name) {
  return "/tmp/iecoop_trace_test_" + std::to_string(::getpid()) + "_" + std::string(name);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool have_program(const char* name) {
  return std::system(("command -v " + std::string(name) + " >/dev/null 2>&1").c_str()) == 0;
}

/// The value changes of a VCD file as read back: for each variable's full name (scopes joined
/// by '.'), the (time, value text) pairs in order.
struct vcd_changes {
  std::string timescale;
  std::map<std::string, std::vector<std::pair<std::uint64_t, std::string>>> changes;
};

vcd_changes parse_vcd(const std::string& text) {
  vcd_changes result;
  std::map<std::string, std::string> name_of;  // identifier code -> full name
  std::vector<std::string> scopes;
  std::istringstream in(text);
  std::string word;
  std::uint64_t now = 0;
  while (in >> word) {
    if (word == "$scope") {
      std::string kind, name, end;
      in >> kind >> name >> end;
      scopes.push_back(name);
    } else if (word == "$upscope") {
      in >> word;
      scopes.pop_back();
    } else if (word == "$timescale") {
      std::string part;
      while (in >> part && part != "$end") result.timescale += part;
    } else if (word == "$var") {
      std::string type, width, id, name, end;
      in >> type >> width >> id >> name >> end;
      std::string full;
      for (std::size_t s = 1; s < scopes.size(); ++s) full += scopes[s] + ".";  // without the top scope
      name_of[id] = full + name;
    } else if (word[0] == '$') {
      if (word == "$dumpvars" || word == "$end") continue;
      while (in >> word && word != "$end") {
      }
    } else if (word[0] == '#') {
      now = std::stoull(word.substr(1));
    } else if (word[0] == 'b' || word[0] == 'B' || word[0] == 'r' || word[0] == 'R') {
      std::string id;
      in >> id;
      std::string value = word.substr(1);
      if (word[0] == 'b' || word[0] == 'B') {  // a vector: its value as a number, leading zeros dropped
        const std::size_t one = value.find('1');
        value = one == std::string::npos ? "0" : value.substr(one);
      }
      result.changes[name_of.at(id)].emplace_back(now, value);
    } else {
      result.changes[name_of.at(word.substr(1))].emplace_back(now, word.substr(0, 1));
    }
  }
  return result;
}

std::string binary(std::uint64_t value, unsigned bits) {
  std::string text;
  for (unsigned b = bits; b-- > 0;) text += ((value >> b) & 1U) != 0 ? '1' : '0';
  const std::size_t one = text.find('1');
  return one == std::string::npos ? "0" : text.substr(one);
}

}  // namespace
}  // namespace trace_test

using namespace trace_test;

TEST_SUITE("trace recorder") {
  TEST_CASE("records every type a trace can show, its extremes included") {
    BOOL b = TRUE;
    SINT si = std::numeric_limits<SINT::rep>::min();
    INT i = -1;
    DINT di = std::numeric_limits<DINT::rep>::min();
    LINT li = std::numeric_limits<LINT::rep>::max();
    USINT usi = 255;
    UINT ui = 65535;
    UDINT udi = 4'000'000'000U;
    ULINT uli = std::numeric_limits<ULINT::rep>::max();
    BYTE by = 0xA5;
    WORD w = 0xBEEF;
    DWORD dw = 0xDEADBEEFU;
    LWORD lw = 0x0123456789ABCDEFULL;
    REAL r = 1.5F;
    LREAL lr = -0.1;
    TIME t = "T#1s500ms"_iec;
    LTIME lt = "LTIME#1ms500us"_iec;
    DATE d = "D#2026-11-23"_iec;
    TOD tod = "TOD#12:30:00.5"_iec;
    DT dt = "DT#2026-11-23-12:30:00"_iec;
    E_Valve valve = E_Valve::Opening;
    E_Signed level = E_Signed::Low;

    trace_recorder<1024, 32> trace;
    CHECK(trace.add("b", b));
    trace.add("si", si);
    trace.add("i", i);
    trace.add("di", di);
    trace.add("li", li);
    trace.add("usi", usi);
    trace.add("ui", ui);
    trace.add("udi", udi);
    trace.add("uli", uli);
    trace.add("by", by);
    trace.add("w", w);
    trace.add("dw", dw);
    trace.add("lw", lw);
    trace.add("r", r);
    trace.add("lr", lr);
    trace.add("t", t);
    trace.add("lt", lt);
    trace.add("d", d);
    trace.add("tod", tod);
    trace.add("dt", dt);
    trace.add("valve", valve);
    trace.add("level", level);
    REQUIRE(trace.channel_count() == 22);
    REQUIRE(trace.start());
    // 1 byte of BOOL bits, then the values in their sizes.
    CHECK(trace.sample_bytes() ==
          trace_view::header_bytes + 1 + (1 + 2 + 4 + 8) * 2 + 1 + 2 + 4 + 8 + 4 + 8 + 4 + 8 + 4 + 4 + 4 + 2 + 1);
    cycle_clock::set(ms(7));
    trace.sample();
    const trace_view view = trace.view();
    REQUIRE(view.size() == 1);
    CHECK(view.time(0) == ms(7));
    CHECK(view.cycle(0) == 0);

    const std::vector<std::string> expected{"TRUE",
                                            "-128",
                                            "-1",
                                            "-2147483648",
                                            "9223372036854775807",
                                            "255",
                                            "65535",
                                            "4000000000",
                                            "18446744073709551615",
                                            "165",
                                            "48879",
                                            "3735928559",
                                            "81985529216486895",
                                            "1.5",
                                            "-0.1",
                                            "T#1s500ms",
                                            "LTIME#1ms500us",
                                            "D#2026-11-23",
                                            "TOD#12:30:00.5",
                                            "DT#2026-11-23-12:30:00",
                                            "Opening",
                                            "Low"};
    for (std::size_t c = 0; c < expected.size(); ++c) {
      INFO("channel ", view.channels()[c].name);
      CHECK(text_of(view, 0, c) == expected[c]);
    }
    CHECK(view.value(0, 0).u == 1);
    CHECK(view.value(0, 1).i == -128);
    CHECK(view.value(0, 4).i == std::numeric_limits<std::int64_t>::max());
    CHECK(view.value(0, 8).u == std::numeric_limits<std::uint64_t>::max());
    CHECK(view.value(0, 13).f == 1.5);
    CHECK(view.value(0, 14).f == -0.1);
    CHECK(view.value(0, 15).u == 1500);  // TIME: ms
    CHECK(view.channels()[15].type->ns_per_count == 1'000'000);
    CHECK(view.value(0, 16).u == 1'500'000);  // LTIME: ns
    CHECK(view.value(0, 20).u == 5);
    CHECK(view.value(0, 21).i == -100);
    CHECK(view.value(0, 21).number() == -100.0);
    CHECK(view.channels()[1].type->kind == trace_kind::signed_integer);
    CHECK(view.channels()[5].type->kind == trace_kind::unsigned_integer);
    CHECK(view.channels()[10].type->kind == trace_kind::bit_string);
    CHECK(view.channels()[10].type->name == "WORD");
    CHECK(view.channels()[20].type->kind == trace_kind::enumeration);
    CHECK(view.channels()[20].type->name == "E_Valve");
  }

  TEST_CASE("add_pins records a block's inputs, outputs and in-outs, leaving out what a trace cannot show") {
    FB_Dosing fb;
    DINT total = 100;
    trace_recorder<2048> trace;
    CHECK(trace.add_pins("PRG.fbDosing", fb));
    const auto channels = trace.channels();
    REQUIRE(channels.size() == 3);  // bEnable, iDosed, diTotal: the STRING is left out
    CHECK(channels[0].scope == "PRG.fbDosing");
    CHECK(channels[0].name == "bEnable");
    CHECK(channels[1].name == "iDosed");
    CHECK(channels[2].name == "diTotal");
    CHECK(trace.find("PRG.fbDosing.iDosed") == 1);
    CHECK(trace.find("iDosed") == trace.channel_count());

    trace.start();
    trace.sample();  // the in-out is not bound yet: its type's initial value
    fb("bEnable"_ = TRUE, "diTotal"_ = total);
    trace.sample();
    fb("bEnable"_ = TRUE, "diTotal"_ = total);
    trace.sample();
    const trace_view view = trace.view();
    REQUIRE(view.size() == 3);
    CHECK(view.value(0, 0).u == 0);
    CHECK(view.value(0, 2).i == 0);
    CHECK(view.value(1, 0).u == 1);
    CHECK(view.value(1, 1).i == 1);
    CHECK(view.value(1, 2).i == 101);  // through the reference, to the caller's variable
    CHECK(view.value(2, 1).i == 2);
    CHECK(view.value(2, 2).i == 102);
    CHECK(view.cycle(2) == 2);  // sample() counts its own cycles
  }

  TEST_CASE("a PROPERTY is recorded as a watch list shows it, through its monitoring mode") {
    FB_Dosing fb;
    trace_recorder<1024> trace;
    trace.add("fb.Rate", fb.Rate);
    trace.add("fb.Level", fb.Level);
    trace.start();
    fb.iStep = 3;
    trace.sample();
    CHECK(fb.gets == 1);  // 'call': the recorder ran the Get accessor
    fb.Level_monitor = 0.75F;
    trace.sample();
    const trace_view view = trace.view();
    CHECK(view.value(0, 0).i == 30);
    CHECK(view.value(0, 1).f == 0.0);  // 'variable': what Get and Set last recorded, not a call
    CHECK(view.value(1, 1).f == 0.75);
  }

  TEST_CASE("located variables and a whole LOCATED list are read from the process image") {
    application plc{task<PRG_Belt>{"Fast", cyclic{"T#1ms"_iec}, 0}, use_image<image>{}};
    simulated_io<image> field;
    plc.connect(field);
    trace_recorder<4096> trace;
    plc.start();
    PRG_Belt& belt = plc.get<PRG_Belt>();
    CHECK(trace.add_located("PRG_Belt", belt));
    trace.add("PRG_Belt", "nCycles", belt.nCycles);
    CHECK(trace.channels()[0].name == "bStart");
    CHECK(trace.channels()[2].name == "iParts");
    trace.attach(plc.task("Fast"));
    trace.start();
    plc.run_for(ms(2));
    field.set<"%IX0.0">(TRUE);
    plc.run_for(ms(3));
    const trace_view view = trace.view();
    REQUIRE(view.size() == 5);
    CHECK(view.value(1, 0).u == 0);
    CHECK(view.value(2, 0).u == 1);  // latched at the cycle's start
    CHECK(view.value(2, 1).u == 1);  // %QX0.0 as the program wrote it
    CHECK(view.value(4, 2).i == 3);
    CHECK(view.value(4, 3).i == 5);
    CHECK(view.time(4) == ms(4));
    CHECK(view.cycle(4) == 4);
  }

  TEST_CASE("a trigger on a var<> BOOL and on a located %IX BOOL") {
    application plc{task<PRG_Belt>{"Fast", cyclic{"T#1ms"_iec}, 0}, use_image<image>{}};
    simulated_io<image> field;
    plc.connect(field);
    plc.start();
    PRG_Belt& belt = plc.get<PRG_Belt>();
    trace_recorder<1024> on_var;
    trace_recorder<1024> on_input;
    for (auto* trace : {&on_var, &on_input}) {
      trace->add("nCycles", belt.nCycles);
      trace->attach(plc.task("Fast"));
    }
    on_var.trigger_on(belt.bLate, trace_edge::rising, 1, 1);
    on_input.trigger_on(belt.bStart, trace_edge::rising, 1, 1);
    on_var.start();
    on_input.start();
    plc.run_for(ms(5));
    field.set<"%IX0.0">(TRUE);
    plc.run_for(ms(5));
    REQUIRE(on_var.complete());
    CHECK(on_var.view().value(on_var.view().trigger_index(), 0).i == 3);
    REQUIRE(on_input.complete());
    CHECK(on_input.view().value(on_input.view().trigger_index(), 0).i == 6);  // latched at the 6th cycle
  }

  TEST_CASE("the ring buffer keeps the newest samples, oldest first") {
    INT i;
    trace_recorder<64> trace;  // 12 + 2 = 14 bytes a sample: 4 slots, 3 samples
    trace.add("i", i);
    trace.start();
    CHECK(trace.capacity() == 3);
    for (int k = 0; k < 10; ++k) {
      cycle_clock::set(ms(static_cast<std::uint64_t>(k) * 10));
      i = INT(static_cast<INT::rep>(k));
      trace.sample();
    }
    const trace_view view = trace.view();
    REQUIRE(view.size() == 3);
    CHECK(view.value(0, 0).i == 7);
    CHECK(view.value(1, 0).i == 8);
    CHECK(view.value(2, 0).i == 9);
    CHECK(view.time(0) == ms(70));
    CHECK(view.cycle(2) == 9);
    CHECK(trace.overwritten() == 7);
    CHECK(view.trigger_index() == trace_view::no_trigger);
    CHECK(trace.state() == trace_state::recording);
  }

  TEST_CASE("on change, a sample is kept only when a value differs from the last one kept") {
    BOOL b;
    INT i;
    trace_recorder<1024> trace;
    trace.add("b", b);
    trace.add("i", i);
    trace.set_mode(trace_mode::on_change);
    trace.start();
    const int values[] = {0, 0, 0, 1, 1, 2, 2, 2, 2, 3};
    for (int k = 0; k < 10; ++k) {
      cycle_clock::set(ms(static_cast<std::uint64_t>(k)));
      i = INT(static_cast<INT::rep>(values[k]));
      b = k == 6;  // a one-cycle pulse is a change too
      trace.sample();
    }
    const trace_view view = trace.view();
    REQUIRE(view.size() == 6);
    const std::uint64_t cycles[] = {0, 3, 5, 6, 7, 9};
    for (std::size_t s = 0; s < 6; ++s) {
      CHECK(view.cycle(s) == cycles[s]);
      CHECK(view.time(s) == ms(cycles[s]));
    }
    CHECK(view.value(3, 0).u == 1);
    CHECK(view.value(4, 0).u == 0);
  }

  TEST_CASE("a rising edge triggers: pre-trigger samples before it, post-trigger samples after it") {
    BOOL bJam;
    INT i;
    trace_recorder<1024> trace;
    trace.add("i", i);
    trace.trigger_on(bJam, trace_edge::rising, /*pre_trigger=*/3, /*post_trigger=*/2);
    trace.start();
    for (int k = 0; k < 30; ++k) {
      cycle_clock::set(ms(static_cast<std::uint64_t>(k)));
      i = INT(static_cast<INT::rep>(k));
      bJam = k >= 20;
      trace.sample();
      if (k == 19) CHECK(trace.state() == trace_state::recording);
      if (k == 20) CHECK(trace.state() == trace_state::triggered);
    }
    CHECK(trace.state() == trace_state::complete);
    CHECK(trace.triggered());
    const trace_view view = trace.view();
    REQUIRE(view.size() == 6);
    CHECK(view.trigger_index() == 3);
    for (std::size_t s = 0; s < 6; ++s) CHECK(view.value(s, 0).i == static_cast<std::int64_t>(17 + s));
  }

  TEST_CASE("falling and both edges, a trigger condition, and the first sample against start()") {
    BOOL bSignal = TRUE;
    INT i;
    SUBCASE("falling") {
      trace_recorder<1024> trace;
      trace.add("i", i);
      trace.trigger_on(bSignal, trace_edge::falling, 1, 1);
      trace.start();
      for (int k = 0; k < 10; ++k) {
        i = INT(static_cast<INT::rep>(k));
        bSignal = k < 5;
        trace.sample();
      }
      const trace_view view = trace.view();
      REQUIRE(view.size() == 3);
      CHECK(view.value(view.trigger_index(), 0).i == 5);
    }
    SUBCASE("both: TRUE at start(), FALSE at the first sample is an edge") {
      trace_recorder<1024> trace;
      trace.add("i", i);
      trace.trigger_on(bSignal, trace_edge::both, 0, 0);
      trace.start();
      bSignal = FALSE;
      trace.sample();
      CHECK(trace.complete());
      CHECK(trace.view().size() == 1);
      CHECK(trace.view().trigger_index() == 0);
    }
    SUBCASE("rising: TRUE at start() and at the first sample is no edge") {
      trace_recorder<1024> trace;
      trace.add("i", i);
      trace.trigger_on(bSignal, trace_edge::rising, 0, 0);
      trace.start();
      trace.sample();
      CHECK(trace.state() == trace_state::recording);
      CHECK_FALSE(trace.triggered());
    }
    SUBCASE("a condition: the first sample where it holds") {
      trace_recorder<1024> trace;
      trace.add("i", i);
      trace.trigger_when(
          i, +[](const INT& value) { return value > 6; }, 2);
      trace.start();
      for (int k = 0; k < 10; ++k) {
        i = INT(static_cast<INT::rep>(k));
        trace.sample();
      }
      const trace_view view = trace.view();
      CHECK(view.trigger_index() == 2);
      CHECK(view.value(0, 0).i == 5);
      CHECK(view.value(view.size() - 1, 0).i == 9);  // post-trigger: until the buffer is full
      CHECK(trace.state() == trace_state::triggered);
    }
    SUBCASE("a pre-trigger count larger than the buffer is clamped") {
      trace_recorder<64> trace;  // 3 samples
      trace.add("i", i);
      trace.trigger_on(bSignal, trace_edge::falling, 100);
      trace.start();
      for (int k = 0; k < 10; ++k) {
        i = INT(static_cast<INT::rep>(k));
        bSignal = k < 8;
        trace.sample();
      }
      const trace_view view = trace.view();
      REQUIRE(view.size() == 3);
      CHECK(view.trigger_index() == 2);
      CHECK(trace.complete());
      CHECK(view.value(2, 0).i == 8);
    }
  }

  TEST_CASE("attached to a task, a recorder samples after each of its cycles, at the cycle's start time") {
    application plc{task<PRG_Belt>{"Fast", cyclic{"T#1ms"_iec}, 0}, task<PRG_Log>{"Slow", cyclic{"T#5ms"_iec}, 1},
                    use_image<image>{}};
    trace_recorder<4096> fast;
    trace_recorder<4096> slow;
    plc.start();
    fast.add("PRG_Belt.nCycles", plc.get<PRG_Belt>().nCycles);
    slow.add("PRG_Log.nCycles", plc.get<PRG_Log>().nCycles);
    fast.attach(plc.task("Fast"));
    slow.attach(plc.task("Slow"));
    CHECK(fast.attached());
    fast.start();
    slow.start();
    plc.run_for(ms(20));
    CHECK(fast.view().size() == 20);
    CHECK(slow.view().size() == 4);
    CHECK(slow.view().time(3) == ms(15));
    CHECK(slow.view().value(3, 0).i == 4);  // after the cycle's programs ran
    CHECK(fast.view().value(19, 0).i == 20);
    fast.detach();
    plc.run_for(ms(5));
    CHECK(fast.view().size() == 20);
    CHECK(slow.view().size() == 5);
    slow.stop();
    plc.run_for(ms(5));
    CHECK(slow.view().size() == 5);
  }

  TEST_CASE("a recorder and its task may end in either order") {
    auto plc = std::make_unique<application<task<PRG_Log>>>(task<PRG_Log>{"Slow", cyclic{"T#5ms"_iec}, 1});
    {
      trace_recorder<1024> first;
      first.attach(plc->task(0));
    }  // the recorder unlinks itself
    plc->start();
    plc->run_for(ms(10));
    trace_recorder<1024> second;
    second.add("n", plc->get<PRG_Log>().nCycles);
    second.attach(plc->task(0));
    second.start();
    plc->run_for(ms(10));
    CHECK(second.view().size() == 2);
    plc.reset();  // the task ends first: it unlinks the recorder
    CHECK_FALSE(second.attached());
  }

  TEST_CASE("misuse is reported as a fault") {
    iecoop_test::fault_recorder faults;
    INT i;
    SUBCASE("too many channels") {
      trace_recorder<1024, 2> trace;
      CHECK(trace.add("a", i));
      CHECK(trace.add("b", i));
      CHECK_FALSE(trace.add("c", i));
      CHECK(faults.count == 1);
      CHECK(std::string_view(faults.last_message).find("MaxChannels") != std::string_view::npos);
    }
    SUBCASE("adding channels while recording") {
      trace_recorder<1024> trace;
      trace.add("a", i);
      trace.start();
      CHECK_FALSE(trace.add("b", i));
      CHECK(faults.count == 1);
      CHECK(trace.channel_count() == 1);
      trace.stop();
      CHECK(trace.add("b", i));
    }
    SUBCASE("a memory too small for one sample") {
      LINT values[8];
      trace_recorder<64> trace;
      for (LINT& v : values) trace.add("v", v);
      CHECK_FALSE(trace.start());
      CHECK(faults.count == 1);
      CHECK(trace.state() == trace_state::stopped);
      trace.sample();  // does nothing
      CHECK(trace.view().empty());
    }
  }
}

TEST_SUITE("trace writers") {
  TEST_CASE("VCD: GTKWave's reader converts it, and the values come back as recorded") {
    REQUIRE_MESSAGE(have_program("vcd2fst"), "vcd2fst is missing: install Debian's gtkwave package");
    REQUIRE_MESSAGE(have_program("fst2vcd"), "fst2vcd is missing: install Debian's gtkwave package");
    TON tJam;
    INT iCount;
    REAL rSpeed;
    E_Valve eValve = E_Valve::Closed;
    trace_recorder<16384> trace;
    trace.add_pins("IO_PRG.tJam", tJam);
    trace.add("IO_PRG", "iCount", iCount);
    trace.add("IO_PRG", "rSpeed", rSpeed);
    trace.add("eValve", eValve);
    trace.start();
    for (std::uint64_t k = 0; k < 40; ++k) {
      cycle_clock::set(ms(k * 2));
      tJam("IN"_ = BOOL(k >= 5 && k < 30), "PT"_ = "T#20ms"_iec);
      iCount = INT(static_cast<INT::rep>(5 - static_cast<int>(k)));  // negative from k = 6
      rSpeed = REAL(static_cast<float>(k) * 0.25F);
      eValve = k < 10 ? E_Valve::Closed : k < 20 ? E_Valve::Opening : E_Valve::Open;
      trace.sample();
    }
    std::string vcd;
    write_vcd(trace.view(), [&](std::string_view s) { vcd += s; });
    const std::string vcd_path = temp_file("a.vcd");
    const std::string fst_path = temp_file("a.fst");
    const std::string back_path = temp_file("back.vcd");
    std::ofstream(vcd_path) << vcd;
    REQUIRE(std::system(("vcd2fst " + vcd_path + " " + fst_path + " >/dev/null 2>&1").c_str()) == 0);
    REQUIRE(std::system(("fst2vcd " + fst_path + " > " + back_path + " 2>/dev/null").c_str()) == 0);
    const vcd_changes ours = parse_vcd(vcd);
    const vcd_changes back = parse_vcd(read_file(back_path));
    std::remove(vcd_path.c_str());
    std::remove(fst_path.c_str());
    std::remove(back_path.c_str());

    CHECK(ours.timescale == "1ms");  // the largest power of ten dividing every time
    CHECK(back.timescale == "1ms");

    // What was written is what was recorded, as changes only...
    using changes = std::vector<std::pair<std::uint64_t, std::string>>;
    CHECK(ours.changes.at("IO_PRG.tJam.IN") == changes{{0, "0"}, {10, "1"}, {60, "0"}});
    CHECK(ours.changes.at("IO_PRG.tJam.Q") == changes{{0, "0"}, {30, "1"}, {60, "0"}});
    CHECK(ours.changes.at("IO_PRG.tJam.PT") == changes{{0, binary(20, 32)}});
    const changes& et = ours.changes.at("IO_PRG.tJam.ET");
    CHECK(std::find(et.begin(), et.end(), std::pair<std::uint64_t, std::string>{30, binary(20, 32)}) != et.end());
    CHECK(et.back() == std::pair<std::uint64_t, std::string>{60, "0"});
    const changes& count = ours.changes.at("IO_PRG.iCount");
    REQUIRE(count.size() == 40);
    CHECK(count[0] == std::pair<std::uint64_t, std::string>{0, "101"});
    CHECK(count[6] == std::pair<std::uint64_t, std::string>{12, binary(0xFFFF, 16)});  // -1, two's complement
    CHECK(ours.changes.at("eValve") == changes{{0, "0"}, {20, "101"}, {40, "110"}});
    CHECK(ours.changes.at("IO_PRG.rSpeed")[3] == std::pair<std::uint64_t, std::string>{6, "0.75"});

    // ... and GTKWave's reader has the same signals with the same changes.
    REQUIRE(back.changes.size() == ours.changes.size());
    for (const auto& signal : ours.changes) {
      const std::string& name = signal.first;
      const changes& list = signal.second;
      INFO("signal ", name);
      REQUIRE(back.changes.count(name) == 1);
      const changes& other = back.changes.at(name);
      REQUIRE(other.size() == list.size());
      for (std::size_t k = 0; k < list.size(); ++k) {
        CHECK(other[k].first == list[k].first);
        if (name == "IO_PRG.rSpeed") {
          CHECK(std::stod(other[k].second) == std::stod(list[k].second));
        } else {
          CHECK(other[k].second == list[k].second);
        }
      }
    }
  }

  TEST_CASE("VCD: the timescale follows the cycle clock, TIME as ms or as seconds, the trigger noted") {
    TIME tElapsed;
    BOOL bGo;
    trace_recorder<4096> trace;
    trace.add("tElapsed", tElapsed);
    trace.add("bGo", bGo);
    trace.trigger_on(bGo, trace_edge::rising, 2, 2);
    trace.start();
    for (std::uint64_t k = 0; k < 8; ++k) {
      cycle_clock::set(LTIME::from_ticks(1'000'000 + k * 250'000));  // a 250 us task from 1 ms on
      tElapsed = TIME::from_ticks(static_cast<TIME::rep>(k * 1500));
      bGo = k >= 3;
      trace.sample();
    }
    std::string vcd;
    write_vcd(trace.view(), [&](std::string_view s) { vcd += s; });
    CHECK(vcd.find("$timescale 10 us $end") != std::string::npos);
    CHECK(vcd.find("$comment trigger at cycle 3, time 175 $end") != std::string::npos);
    CHECK(vcd.find("$var reg 32 ! tElapsed $end") != std::string::npos);
    // The pre-trigger samples start at 1.25 ms, with 1500 ms.
    CHECK(vcd.find("#125\n$dumpvars\nb10111011100 !\n0\"\n$end\n#150\n") != std::string::npos);
    std::string as_real;
    write_vcd(
        trace.view(), [&](std::string_view s) { as_real += s; }, vcd_options{.top_scope = "plc", .time_as_real = true});
    CHECK(as_real.find("$scope module plc $end") != std::string::npos);
    CHECK(as_real.find("$var real 64 ! tElapsed $end") != std::string::npos);
    CHECK(as_real.find("#125\n$dumpvars\nr1.5 !\n") != std::string::npos);

    if (have_program("vcd2fst")) {
      const std::string vcd_path = temp_file("b.vcd");
      const std::string fst_path = temp_file("b.fst");
      std::ofstream(vcd_path) << as_real;
      CHECK(std::system(("vcd2fst " + vcd_path + " " + fst_path + " >/dev/null 2>&1").c_str()) == 0);
      std::remove(vcd_path.c_str());
      std::remove(fst_path.c_str());
    }
  }

  TEST_CASE("VCD and CSV: a REAL is its own shortest text, TIME in seconds is exact") {
    // The writers format no double themselves (std::to_chars for double is not in a firmware's
    // link): a REAL or LREAL is written as its type's text, a duration in seconds digit by digit.
    REAL r = 0.1F;
    LREAL lr = -2.5e-7;
    LTIME lt = LTIME::from_ticks(1);
    trace_recorder<1024> trace;
    trace.add("r", r);
    trace.add("lr", lr);
    trace.add("lt", lt);
    trace.start();
    cycle_clock::set(ms(0));
    trace.sample();
    std::string vcd;
    write_vcd(
        trace.view(), [&](std::string_view s) { vcd += s; }, vcd_options{.time_as_real = true});
    CHECK(vcd.find("$dumpvars\nr0.1 !\nr-2.5e-07 \"\nr0.000000001 #\n$end\n") != std::string::npos);
    std::string csv;
    write_csv(trace.view(), [&](std::string_view s) { csv += s; });
    CHECK(csv == "cycle,time_ms,r,lr,lt_ns\n0,0,0.1,-2.5e-07,1\n");
  }

  TEST_CASE("CSV: a block's recorded pins replay through iecoop-replay's reader to the same outputs") {
    TON timer;
    trace_recorder<65536> trace;
    trace.add_pins(timer);  // bare pin names: the columns iecoop-replay reads
    trace.start();
    const bool in[] = {false, true, true, true, false, true, true, true, true, true, true, false, false};
    for (std::size_t k = 0; k < std::size(in); ++k) {
      cycle_clock::set(ms(k * 10));
      timer("IN"_ = BOOL(in[k]), "PT"_ = "T#35ms"_iec);
      trace.sample();
    }
    std::string csv;
    write_csv(trace.view(), [&](std::string_view s) { csv += s; });
    CHECK(csv.starts_with("cycle,time_ms,IN,PT_ms,Q,ET_ms\n0,0,0,35,0,0\n1,10,1,35,0,0\n"));

    // Replayed as a stimulus: the recorded Q and ET come through as extra columns, beside the
    // outputs the replay computes; they must agree row by row.
    const std::string replayed = iecoop_replay::replay<TON>(csv, "TON", false);
    std::istringstream lines(replayed);
    std::string line;
    std::getline(lines, line);
    CHECK(line == "cycle,time_ms,IN,PT_ms,Q,ET_ms,Q,ET_ms");
    std::size_t rows = 0;
    bool q_seen = false;
    while (std::getline(lines, line)) {
      const auto fields = iecoop_replay::split_fields(line);
      REQUIRE(fields);
      REQUIRE(fields->size() == 8);
      CHECK((*fields)[4] == (*fields)[6]);
      CHECK((*fields)[5] == (*fields)[7]);
      q_seen = q_seen || (*fields)[4] == "1";
      ++rows;
    }
    CHECK(rows == std::size(in));
    CHECK(q_seen);
  }

  TEST_CASE(
      "CSV: names are quoted where CSV needs it, dates are IEC literals, REAL its float, times may have a fraction") {
    DATE d = "D#2026-11-23"_iec;
    LREAL x = 0.1;
    REAL y = 0.1F;
    LTIME lt = "LTIME#2us"_iec;
    trace_recorder<1024> trace;
    trace.add("a,b", d);
    trace.add("say \"x\"", x);
    trace.add("lt", lt);
    trace.add("y", y);
    trace.start();
    cycle_clock::set(LTIME::from_ticks(1'250'000));
    trace.sample();
    std::string csv;
    write_csv(trace.view(), [&](std::string_view s) { csv += s; });
    // A REAL as the float it is: 0.1, not the double it widens to (0.10000000149011612).
    CHECK(csv == "cycle,time_ms,\"a,b\",\"say \"\"x\"\"\",lt_ns,y\n0,1.25,D#2026-11-23,0.1,2000,0.1\n");
  }
}
