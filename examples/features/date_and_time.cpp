// One feature: the points in time DATE, TIME_OF_DAY and DATE_AND_TIME (and LDATE, LTOD, LDT) as
// CODESYS stores them: literals checked while compiling, the arithmetic CODESYS's ADD and SUB
// allow, the conversions, and IEC's functions of time data types (CONCAT_*, SPLIT_*,
// DAY_OF_WEEK).
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Shift          (* which shift a point in time falls in, and how long it ran *)
struct FB_Shift : function_block<FB_Shift> {
  DT dtNow;          // VAR_INPUT dtNow : DT; END_VAR
  USINT iShift;      // VAR_OUTPUT iShift : USINT;          (* 1 early, 2 late, 3 night *)
  TIME tIntoShift;   //            tIntoShift : TIME;
  BOOL bWeekend;     //            bWeekend : BOOL; END_VAR
  using VAR_INPUT = pins<&FB_Shift::dtNow>;
  using VAR_OUTPUT = pins<&FB_Shift::iShift, &FB_Shift::tIntoShift, &FB_Shift::bWeekend>;

  void body() {
    const TOD todNow = DT_TO_TOD(dtNow);                         // todNow := DT_TO_TOD(dtNow);
    if (todNow >= "TOD#06:00:00"_iec && todNow < "TOD#14:00:00"_iec) {  // IF todNow >= TOD#06:00:00 AND todNow < TOD#14:00:00 THEN
      iShift = 1;                                                //   iShift := 1;
      tIntoShift = todNow - "TOD#06:00:00"_iec;                  //   tIntoShift := todNow - TOD#06:00:00;
    } else if (todNow >= "TOD#14:00:00"_iec && todNow < "TOD#22:00:00"_iec) {  // ELSIF ... THEN
      iShift = 2;                                                //   iShift := 2;
      tIntoShift = todNow - "TOD#14:00:00"_iec;                  //   tIntoShift := todNow - TOD#14:00:00;
    } else if (todNow >= "TOD#22:00:00"_iec) {                   // ELSIF todNow >= TOD#22:00:00 THEN
      iShift = 3;                                                //   iShift := 3;
      tIntoShift = todNow - "TOD#22:00:00"_iec;                  //   tIntoShift := todNow - TOD#22:00:00;
    } else {                                                     // ELSE  (* the night shift, past midnight *)
      iShift = 3;                                                //   iShift := 3;
      tIntoShift = todNow - "TOD#00:00:00"_iec + "T#2h"_iec;     //   tIntoShift := todNow - TOD#00:00:00 + T#2h;
    }                                                            // END_IF
    const USINT iDay = DAY_OF_WEEK(DT_TO_DATE(dtNow));           // iDay := DAY_OF_WEEK(DT_TO_DATE(dtNow));
    bWeekend = (iDay == 0) | (iDay == 6);                        // bWeekend := iDay = 0 OR iDay = 6;
  }
};

int main() {
  // VAR dStart : DATE := D#2026-11-23; todStart : TOD := TOD#06:00:00; END_VAR
  const DATE dStart = "D#2026-11-23"_iec;
  const TOD todStart = "TOD#06:00:00"_iec;

  // dtStart := CONCAT_DATE_TOD(dStart, todStart);
  const DT dtStart = CONCAT_DATE_TOD(dStart, todStart);
  fmt::print("dtStart                         {}\n", dtStart);
  fmt::print("DT_TO_UDINT(dtStart)            {}   (seconds since 1970)\n", DT_TO_UDINT(dtStart));
  fmt::print("DT_TO_STRING(dtStart + T#90m)   '{}'\n", DT_TO_STRING(dtStart + "T#90m"_iec));
  fmt::print("dtStart - DT#2026-11-22-18:00   {}\n", dtStart - "DT#2026-11-22-18:00:00"_iec);
  fmt::print("D#2026-12-25 - dStart           {}\n", "D#2026-12-25"_iec - dStart);
  fmt::print("D#2027-02-01 - dStart           {}   (70 days do not fit a TIME: it wraps)\n",
             "D#2027-02-01"_iec - dStart);
  fmt::print("LDATE#2027-02-01 - dStart       {}\n", "LDATE#2027-02-01"_iec - dStart);

  // A TOD is a DWORD of milliseconds: it does not wrap at midnight.
  const TOD todLate = "TOD#23:00:00"_iec + "T#2h"_iec;         // todLate := TOD#23:00:00 + T#2h;
  fmt::print("TOD#23:00:00 + T#2h             {}\n", todLate);
  fmt::print("DT_TO_TOD(CONCAT_DATE_TOD(..))  {}\n", DT_TO_TOD(CONCAT_DATE_TOD(dStart, todLate)));

  // SPLIT_DT(IN := dtStart, YEAR => iYear, MONTH => iMonth, DAY => iDay, HOUR => iHour, ...);
  INT iYear, iMonth, iDay, iHour, iMinute, iSecond, iMs;
  SPLIT_DT(dtStart, iYear, iMonth, iDay, iHour, iMinute, iSecond, iMs);
  fmt::print("SPLIT_DT                        {}-{}-{} {}:{}:{}\n", iYear, iMonth, iDay, iHour, iMinute, iSecond);
  // dNext := CONCAT_DATE(iYear, iMonth + 1, 31);      (* 31 December: checked, it exists *)
  fmt::print("CONCAT_DATE(2026, 12, 31)       {}\n", CONCAT_DATE(iYear, iMonth + 1, 31));
  fmt::print("DAY_OF_WEEK(dStart)             {}   (0 = Sunday)\n", DAY_OF_WEEK(dStart));

  FB_Shift fbShift;                                            // fbShift : FB_Shift;
  for (const DT dt : {"DT#2026-11-23-07:15:00"_iec, "DT#2026-11-28-21:59:59"_iec, "DT#2026-11-29-02:30:00"_iec}) {
    fbShift("dtNow"_ = dt);                                    // fbShift(dtNow := dt);
    fmt::print("{}  shift {}  {} into it  weekend {}\n", dt, fbShift.iShift, fbShift.tIntoShift,
               fbShift.bWeekend);
  }
}
