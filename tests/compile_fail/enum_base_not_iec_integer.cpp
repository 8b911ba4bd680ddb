// EXPECT: iecoop: an IEC enumeration is a C\+\+ enum with an IEC integer base type
// ST's TYPE E_Dir : (Left, Right) SINT; END_TYPE has an IEC integer base type; a C++ enum of
// char (or without a base type, or of bool) is no IEC enumeration.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
enum class E_Dir : char { Left, Right };
#else
enum class E_Dir : SINT::rep { Left, Right };
#endif
int main() {
  const STRING<> s = TO_STRING(E_Dir::Right);
  return s == "1" ? 0 : 1;
}
