// GCC 12 keeps a loop's counter in memory when a store in the loop goes through a member
// pointer, but not when the same store names the member. Not built; read the optimiser's
// decision with (bench/performance-notes.md explains why it matters to iecoop's `:=`):
//
//   g++ -std=c++20 -O2 -c member_pointer_store.cpp -fdump-tree-lim2-details -o /dev/null
//   grep -c "Executing store motion" member_pointer_store.cpp.*lim2        # 1
//   g++ -std=c++20 -O2 -DTHROUGH_MEMBER_POINTER -c member_pointer_store.cpp \
//       -fdump-tree-lim2-details -o /dev/null
//   grep -c "Executing store motion" member_pointer_store.cpp.*lim2        # 0
//
// With the member pointer, the store reaches the loop as MEM[(struct S *)_1 + 2B] (the
// cell's address plus an offset), which GCC's alias oracle cannot tell from machine.count;
// with the member named, it is machine.cells[k].counter.preset and the array's bounds
// separate the two.
struct scalar {
  short v;
};
struct counter {
  bool up;
  scalar preset;
  scalar value;
};
struct cell {
  unsigned stamp;
  counter c;
};
struct machine_state {
  cell cells[1000];
  scalar count;
};
machine_state machine;

template <auto Member, class Block>
inline void assign(Block& block, short x) {
#ifdef THROUGH_MEMBER_POINTER
  (block.*Member).v = x;
#else
  block.preset.v = x;
#endif
}

void scan() {
  machine.count.v = 0;
  for (int k = 0; k < 1000; ++k) {
    cell& here = machine.cells[k];
    assign<&counter::preset>(here.c, 50);
    here.c.value.v = static_cast<short>(here.c.value.v + 1);
    if (here.c.value.v > here.c.preset.v) machine.count.v = static_cast<short>(machine.count.v + 1);
  }
}
