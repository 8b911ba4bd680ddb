// EXPECT: a RETAIN or PERSISTENT variable must be trivially copyable
// RETAIN and PERSISTENT values are saved and restored as bytes: a type with a destructor of
// its own, or one that owns memory elsewhere (std::string), cannot be RETAIN.
#include <iecoop/iecoop.hpp>
#include <iecoop/runtime/retain.hpp>

#include <string>

using namespace iecoop;

struct ST_Logged {
  INT iValue;
  ~ST_Logged() { iValue = 0; }
};
struct ST_Plain {
  INT iValue;
};

int main() {
#ifdef IECOOP_COMPILE_FAIL
  retain<ST_Logged> stValue;
  persistent<std::string> sName;
#else
  retain<ST_Plain> stValue;
  persistent<STRING<20>> sName;
#endif
  return stValue->iValue == 0 && sName->empty() ? 0 : 1;
}
