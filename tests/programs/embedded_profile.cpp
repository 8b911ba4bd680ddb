// The core in use with -fno-exceptions -fno-rtti, as a firmware build compiles it: types,
// literals, strings, string functions, conversions, blocks, properties, interfaces with their
// queries (no RTTI) and the fault path. Returns 0 when
// every result is right.
#include <cstdint>

#include <iecoop/iecoop.hpp>

namespace {
int faults = 0;
void count_fault(const iecoop::fault_info&) { ++faults; }

using namespace iecoop;

struct FB_Ramp : function_block<FB_Ramp> {
  explicit FB_Ramp(INT limit) { run_fb_init(*this, limit); }
  INT iTarget;
  INT iValue;
  INT iLimit;
  using VAR_INPUT = pins<&FB_Ramp::iTarget>;
  using VAR_OUTPUT = pins<&FB_Ramp::iValue>;
  BOOL FB_Init(BOOL, BOOL, INT limit) {
    iLimit = limit;
    return TRUE;
  }
  void body() {
    if (iValue < iTarget) iValue = iValue + 1;
  }
  struct Clamp_vars {
    INT iIn;
    output<BOOL> bClamped;
  };
  INT Clamp(args<Clamp_vars> in) {
    in.bClamped = in.iIn > iLimit;
    return in.bClamped == TRUE ? iLimit : in.iIn;
  }
};

struct I_Drive : interface_base<I_Drive> {
  virtual void Start() = 0;
  virtual DINT Speed_Get() = 0;
  [[no_unique_address]] property<DINT, &I_Drive::Speed_Get> Speed{this};
};
struct I_Brake : interface_base<I_Brake> {
  virtual void Hold() = 0;
};
struct FB_Drive : function_block<FB_Drive, implements<I_Drive, I_Brake>> {
  DINT dSpeed;
  void body() {}
  void Start() override { dSpeed = 1500; }
  void Hold() override { dSpeed = 0; }
  DINT Speed_Get() override { return dSpeed; }
};
struct FB_Idle : function_block<FB_Idle, implements<I_Drive>> {
  void body() {}
  void Start() override {}
  DINT Speed_Get() override { return 0; }
};
}  // namespace

int main() {
  using namespace iecoop;
  set_fault_handler(&count_fault);
  int failures = 0;
  const auto expect = [&failures](bool ok) { failures += ok ? 0 : 1; };

  INT counter = 32767;
  counter = counter + 1;
  expect(counter == -32768);

  const DINT zero = faults;  // 0, unknown to the compiler
  expect(DINT(10) / zero == 0 && faults == 1);

  TIME pt = "T#1h2m3s4ms"_iec;
  pt += "T#996ms"_iec;
  expect(TIME_TO_DINT(pt) == 3724000);
  expect(TIME_TO_STRING(pt) == "T#1h2m4s");
  expect(STRING_TO_TIME("T#1.5s") == "T#1500ms"_iec);
  expect(!parse_time("t#5m68s") && parse_time("t#5m68s").error() == parse_error::unit_overflow);

  STRING<12> name = "conveyor belt one";
  expect(name == "conveyor bel" && LEN(name) == 12);
  expect(CONCAT(LEFT(name, 4), "-", MID(name, 3, 10)) == "conv-bel");
  expect(FIND(name, "belt") == 0 && FIND(name, "bel") == 10);
  expect(REAL_TO_INT(REAL(2.5f)) == 3 && INT_TO_SINT(4223) == 127);
  expect(WSTRING_TO_STRING(STRING_TO_WSTRING(name)) == name);

  FB_Ramp ramp{INT(10)};
  INT value;
  ramp("iTarget"_ = INT(3), "iValue"_ >> value);
  ramp();
  expect(value == 1 && ramp.iValue == 2);
  BOOL clamped;
  const INT clamp = ramp.Clamp({"iIn"_ = INT(50), "bClamped"_ >> clamped});
  expect(clamp == 10 && clamped == TRUE);
  reset(ramp, reset_kind::cold, INT(20));
  expect(ramp.iValue == 0 && ramp.iLimit == 20);

  FB_Drive drive;
  FB_Idle idle;
  itf<I_Drive> ip = drive;
  ip->Start();
  expect(ip->Speed == 1500);
  itf<I_Brake> brake;
  expect(query_interface(ip, brake) == TRUE);
  brake->Hold();
  expect(drive.dSpeed == 0 && query_pointer<FB_Drive>(ip) == &drive);
  ip = idle;
  expect(query_interface(ip, brake) == FALSE && brake == nullptr && query_pointer<FB_Drive>(ip) == nullptr);

  // The standard blocks, driven by the cycle clock as a SysTick handler would drive it.
  TON jam;
  CTU parts;
  iec::F_TRIG released;
  for (int tick = 0; tick <= 300; ++tick) {
    cycle_clock::set(LTIME::from_ticks(static_cast<std::uint64_t>(tick) * 1'000'000));
    jam("IN"_ = BOOL(tick >= 100), "PT"_ = "T#150ms"_iec);
    parts("CU"_ = BOOL(tick % 20 < 10), "RESET"_ = FALSE, "PV"_ = 12);
    released("CLK"_ = BOOL(tick < 250));
    if (tick == 249) expect(jam.Q == FALSE && jam.ET == "T#149ms"_iec);
    if (tick == 250) expect(jam.Q == TRUE && released.Q == TRUE);
  }
  expect(parts.CV == 16 && parts.Q == TRUE && released.Q == FALSE);

  return failures;
}
