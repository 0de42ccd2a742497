// Door transitions and weight borrowing (seed 000, §3.3 and Fig. 4): a door between two rooms needs
// a straight shared wall portion of at least its width plus a clearance at each end. When it does
// not fit, weight is lent to one of the two rooms (by the other room, then by the room's siblings)
// in growing amounts up to Restrictions::borrow_limit of each lender's weight, the subdivision is
// redone and every door accepted so far re-tested; the first transfer under which all of them fit
// is kept. Otherwise the borrowed weight flows back and the door is dropped with a warning.
#pragma once

#include <vector>

#include "lang/bldg/plan_state.h"

namespace insula::lang::bldg::plan {

struct DoorRequest {
  const Transition* transition = nullptr;  // null for a door the engine asks for (connections)
  int a = 0;                               // work room indices, same level
  int b = 0;
  double width = 0;
  bool accepted = false;
  bool borrowed = false;  // accepted after weight borrowing
  bool added = false;     // asked by request_connections, not by the grammar
};

// Work room indices of the rooms named `symbol` (a symbol may repeat across storeys).
std::vector<int> rooms_named(const Work& work, const std::string& symbol);

// The door transitions of the building as room pairs. Transitions touching a disposable part are
// ignored (§3.2), as are doors between rooms on different storeys; both with a warning.
std::vector<DoorRequest> collect_doors(Work& work);

// Past the paper: door requests that join the rooms of each storey into one connected group
// (storey 0's with an entrance room), between the adjacent rooms of two groups with the longest
// shared boundary, so that probing and weight borrowing make room for them too. The final
// reachability stage (plan_reach.cc) covers what still fails.
// One round: uses the accepted requests, never a pair that already failed; returns how many
// requests it added (fit_doors then tests them from where they start).
int request_connections(Work& work, std::vector<DoorRequest>& doors);

// Longest straight piece of the boundary rooms a and b share (0 when they do not touch).
double longest_shared(const Work& work, int a, int b);
bool door_fits(const Work& work, int a, int b, double width);

// Tests the requests from index `start` on, in order, borrowing weight where needed (cells are
// redone in `work`); earlier accepted doors must keep fitting.
void fit_doors(Work& work, std::vector<DoorRequest>& doors, std::size_t start = 0);

}  // namespace insula::lang::bldg::plan
