#pragma once
// G96 under G95 along a straight cut: the feed f·n follows the diameter (docs/controller-state.md
// "Constant cutting speed"). The interpreter gives such a block one feed, the one that gives it
// its true time, and the law of its spindle speed (PathElement::cutting_speed); this stage, the
// last before the planner, splits the element as the earlier stages left it (chamfers and
// roundings inserted, the tool radius offset applied, corners smoothed) so that the feed has its
// course too. Splitting in the interpreter instead made those stages see pieces: a chamfer or
// rounding was reduced to fit the first piece, and the offset of a piece missed the intersection
// with the next block (a false 10751 / 10763).
//
// ALGORITHM (a straight element from a to b, x(p) the SCC axis position of the law)
//   n0 = n(x(a)), n1 = n(x(b)); when max/min <= kStep (1.05) the element passes unchanged.
//   Otherwise it becomes k = clamp(ceil(ln(max/min) / ln kStep), 2, 32) pieces of equal length,
//   piece j at feed F·n̄_j / n̄ with F the element's feed, n̄ the harmonic mean of n over the whole
//   element and n̄_j over the piece (constant_cutting_speed_rpm): the pieces' times add up to the
//   element's (∫ ds / v exactly), and neighbouring speeds differ by at most kStep. Every piece but
//   the last continues the block (one block in the report, no block change, no exact stop).
// A circular arc (no helix): x(φ) is not linear along it, so its speed range min/max n is taken
//   from 17 points at equal angles (a bulge between ends of equal diameter counts too); over
//   kStep it becomes k sub-arcs of equal angle as above, sub-arc j at F·n̄_j / n̄ with n̄_j the
//   speed of its mean x (∫ x dφ / Δφ, exact where no limit binds) and n̄ = n(x(a), x(b)), the
//   mean the interpreter gave the block's feed (its ends, as for a line): the sub-arcs' times add
//   up to ∫ ds / (f·n) along the arc, not to the block's chord-based time (until 2026-11-29 an
//   arc kept that one feed: a quarter arc from Ø40 to Ø80 was 8 % short when convex, 10 % long
//   when concave).
#include "interp/path_element.hpp"

namespace drycut::interp {

// Piece k (1..pieces) of element e along `curve` at `feed`: every piece but the last continues
// the block (one block in the report, no block change, no exact stop between them). Also the
// G34/G35 thread's pieces (interpreter_curves.cpp).
PathElement block_piece(const PathElement& e, geometry::CurvePtr curve, double feed, int k, int pieces);

class CuttingSpeedPieces final : public ElementSink {
 public:
  explicit CuttingSpeedPieces(ElementSink& next) : next_(next) {}
  void consume(PathElement&& e) override;
  void finish() override { next_.finish(); }

 private:
  // Hand the element on in pieces; false: it needs none (the caller hands it on whole).
  bool cut_line(const PathElement& e, const CuttingSpeedLaw& law);
  bool cut_arc(const PathElement& e, const CuttingSpeedLaw& law);
  ElementSink& next_;
};

}  // namespace drycut::interp
