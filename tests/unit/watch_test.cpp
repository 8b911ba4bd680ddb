// The watch list (<iecoop/trace/watch.hpp>): snapshots after a task's cycles at most once per
// interval, the table as CODESYS's watch view shows it (values as ST writes them), snapshots
// that are never torn while another thread reads them, and the display thread with the
// real-time runner.
#include "iecoop_test.hpp"

#include <iecoop/runtime/application.hpp>
#include <iecoop/runtime/realtime.hpp>
#include <iecoop/trace/watch.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <thread>

using namespace iecoop;

namespace watch_test {
namespace {

LTIME ms(std::uint64_t n) { return LTIME::from_ticks(n * 1'000'000U); }

// PROGRAM PRG_Mirror: two variables that are always equal at the end of a cycle, a timer.
struct PRG_Mirror : program<PRG_Mirror> {
  var<DINT> diA;
  var<DINT> diB;
  var<BOOL> bOdd;
  TON tDelay;
  void body() {
    diA = diA + 1;
    bOdd = MOD(diA, DINT(2)) == 1;  // bOdd := diA MOD 2 = 1;
    tDelay("IN"_ = TRUE, "PT"_ = "T#1s500ms"_iec);
    diB = diA;
  }
};

std::string table_of(watch_list<8>& watch) {
  std::string text;
  watch.write_table([&](std::string_view s) { text += s; });
  return text;
}

}  // namespace
}  // namespace watch_test

using namespace watch_test;

TEST_SUITE("watch list") {
  TEST_CASE("a snapshot after a cycle at most once per interval, shown as a watch view shows it") {
    application plc{task<PRG_Mirror>{"Fast", cyclic{"T#1ms"_iec}, 0}};
    plc.start();
    watch_list<8> watch{ms(10)};
    const PRG_Mirror& prg = plc.get<PRG_Mirror>();
    watch.add("PRG_Mirror", "diA", prg.diA);
    watch.add("PRG_Mirror", "bOdd", prg.bOdd);
    watch.add_pins("PRG_Mirror.tDelay", prg.tDelay);
    CHECK(table_of(watch) == "iecoop watch: no cycle yet\n");
    watch.attach(plc.task("Fast"));
    plc.run_for(ms(35));
    CHECK(watch.snapshots() == 4);  // at 0, 10, 20 and 30 ms
    const trace_view view = watch.snapshot();
    REQUIRE(view.size() == 1);
    CHECK(view.time(0) == ms(30));
    CHECK(view.cycle(0) == 30);
    CHECK(view.value(0, 0).i == 31);
    CHECK(table_of(watch) ==
          "iecoop watch at LTIME#30ms, cycle 30\n"
          "Expression            Type        Value\n"
          "PRG_Mirror.diA        DINT        31\n"
          "PRG_Mirror.bOdd       BOOL        TRUE\n"
          "PRG_Mirror.tDelay.IN  BOOL        TRUE\n"
          "PRG_Mirror.tDelay.PT  TIME        T#1s500ms\n"
          "PRG_Mirror.tDelay.Q   BOOL        FALSE\n"
          "PRG_Mirror.tDelay.ET  TIME        T#30ms\n");
    // The channels are fixed while attached.
    iecoop_test::fault_recorder faults;
    CHECK_FALSE(watch.add("x", prg.diB));
    CHECK(faults.count == 1);
    watch.detach();
    CHECK(watch.add("x", prg.diB));
  }

  TEST_CASE("a reader in another thread never sees a torn snapshot") {
    application plc{task<PRG_Mirror>{"Fast", cyclic{"T#1ms"_iec}, 0}};
    plc.start();
    watch_list<8> watch{LTIME{}};  // a snapshot after every cycle
    const PRG_Mirror& prg = plc.get<PRG_Mirror>();
    watch.add("diA", prg.diA);
    watch.add("diB", prg.diB);
    watch.attach(plc.task("Fast"));
    std::atomic<bool> done{false};
    std::atomic<std::uint64_t> reads{0};
    std::uint64_t torn = 0;
    std::int64_t last = 0;
    std::uint64_t backwards = 0;
    std::thread reader([&] {
      while (!done.load()) {
        const trace_view view = watch.snapshot();
        if (view.empty()) continue;
        const std::int64_t a = view.value(0, 0).i;
        if (a != view.value(0, 1).i) ++torn;
        if (a < last) ++backwards;
        last = a;
        reads.fetch_add(1);
      }
    });
    // 200'000 cycles at least, and on while the reader has not read 100 snapshots yet: on a
    // loaded machine its thread may start after 200'000 cycles (2 ms in a Release build) have run.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    std::uint64_t batches = 0;
    while (batches < 200 || (reads.load() < 100 && std::chrono::steady_clock::now() < deadline)) {
      plc.run_for(ms(1000));
      ++batches;
    }
    done.store(true);
    reader.join();
    CHECK(watch.snapshots() == batches * 1000U);
    CHECK(reads > 0);
    CHECK(torn == 0);
    CHECK(backwards == 0);
  }

  TEST_CASE("the display redraws the table in its own thread while the real-time runner runs the task") {
    application plc{task<PRG_Mirror>{"Fast", cyclic{"T#1ms"_iec}, 0}};
    plc.start();
    watch_list<8> watch{ms(20)};
    watch.add("PRG_Mirror", "diA", plc.get<PRG_Mirror>().diA);
    watch.attach(plc.task("Fast"));
    std::FILE* out = std::tmpfile();
    REQUIRE(out != nullptr);
    {
      watch_display<8> display{watch, out, ms(50), "conveyor"};
      realtime_runner runner{plc};
      const std::atomic<bool> stop{false};
      runner.run(stop, ms(300));
    }  // the display's thread ends
    CHECK(watch.snapshots() >= 5);
    std::rewind(out);
    std::string text;
    char chunk[4096];
    for (std::size_t n; (n = std::fread(chunk, 1, sizeof chunk, out)) > 0;) text.append(chunk, n);
    std::fclose(out);
    CHECK(text.find("\x1b[H\x1b[Jconveyor") != std::string::npos);
    CHECK(text.find("Expression      Type        Value\nPRG_Mirror.diA  DINT        ") != std::string::npos);
    CHECK(text.find("conveyor at LTIME#") != std::string::npos);
  }
}
