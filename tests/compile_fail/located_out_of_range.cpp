// EXPECT: iecoop: the address lies outside its area of the process image
// A located variable must lie inside its process image: the default image has 64 input
// bytes, and in CODESYS addressing %IW40 is bytes 80..81.
#include <iecoop/io/located.hpp>
using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  located<INT, "%IW40"> iLevel;  // iLevel AT %IW40 : INT;
#else
  located<INT, "%IW31"> iLevel;  // bytes 62..63: the last word of 64 input bytes
#endif
  return iLevel > 0 ? 1 : 0;
}
