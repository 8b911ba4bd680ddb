// iecoop-check fixture: a block's VAR written from outside the block (check 2). CODESYS lets
// only the block and the blocks that extend it write its VAR; C++ lets everyone.
#include <array>

#include <iecoop/iecoop.hpp>

using namespace iecoop;

struct ST_Pos {
  INT x;
  INT y;
  int raw = 0;
};

// FUNCTION_BLOCK FB_Axis
struct FB_Axis : function_block<FB_Axis> {
  BOOL bEnable;                       // VAR_INPUT
  using VAR_INPUT = pins<&FB_Axis::bEnable>;
  var<INT> nMoves;                    // VAR
  var<BOOL> bDone;
  var<ST_Pos> stPos;
  var<std::array<INT, 4>> aSteps;
  virtual void body() {}

  // A class nested in the block is not the block.
  struct Helper {
    static void Poke(FB_Axis& axis) { axis.nMoves = 1; }
  };
};

// FUNCTION_BLOCK FB_Cell: another block, writing the VAR of the axis it contains.
struct FB_Cell : function_block<FB_Cell> {
  FB_Axis fbAxis;
  TON tmrDone;
  void body() {
    fbAxis.nMoves = 0;                          // fbAxis.nMoves := 0;
    tmrDone("IN"_ = TRUE, "Q"_ >> fbAxis.bDone);  // tmrDone(IN := TRUE, Q => fbAxis.bDone);
  }
};

void Operate(FB_Axis& fb) {
  fb.bEnable = TRUE;        // an input: fine
  const INT n = fb.nMoves;  // reading: fine
  fb.nMoves = n;            // fb.nMoves := n;
  fb.nMoves += 2;
  ++fb.nMoves;
  --fb.nMoves;
  fb.stPos->x = 1;          // a member of a structured VAR
  fb.stPos.ref().y = 2;     // write access by ref()
  fb.stPos->raw = 3;        // a plain C++ member
  fb.stPos->raw += 3;
  fb.aSteps[1] = 5;         // an element of an array VAR
}

inline auto reset_axis = [](FB_Axis& fb) { fb.bDone = FALSE; };
