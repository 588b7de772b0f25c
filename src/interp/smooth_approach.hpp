#pragma once
// Smooth approach and retraction (SAR; PGsl Fundamentals "Smooth approach and retraction",
// Function Manual W1 "Tool radius compensation 2D": G147/G148 straight line, G247/G248 quadrant,
// G347/G348 semicircle; G340 in space / G341 in the plane; G140..G143 side; DISR, DISCL, FAD).
// The geometry of the sub-movements, in the coordinates of the path elements; which speed each
// runs at is the interpreter's (interpreter_smooth_approach.cpp).
//
// Approach from the start point P0 to the contour start P4 (the SAR block's end point), joining
// the following block's start direction t (projected into the plane) tangentially:
//   - The contour of the approach (P3 -> P4) is a line along t (G147), a quadrant (G247) or a
//     semicircle (G347) that ends at P4 going along t. It is computed on the programmed contour
//     so that the tool-radius compensation's offset of it has the manual's size on the tool
//     centre: a line of DISR + r (DISR is the distance of the cutter's edge), a circle whose
//     tool-centre radius is DISR (contour radius DISR + r when it comes from the tool's side,
//     DISR - r from the other side). r = 0 without compensation.
//   - Side s (+1 from the left of t, -1 from the right): G141 left, G142 right, G140 the
//     compensation side (G41 left, G42 right; without compensation as G143), G143 the side P0
//     lies on. The circle's centre is P4 + s R nL (nL = n x t, n the plane normal), the arc turns
//     counter-clockwise about n for s = +1.
//   - Heights along n: the machining plane is P4's; DISCL the clearance above it (P2/P3).
//     G340: P0 -> P1 (in the plane's direction, at P0's height, above P3) -> P3 (down to the
//     clearance) -> P4 along the contour, which descends to P4 (a helix or an inclined line).
//     G341: P0 -> P1 -> P2 (down to the clearance) -> P3 (down to P4's plane) -> P4 in the plane.
// Retraction from the contour end P4 (the previous block's end, leaving along its end direction
// t) to the SAR block's end point P0: the same pieces in reverse (the contour leaves P4 along t
// and turns away to side s). A block that deselects the compensation (G40 G248 ...) runs them on
// the tool centre from the contour end's offset (circle radius DISR, line DISR + r), with the
// compensation off; one that keeps it runs them on the programmed contour, compensated.
// Pieces of no length are left out. A t with no component in the plane gives no pieces (the
// caller moves straight).
#include <vector>

#include "interp/geometry/curve.hpp"

namespace drycut::interp {

enum class SarShape { Line = 1, Quadrant = 2, Semicircle = 3 };

// Which speed a piece runs at: the one in force before the SAR block, FAD, or the SAR block's own
// (the interpreter resolves them; on retraction the roles of "before" and "own" swap).
enum class SarSpeed { Before, Fad, Own };

struct SarRequest {
  SarShape shape = SarShape::Line;
  bool in_plane = false;   // G341 (else G340)
  int side_rule = 140;     // G140..G143
  double disr_mm = 0.0;    // DISR
  double clearance_height = 0.0;  // the height (along the normal) of P2/P3: P4's plane + DISCL
};

// The speeds the interpreter resolved for the SAR block (mm/s). g0: G0 is in force for the
// block (group 1), so the movements up to the clearance (approach) or from it (retraction) are
// rapid.
struct SarSpeeds {
  bool g0 = false;
  double before_mm_s = 0.0;
  double fad_mm_s = 0.0;  // 0: no FAD
  double own_mm_s = 0.0;
};

struct SarPiece {
  geometry::CurvePtr curve;
  SarSpeed speed = SarSpeed::Own;
  bool contour = false;  // the approach/retraction contour itself (on the programmed contour)
};

// compensation_side: +1 G41, -1 G42, 0 none; radius: the compensation radius (0 without).
std::vector<SarPiece> approach_pieces(const geometry::Vec3& p0, const geometry::Vec3& p4,
                                      const geometry::Vec3& tangent, const geometry::Vec3& normal,
                                      const SarRequest& request, double radius, int compensation_side);
// p0_height: the end point's height; p0_in_plane: its position in the plane, or nullptr when
// the block names no axis of the plane (it ends above the retraction contour's end).
std::vector<SarPiece> retraction_pieces(const geometry::Vec3& p4, const geometry::Vec3& tangent,
                                        const geometry::Vec3* p0_in_plane, double p0_height,
                                        const geometry::Vec3& normal, const SarRequest& request, double radius,
                                        int compensation_side, bool on_tool_centre);

}  // namespace drycut::interp
