// One feature: the IEC standard functions — selection (SEL, MAX, MIN, LIMIT, MUX), bit shift
// (SHL, SHR, ROL, ROR), numerical (ABS, SQRT, EXPT, ...) and comparison (GT, LE, ...) — with
// IEC's names and argument order; their inputs meet in one type, as in ST.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Valve       (* a valve position from a setpoint, with a status word *)
struct FB_Valve : function_block<FB_Valve> {
  REAL rSetpoint;   // VAR_INPUT rSetpoint : REAL;
  BOOL bManual;     //           bManual : BOOL;
  REAL rManual;     //           rManual : REAL; END_VAR
  REAL rPosition;   // VAR_OUTPUT rPosition : REAL;
  WORD wStatus;     //            wStatus : WORD; END_VAR
  using VAR_INPUT = pins<&FB_Valve::rSetpoint, &FB_Valve::bManual, &FB_Valve::rManual>;
  using VAR_OUTPUT = pins<&FB_Valve::rPosition, &FB_Valve::wStatus>;

  void body() {
    // rPosition := LIMIT(0.0, SEL(bManual, rSetpoint, rManual), 100.0);
    rPosition = LIMIT(0.0f, SEL(bManual, rSetpoint, rManual), 100.0f);
    // wStatus := SHL(BOOL_TO_WORD(bManual), 15) OR BOOL_TO_WORD(GE(rPosition, 99.5));
    wStatus = SHL(BOOL_TO_WORD(bManual), 15) | BOOL_TO_WORD(GE(rPosition, 99.5f));
  }
};

int main() {
  FB_Valve fbValve;  // fbValve : FB_Valve;
  fbValve("rSetpoint"_ = 42.5f);
  fmt::print("setpoint 42.5       position {:5.1f}  status 16#{:04X}\n", fbValve.rPosition, fbValve.wStatus);
  fbValve("rSetpoint"_ = 180.0f);
  fmt::print("setpoint 180        position {:5.1f}  status 16#{:04X}\n", fbValve.rPosition, fbValve.wStatus);
  fbValve("bManual"_ = TRUE, "rManual"_ = -5.0f);
  fmt::print("manual -5           position {:5.1f}  status 16#{:04X}\n", fbValve.rPosition, fbValve.wStatus);

  // VAR iA : INT := 17; iB : INT := -40; k : INT := 2; END_VAR
  INT iA = 17, iB = -40, k = 2;
  fmt::print("MAX(iA, iB, 0)                {}\n", MAX(iA, iB, 0));
  fmt::print("MIN(iA, iB, 0)                {}\n", MIN(iA, iB, 0));
  fmt::print("ABS(iB)                       {}\n", ABS(iB));
  fmt::print("MUX(k, 10, 20, 30)            {}\n", MUX(k, 10, 20, 30));
  fmt::print("MUX(7, 10, 20, 30)            {}   (beyond the last: the last)\n", MUX(7, 10, 20, 30));
  fmt::print("LIMIT(100, iA, 0)             {}    (MN > MX: MX, as CODESYS)\n", LIMIT(100, iA, 0));
  fmt::print("GT(30, iA, 0, iB)             {}\n", GT(30, iA, 0, iB));
  fmt::print("ROL(BYTE#16#81, 9)            16#{:02X}  (a BYTE by 9 is by 1)\n", ROL(BYTE(0x81), 9));
  fmt::print("SHR(WORD#16#8000, 15)         {}\n", SHR(WORD(0x8000), 15));
  fmt::print("SQRT(REAL#2.0)                {:.6f}\n", SQRT(REAL(2.0f)));
  fmt::print("EXPT(-2.0, 3)                 {}\n", EXPT(LREAL(-2.0), 3));
  fmt::print("MAX(T#1s, T#900ms, LT#2s)     {}\n", MAX("T#1s"_iec, "T#900ms"_iec, "LT#2s"_iec));
}
