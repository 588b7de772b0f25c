#pragma once
// Where two stretches of the tool-centre path cross in the compensation plane (inside corners,
// bottlenecks, loops of an offset that bends tighter than the tool radius).
#include <optional>
#include <vector>

#include "interp/cutter_compensation_piece.hpp"

namespace drycut::interp {

struct PieceCrossing {
  double u_earlier = 0.0;  // base parameter on the earlier piece (or the first pass of a loop)
  double u_later = 0.0;    // base parameter on the later piece (or the second pass of a loop)
};

// Every crossing of `later` with `earlier`, in the order along `earlier` (the first one closes
// the largest loop). `consecutive`: later starts where earlier ends; that shared point is no
// crossing.
std::vector<PieceCrossing> find_crossings(const OffsetPiece& earlier, const OffsetPiece& later, bool consecutive,
                                          const CompensationPlane& plane);

// A loop of one piece: the first point that the piece passes twice.
std::optional<PieceCrossing> find_self_crossing(const OffsetPiece& piece, const CompensationPlane& plane);

}  // namespace drycut::interp
