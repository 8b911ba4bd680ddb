// EXPECT: final
// A FINAL block cannot be extended.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Base : function_block<FB_Base> {
  virtual ~FB_Base() = default;
  virtual void body() {}
};
#ifdef IECOOP_COMPILE_FAIL
struct FB_Final final : extends<FB_Final, FB_Base> {
  void body() override {}
};
struct FB_More : extends<FB_More, FB_Final> {
  void body() override {}
};
#else
struct FB_Final : extends<FB_Final, FB_Base> {
  void body() override {}
};
struct FB_More : extends<FB_More, FB_Final> {
  void body() override {}
};
#endif
int main() {
  FB_More fb;
  fb();
}
