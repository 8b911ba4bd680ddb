// One feature: ARRAY with IEC bounds — ARRAY[1..n], multi-dimensional ARRAYs indexed a(i, j),
// initial values with repetitions, LOWER_BOUND/UPPER_BOUND, a FUNCTION over ARRAY[*], ARRAY OF
// blocks, and CheckBounds: an index out of range is a fault, then the nearest bound is used.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION F_Average : REAL
// VAR_IN_OUT aValues : ARRAY[*] OF INT; END_VAR
// VAR i, diSum : DINT; END_VAR
REAL F_Average(in_out<ARRAY<INT, '*'>> aValues) {
  DINT i, diSum;
  // FOR i := LOWER_BOUND(aValues, 1) TO UPPER_BOUND(aValues, 1) DO diSum := diSum + aValues[i]; END_FOR
  for (i = LOWER_BOUND(aValues, 1); i <= UPPER_BOUND(aValues, 1); i = i + 1) diSum = diSum + aValues[i];
  // F_Average := DINT_TO_REAL(diSum) / DINT_TO_REAL(UPPER_BOUND(aValues, 1) - LOWER_BOUND(aValues, 1) + 1);
  return DINT_TO_REAL(diSum) / DINT_TO_REAL(UPPER_BOUND(aValues, 1) - LOWER_BOUND(aValues, 1) + 1);
}

// FUNCTION_BLOCK FB_Station      (* four filling heads, each with its own delay *)
struct FB_Station : function_block<FB_Station> {
  ARRAY<BOOL, 1, 4> abDemand;  // VAR_INPUT abDemand : ARRAY[1..4] OF BOOL; END_VAR
  ARRAY<BOOL, 1, 4> abValve;   // VAR_OUTPUT abValve : ARRAY[1..4] OF BOOL; END_VAR
  // VAR atDelay : ARRAY[1..4] OF TON;
  //     atPreset : ARRAY[1..4] OF TIME := [2(T#1s), 2(T#3s)];
  //     i : INT; END_VAR
  ARRAY<TON, 1, 4> atDelay;
  ARRAY<TIME, 1, 4> atPreset = array_init(repeat<2>("T#1s"_iec), repeat<2>("T#3s"_iec));
  INT i;
  using VAR_INPUT = pins<&FB_Station::abDemand>;
  using VAR_OUTPUT = pins<&FB_Station::abValve>;

  void body() {
    // FOR i := 1 TO 4 DO
    //     atDelay[i](IN := abDemand[i], PT := atPreset[i]);
    //     abValve[i] := atDelay[i].Q;
    // END_FOR
    for (i = 1; i <= 4; i = i + 1) {
      atDelay[i]("IN"_ = abDemand[i], "PT"_ = atPreset[i]);
      abValve[i] = atDelay[i].Q;
    }
  }
};

void on_fault(const fault_info& f) { fmt::print("fault: {}: {}\n", to_string(f.kind), f.message); }

int main() {
  // VAR aiLevels : ARRAY[1..6] OF INT := [40, 42, 3(45)];   (the last one 0)
  //     aiOffset : ARRAY[-2..2] OF INT := [-4, -2, 0, 2, 4];
  //     arGrid : ARRAY[1..2, 0..2] OF REAL; END_VAR
  ARRAY<INT, 1, 6> aiLevels = array_init(40, 42, repeat<3>(45));
  ARRAY<INT, -2, 2> aiOffset{-4, -2, 0, 2, 4};
  ARRAY<REAL, 1, 2, 0, 2> arGrid;
  fmt::print("aiLevels: {} {} {} {} {} {}\n", aiLevels[1], aiLevels[2], aiLevels[3], aiLevels[4], aiLevels[5],
             aiLevels[6]);
  fmt::print("F_Average(aiLevels) = {:.2f}\n", F_Average(aiLevels));
  fmt::print("F_Average(aiOffset) = {:.2f}  (bounds -2..2)\n", F_Average(aiOffset));

  // arGrid[2, 0] := 1.5;  arGrid[1, 2] := arGrid[2, 0] * 2.0;
  arGrid(2, 0) = 1.5f;
  arGrid(1, 2) = arGrid(2, 0) * 2.0f;
  fmt::print("arGrid: [{} {} {}] [{} {} {}]\n", arGrid(1, 0), arGrid(1, 1), arGrid(1, 2), arGrid(2, 0), arGrid(2, 1),
             arGrid(2, 2));
  fmt::print("LOWER_BOUND(arGrid, 2) = {}, UPPER_BOUND(arGrid, 2) = {}\n", LOWER_BOUND(arGrid, 2),
             UPPER_BOUND(arGrid, 2));

  // Four heads, cycles of 500 ms of simulated time: heads 1 and 2 open after 1 s, 3 and 4 after 3 s.
  FB_Station fbStation;
  fbStation.abDemand = ARRAY<BOOL, 1, 4>{TRUE, TRUE, TRUE, FALSE};
  cycle_clock::set(LTIME::from_ticks(0));
  for (int cycle = 0; cycle <= 7; ++cycle) {
    fbStation();
    fmt::print("t = {:4} ms  valves {} {} {} {}\n", cycle * 500, fbStation.abValve[1], fbStation.abValve[2],
               fbStation.abValve[3], fbStation.abValve[4]);
    cycle_clock::advance(LTIME::from_ticks(500'000'000));
  }

  // CheckBounds: aiLevels[i] with i = 9 is a fault, then aiLevels[6] is used.
  set_fault_handler(&on_fault);
  INT i = 9;
  aiLevels[i] = 99;
  fmt::print("aiLevels[6] = {}\n", aiLevels[6]);
}
