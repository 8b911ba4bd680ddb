// EXPECT: the variables struct is not complete where the method's return type is read
// A method that returns its first output reads its variables struct in its declaration; a
// struct nested in the block whose members have brace initial values (a TON t{}) is not
// complete there for C++. Declared before the block, it is.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
struct FB : function_block<FB> {
  struct M_vars {
    TON tDelay{};
    STRING<> sName{"axis"};
    output<INT> nLen;
  };
  first_output_t<M_vars> M(args<M_vars> in) { return in.nLen = LEN(in.sName); }
  void body() {}
};
#else
struct M_vars {
  TON tDelay{};
  STRING<> sName{"axis"};
  output<INT> nLen;
};
struct FB : function_block<FB> {
  first_output_t<M_vars> M(args<M_vars> in) {
    in.nLen = LEN(in.sName);
    return in.nLen;
  }
  void body() {}
};
#endif
int main() {
  FB fb;
  return fb.M({}) == 4 ? 0 : 1;
}
