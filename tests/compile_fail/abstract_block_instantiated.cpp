// EXPECT: FB_Abstract
// An ABSTRACT block cannot be instantiated, only extended.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Abstract : function_block<FB_Abstract> {
  virtual ~FB_Abstract() = default;
  virtual void body() {}

 protected:
  FB_Abstract() = default;  // FUNCTION_BLOCK ABSTRACT FB_Abstract
};
struct FB_Concrete : extends<FB_Concrete, FB_Abstract> {
  void body() override {}
};
int main() {
#ifdef IECOOP_COMPILE_FAIL
  FB_Abstract fb;
#else
  FB_Concrete fb;
#endif
  fb();
}
