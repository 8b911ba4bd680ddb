// iecoop's headers survive a translation unit that defined IEC names as macros first, as
// <windows.h> does (IN, OUT, TRUE, FALSE, DELETE, ERROR, interface) and as users do with
// BOOL or WORD, and they leave those macros exactly as they found them.
#define IN
#define OUT
#define OPTIONAL
#define BOOL int
#define WORD unsigned short
#define INT long
#define TIME double
#define STRING char*
#define TRUE 1
#define FALSE 0
#define DELETE (0x00010000L)
#define ERROR 0
#define interface struct
#include <sys/param.h>  // glibc: MIN and MAX as macros
#define ABS(x) ((x) < 0 ? -(x) : (x))

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

// The user's macros are back after the include.
static_assert(sizeof(BOOL) == sizeof(int) && sizeof(WORD) == sizeof(unsigned short) && sizeof(INT) == sizeof(long));
static_assert(TRUE == 1 && FALSE == 0 && DELETE == 0x00010000L && ERROR == 0);
static_assert(MIN(2, 3) == 2 && MAX(2, 3) == 3 && ABS(-4) == 4);
interface windows_style_interface {
  int OUT value IN;
};

// What a user does next, as with <windows.h>: #undef the names iecoop's code needs.
#undef IN
#undef OUT
#undef OPTIONAL
#undef BOOL
#undef WORD
#undef INT
#undef TIME
#undef STRING
#undef TRUE
#undef FALSE
#undef DELETE
#undef ERROR
#undef MIN
#undef MAX
#undef ABS
#undef interface

#include "iecoop_test.hpp"

TEST_CASE("iecoop works in a translation unit that had Windows-style macros") {
  using namespace iecoop;
  const BOOL b = TRUE;
  const WORD w = 0xFFFF;
  const INT i = 32767;
  const TIME t = "T#1s"_iec;
  const STRING<5> s = DELETE("SUXYSI", 2, 3);
  CHECK(b == TRUE);
  CHECK(TO_WORD(w + WORD(1)) == 0);
  CHECK(i + 1 == 32768);
  CHECK(t == TIME(1000));
  CHECK(s == "SUSI");
  CHECK(MAX(i, 5) == 32767);  // IEC's MAX, once <sys/param.h>'s macro is gone
  CHECK(ABS(INT(-3)) == 3);
  windows_style_interface x{5};
  CHECK(x.value == 5);
}
