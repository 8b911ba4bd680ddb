// iecoop-check fixture: a user's header with one slip, included by two checked files
// (shared_block_a.cpp, shared_block_b.cpp): reported once.
#pragma once

#include <iecoop/iecoop.hpp>

namespace shared {

using namespace iecoop;

struct FB_Shared : function_block<FB_Shared> {
  INT Value() { return 1; }   // not virtual
  virtual void body() {}
};

struct FB_SharedChild : extends<FB_SharedChild, FB_Shared> {
  INT Value() { return 2; }   // hides FB_Shared::Value
  void body() override {}
};

}  // namespace shared
