// EXPECT: private
// METHOD PRIVATE is callable only inside its block.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  void body() { Secret(); }

 private:
  void Secret() {}
};
int main() {
  FB fb;
#ifdef IECOOP_COMPILE_FAIL
  fb.Secret();
#else
  fb();
#endif
}
