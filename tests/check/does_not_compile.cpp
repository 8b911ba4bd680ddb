// iecoop-check fixture: a file that does not compile is an error (exit status 2), never clean.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

struct FB_Broken : function_block<FB_Broken> {
  var<INT> nCount;
  void body() { nCount = nCount + undeclared_variable; }
};
