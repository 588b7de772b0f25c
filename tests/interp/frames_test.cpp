// Frames: the frame type, the chain, and programs with TRANS/ROT/SCALE/MIRROR and settable
// frames. Every expected position is computed by hand in the comment beside it.
#include <cmath>
#include <numbers>

#include "interp/cutter_compensation.hpp"
#include "interp/frame_chain.hpp"
#include "interp/frame_components.hpp"
#include "interp/geometry/arc_curve.hpp"
#include "interp_test_support.hpp"

namespace drycut::interp::testing {
namespace {

using Eigen::Vector3d;

TEST(Frame, RotationIsCounterClockwiseAboutTheAxis) {
  // ROT Z90: the inner X axis points along the outer +Y.
  EXPECT_TRUE(near(Frame::rotation_about(2, 90).to_outer({10, 0, 0}), Vector3d(0, 10, 0)));
  // ROT X90: the inner Y axis points along the outer +Z.
  EXPECT_TRUE(near(Frame::rotation_about(0, 90).to_outer({0, 10, 0}), Vector3d(0, 0, 10)));
  // ROT Y90: the inner Z axis points along the outer +X.
  EXPECT_TRUE(near(Frame::rotation_about(1, 90).to_outer({0, 0, 10}), Vector3d(10, 0, 0)));
}

TEST(Frame, RpyTurnsAboutZThenYThenX) {
  // ROT X90 Z90 = Rz(90) * Rx(90): (0, 0, 10) -> Rx -> (0, -10, 0) -> Rz -> (10, 0, 0).
  // The other order, Rx(90) * Rz(90), would give (0, -10, 0).
  const Frame f = Frame::rotation_rpy({90, 0, 90});
  EXPECT_TRUE(near(f.to_outer({0, 0, 10}), Vector3d(10, 0, 0)));
  EXPECT_TRUE(near(f.to_outer({10, 0, 0}), Vector3d(0, 10, 0)));
}

TEST(Frame, ThenChainsInsideAndInverseUndoes) {
  // Translation (10, 5, 0) with a rotation of 90 degrees about Z inside it:
  // (10, 0, 0) -> (0, 10, 0) -> (10, 15, 0).
  const Frame f = Frame::translation({10, 5, 0}).then(Frame::rotation_about(2, 90));
  EXPECT_TRUE(near(f.to_outer({10, 0, 0}), Vector3d(10, 15, 0)));
  EXPECT_TRUE(near(f.to_inner({10, 15, 0}), Vector3d(10, 0, 0)));
  EXPECT_FALSE(Frame::scale({0, 1, 1}).invertible());
}

TEST(Frame, MirroredArcRunsTheOtherWay) {
  // Quarter circle G3 from (10, 0) about the origin to (0, 10); MIRROR X maps it to the arc from
  // (-10, 0) to (0, 10), clockwise seen from +Z: its midpoint is (-7.07, 7.07).
  auto arc = std::make_shared<geometry::ArcCurve>(Vector3d::Zero(), 10.0, geometry::Plane::G17, 0.0,
                                                  std::numbers::pi / 2, 0.0);
  auto mapped = transform_curve(arc, Frame::mirror({true, false, false}));
  ASSERT_TRUE(mapped);
  const double h = 10 / std::sqrt(2.0);
  EXPECT_TRUE(near((*mapped)->start(), Vector3d(-10, 0, 0)));
  EXPECT_TRUE(near((*mapped)->at((*mapped)->length() / 2).position, Vector3d(-h, h, 0)));
  EXPECT_TRUE(near((*mapped)->end(), Vector3d(0, 10, 0)));
  // Unequal scale in the circle's plane has no circle as image.
  EXPECT_FALSE(transform_curve(arc, Frame::scale({2, 1, 1})));
  // A helix keeps its axial travel under a uniform scale times the factor: 2 * 5 = 10.
  auto helix = std::make_shared<geometry::ArcCurve>(Vector3d::Zero(), 10.0, geometry::Plane::G17, 0.0,
                                                    std::numbers::pi, 5.0);
  auto scaled = transform_curve(helix, Frame::scale({2, 2, 2}));
  ASSERT_TRUE(scaled);
  EXPECT_TRUE(near((*scaled)->end(), Vector3d(-20, 0, 10)));
}

TEST(FrameChain, SettableIndicesAndNames) {
  EXPECT_EQ(settable_frame_index(500), 0);
  EXPECT_EQ(settable_frame_index(54), 1);
  EXPECT_EQ(settable_frame_index(57), 4);
  EXPECT_EQ(settable_frame_index(505), 5);
  EXPECT_EQ(settable_frame_index(599), 99);
  EXPECT_EQ(settable_frame_index(58), -1);
  EXPECT_EQ(settable_frame_index(504), -1);
  EXPECT_EQ(settable_frame_name(4), "G57");
  EXPECT_EQ(settable_frame_name(17), "G517");
}

TEST(FrameChain, ProgrammableFrameActsInsideTheSettableFrame) {
  FrameChain chain;
  chain.set_settable(Frame::translation({100, 0, 0}));
  chain.program(Frame::rotation_about(2, 90), false);
  // (10, 0, 0) -> rotated (0, 10, 0) -> settable (100, 10, 0); suppressed: unchanged.
  EXPECT_TRUE(near(chain.total(false).to_outer({10, 0, 0}), Vector3d(100, 10, 0)));
  EXPECT_TRUE(near(chain.total(true).to_outer({10, 0, 0}), Vector3d(10, 0, 0)));
}

TEST(FrameChain, AxialOffsetsReplaceOnePartOfTheTranslation) {
  FrameChain chain;
  chain.program(Frame::translation({10, 7, 0}), false);  // TRANS X10 Y7
  chain.program(Frame::translation({2, 0, 0}), true);    // ATRANS X2
  ASSERT_TRUE(chain.axial_offset(0, 20, false));         // G58 X20: absolute X, additive 2 stays
  EXPECT_TRUE(near(chain.programmable().offset(), Vector3d(22, 7, 0)));
  ASSERT_TRUE(chain.axial_offset(0, 11, true));          // G59 X11: additive X
  EXPECT_TRUE(near(chain.programmable().offset(), Vector3d(31, 7, 0)));
  chain.program(Frame::translation({5, 0, 0}), false);   // TRANS X5 starts both parts afresh
  ASSERT_TRUE(chain.axial_offset(1, 3, true));
  EXPECT_TRUE(near(chain.programmable().offset(), Vector3d(5, 3, 0)));
  chain.program(Frame::rotation_about(2, 90), true);     // AROT RPL=90: no longer a translation
  EXPECT_FALSE(chain.axial_offset(0, 1, false));
}

Vector3d end_of(const RunResult& r, size_t motion) { return r.sink.motions().at(motion).curve->end(); }

TEST(Frames, RotationInThePlaneAfterATranslation) {
  // TRANS X10 Y5, AROT RPL=90: (10, 0) -> rotated (0, 10) -> shifted (10, 15).
  auto r = run_program("G0 X0 Y0 Z0\nTRANS X10 Y5\nAROT RPL=90\nG1 X10 Y0 F1000\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  ASSERT_EQ(r->sink.motions().size(), 2u);
  EXPECT_TRUE(near(r->sink.motions()[1].curve->end(), Vector3d(10, 15, 0)));
}

TEST(Frames, AbsoluteInstructionsReplaceTheWholeProgrammableFrame) {
  // TRANS X10 then ROT RPL=90: the translation is gone; (10, 0) -> (0, 10).
  // Then ROT alone clears the rotation: (10, 0) stays (10, 0).
  auto r = run_program("G0 X0 Y0 Z0\nTRANS X10\nROT RPL=90\nG0 X10 Y0\nROT\nG0 X10 Y0\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(0, 10, 0)));
  EXPECT_TRUE(near(end_of(*r, 2), Vector3d(10, 0, 0)));
}

TEST(Frames, AdditiveTranslationFollowsTheRotatedAxes) {
  // ROT RPL=90, ATRANS X10: the shift runs along the rotated X (= machine +Y): (0, 0) -> (0, 10).
  auto r = run_program("G0 X0 Y0 Z0\nROT RPL=90\nATRANS X10\nG0 X0 Y0\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(0, 10, 0)));
}

TEST(Frames, ScaleAppliesToWhatFollowsIt) {
  // TRANS X10, ASCALE X2 Y2: (5, 5) -> (10, 10) + (10, 0) = (20, 10): the earlier shift unscaled.
  // SCALE X2 Y2, ATRANS X5: (1, 1) -> (6, 1) -> (12, 2): the later shift is scaled.
  auto r = run_program(
      "G0 X0 Y0 Z0\nTRANS X10\nASCALE X2 Y2\nG0 X5 Y5\nSCALE X2 Y2\nATRANS X5\nG0 X1 Y1\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(20, 10, 0)));
  EXPECT_TRUE(near(end_of(*r, 2), Vector3d(12, 2, 0)));
}

TEST(Frames, RotationInSpaceUsesRpyOrder) {
  // ROT X90 Z90: (0, 0, 10) -> (10, 0, 0) (see Frame.RpyTurnsAboutZThenYThenX).
  auto r = run_program("G0 X0 Y0 Z0\nROT X90 Z90\nG0 X0 Y0 Z10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(10, 0, 0)));
}

TEST(Frames, RplTurnsAboutTheNormalOfTheActivePlane) {
  // G18 (normal Y): ROT RPL=90 turns Z towards X: (X0 Z10) -> X10 Z0.
  // G19 (normal X): ROT RPL=90 turns Y towards Z: (Y10 Z0) -> Y0 Z10.
  auto r = run_program("G0 X0 Y0 Z0\nG18 ROT RPL=90\nG0 X0 Y0 Z10\nG19 ROT RPL=90\nG0 X0 Y10 Z0\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(10, 0, 0)));
  EXPECT_TRUE(near(end_of(*r, 2), Vector3d(0, 0, 10)));
}

TEST(Frames, MirrorReversesCirclesAndCompensationSide) {
  // MIRROR X0: G0 X12 Y0 -> (-12, 0), the G41 approach X10 Y0 -> (-10, 0). G2 to (0, -10) about
  // the workpiece zero is clockwise in the program; on the machine it runs from (-10, 0) to
  // (0, -10) through (-7.07, -7.07), i.e. counter-clockwise (G3). G41 acts on the machine as
  // G42. The test tool is 50 long: the carrier (what the elements give) stands at Z50 above the
  // tip at Z0. (G41 is selected in a straight block that moves in the plane: in the circle block,
  // or with the circle as the first block moving in the plane, it would be alarm 10753.)
  auto r = run_program("T1 M6 D1\nG0 X0 Y0 Z0\nMIRROR X0\nG0 X12 Y0\nG41 G1 X10 Y0 F100\nG2 X0 Y-10 I-10 J0\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 4u);  // G0, G0, the G41 approach, the circle
  EXPECT_TRUE(near(m[1].curve->end(), Vector3d(-12, 0, 50)));
  EXPECT_TRUE(near(m[2].curve->end(), Vector3d(-10, 0, 50)));
  const double h = 10 / std::sqrt(2.0);
  EXPECT_TRUE(near(m[3].curve->at(m[3].curve->length() / 2).position, Vector3d(-h, -h, 50)));
  EXPECT_TRUE(near(m[3].curve->end(), Vector3d(0, -10, 50)));
  const auto* arc = dynamic_cast<const geometry::ArcCurve*>(m[3].curve.get());
  ASSERT_NE(arc, nullptr);
  EXPECT_GT(arc->sweep() * arc->normal().z(), 0.0);  // counter-clockwise seen from +Z
  EXPECT_EQ(m[3].compensation.side, CompensationSide::Right);
}

TEST(Frames, MirrorOfThePlaneNormalKeepsTheSide) {
  // MIRROR Z0 in G17 does not mirror the X/Y contour: G41 stays left; Z10 -> tip Z-10, the
  // carrier of the 50 mm test tool at Z40.
  auto r = run_program("T1 M6 D1\nG0 X0 Y0 Z0\nMIRROR Z0\nG41 G1 X10 Y0 Z10 F100\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  EXPECT_TRUE(near(m[1].curve->end(), Vector3d(10, 0, 40)));
  EXPECT_EQ(m[1].compensation.side, CompensationSide::Left);
}

TEST(Frames, UniformScaleScalesCirclesAndUnequalScaleIsRefused) {
  // SCALE X2 Y2: G0 X10 Y0 -> (20, 0); G3 X0 Y10 I-10 -> (0, 20), radius 20, midpoint 20(c45, s45).
  auto r = run_program("G0 X0 Y0 Z0\nSCALE X2 Y2\nG0 X10 Y0\nG3 X0 Y10 I-10 F100\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  const double h = 20 / std::sqrt(2.0);
  EXPECT_TRUE(near(m[2].curve->at(m[2].curve->length() / 2).position, Vector3d(h, h, 0)));
  EXPECT_TRUE(near(m[2].curve->end(), Vector3d(0, 20, 0)));
  auto bad = run_program("G0 X0 Y0 Z0\nSCALE X2\nG0 X10 Y0\nG3 X0 Y10 I-10 F100\nM30\n");
  ASSERT_TRUE(bad->alarm);
  EXPECT_EQ(bad->alarm->number, 990006);
  EXPECT_EQ(bad->alarm->where.line, 4u);
}

TEST(Frames, ArcInARotatedFrameIsBuiltInTheProgramAndTurned) {
  // ROT RPL=90: G0 X10 Y0 -> (0, 10). G3 X0 Y10 I-10 (quarter circle about the zero, from
  // 0 to 90 degrees) -> machine from 90 to 180 degrees: end (-10, 0), midpoint 10(c135, s135).
  // CR= and CT follow the same path: the same circle written with CR=10 ends in the same place.
  auto r = run_program("G0 X0 Y0 Z0\nROT RPL=90\nG0 X10 Y0\nG3 X0 Y10 I-10 F100\nG0 X10 Y0\nG3 X0 Y10 CR=10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  const double h = 10 / std::sqrt(2.0);
  EXPECT_TRUE(near(m[2].curve->at(m[2].curve->length() / 2).position, Vector3d(-h, h, 0)));
  EXPECT_TRUE(near(m[2].curve->end(), Vector3d(-10, 0, 0)));
  EXPECT_TRUE(near(m[4].curve->at(m[4].curve->length() / 2).position, Vector3d(-h, h, 0)));
}

TEST(Frames, ProfileSettableFramesWithRotationAndHighNumbers) {
  // G54 = (10, 20, 0) rotated 90 about Z: X10 Y0 -> (0, 10) + (10, 20) = (10, 30).
  // G505 = (1, 2, 3): X0 Y0 Z0 -> (1, 2, 3). G500: no offset. G599 not in the profile: zero, warned.
  machine::MachineProfile p = test_profile();
  p.work_offset_rotations_deg["G54"] = Vector3d(0, 0, 90);
  p.work_offsets["G505"] = Vector3d(1, 2, 3);
  auto r = run_program("G54 G0 X10 Y0 Z0\nG505 X0 Y0 Z0\nG500 X5 Y5 Z5\nG599 X1 Y1 Z1\nM30\n", p);
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 0), Vector3d(10, 30, 0)));
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(1, 2, 3)));
  EXPECT_TRUE(near(end_of(*r, 2), Vector3d(5, 5, 5)));
  EXPECT_TRUE(near(end_of(*r, 3), Vector3d(1, 1, 1)));
  ASSERT_EQ(r->diagnostics.warning_count(), 1u);
  EXPECT_EQ(r->diagnostics.items()[0].number, 990002);
  EXPECT_NE(r->diagnostics.items()[0].text.find("G599"), std::string::npos);
}

TEST(Frames, G53G153AndSupaSuppressTheFramesForOneBlock) {
  // G54 = (10, 20, 0), TRANS X5: X0 Y0 -> (15, 20); G53/G153/SUPA X1 Y1 -> (1, 1); then back.
  auto r = run_program("G54 TRANS X5\nG0 X0 Y0\nG53 X1 Y1\nG153 X2 Y2\nSUPA X3 Y3\nX0 Y0\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 0), Vector3d(15, 20, 100)));
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(1, 1, 100)));
  EXPECT_TRUE(near(end_of(*r, 2), Vector3d(2, 2, 100)));
  EXPECT_TRUE(near(end_of(*r, 3), Vector3d(3, 3, 100)));
  EXPECT_TRUE(near(end_of(*r, 4), Vector3d(15, 20, 100)));
}

TEST(Frames, UnwrittenAxesKeepTheirWorkpieceCoordinate) {
  // At machine (10, 0, 0) = workpiece (10, 0, 0); ROT RPL=90: workpiece of (10, 0) is now
  // (0, -10). "Y5" keeps X = 0: workpiece (0, 5) -> machine (-5, 0). G91 X1: (1, 5) -> (-5, 1).
  auto r = run_program("G0 X10 Y0 Z0\nROT RPL=90\nG0 Y5\nG91 X1\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(-5, 0, 0)));
  EXPECT_TRUE(near(end_of(*r, 2), Vector3d(-5, 1, 0)));
}

TEST(Frames, ScaleFactorZeroIsRefused) {
  auto r = run_program("G0 X0 Y0 Z0\nSCALE X0 Y1\nG0 X1\nM30\n");
  ASSERT_TRUE(r->alarm);
  EXPECT_EQ(r->alarm->number, 990006);
  EXPECT_EQ(r->alarm->where.line, 2u);
}

TEST(Frames, CompensationWorksInThePlaneAFrameTilts) {
  // ROT X90 (3+2 machining): workpiece X stays machine X, workpiece Y becomes machine Z, so the
  // G17 plane of the program is the machine's X/Z plane, normal e_x x e_z = (0, -1, 0). G41 is
  // requested in that plane; the side is not swapped (no mirror). Without rotation: the machine's
  // own plane, nothing tilted.
  auto r = run_program("T1 M6 D1\nG0 X0 Y0 Z0\nROT X90\nG41 G1 X10 F100\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  const auto motions = r->sink.motions();  // a copy: the reference below must outlive the call
  const auto& c = motions.back().compensation;
  EXPECT_EQ(c.side, CompensationSide::Left);
  EXPECT_TRUE(c.tilted);
  EXPECT_TRUE(near(c.tilted_first, Vector3d(1, 0, 0)));
  EXPECT_TRUE(near(c.tilted_normal, Vector3d(0, -1, 0)));
  auto flat = run_program("T1 M6 D1\nG0 X0 Y0 Z0\nROT Z30\nG41 G1 X10 F100\nM30\n");
  ASSERT_FALSE(flat->alarm) << flat->alarm->format();
  EXPECT_FALSE(flat->sink.motions().back().compensation.tilted);
  // ROT Y180 turns the plane upside down: normal (0, 0, -1), so the side is swapped (as for a
  // mirror) and judged about +Z: G42 about +Z is G41 about the tilted normal.
  auto flipped = run_program("T1 M6 D1\nG0 X0 Y0 Z0\nROT Y180\nG41 G1 X10 F100\nM30\n");
  ASSERT_FALSE(flipped->alarm) << flipped->alarm->format();
  EXPECT_EQ(flipped->sink.motions().back().compensation.side, CompensationSide::Right);
}

TEST(Frames, SetSettableFrameTakesEffectOnTheNextSelection) {
  machine::MachineProfile p = test_profile();
  CollectingSink sink;
  Diagnostics diagnostics;
  Interpreter interp(p, sink, diagnostics);
  interp.set_settable_frame(2, Frame::translation({7, 0, 0}));  // $P_UIFR[2] = G55
  EXPECT_TRUE(near(interp.settable_frame(2).to_outer(Vector3d::Zero()), Vector3d(7, 0, 0)));
  interp.set_programmable_frame(Frame::translation({0, 1, 0}));
  EXPECT_TRUE(near(interp.frame().to_outer(Vector3d::Zero()), Vector3d(0, 1, 0)));
}

}  // namespace
}  // namespace drycut::interp::testing

namespace drycut::interp::testing {
namespace {

// Interpreter and tool radius compensation in a row (the tool centre path).
std::vector<PathElement> tool_centre_path(const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / ("drycut_frames_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "MAIN.MPF") << text;
  Diagnostics diagnostics;
  CollectingSink sink;
  const machine::MachineProfile profile = test_profile();
  CutterCompensation compensation(sink, profile, diagnostics);
  parser::ProgramLoader loader({}, diagnostics);
  loader.open_main(dir / "MAIN.MPF");
  Interpreter interp(profile, compensation, diagnostics);
  parser::Block block;
  while (loader.next(block) && !interp.ended()) interp.execute(block);
  interp.finish();
  std::filesystem::remove_all(dir);
  return sink.motions();
}

TEST(Frames, MirroredContourIsCompensatedOnTheMirroredSide) {
  // The square (0,0) (10,0) (10,10) (0,10) with G41 (inside, r = 2) under MIRROR X0 is the square
  // x in [-10, 0] on the machine; the tool centre runs inside it: x = -8 on the second side,
  // y = 8 on the third (the carrier of the 50 mm test tool at Z50).
  auto m = tool_centre_path("T1 M6 D1\nG0 X0 Y0 Z0\nMIRROR X0\nG41 G1 X10 Y0 F100\nY10\nX0\nG40 X0 Y20\nM30\n");
  ASSERT_GE(m.size(), 4u);
  EXPECT_TRUE(near(m[2].curve->start(), Vector3d(-8, 0, 50), 1e-6));  // NORM: the approach ends normal to the next side
  EXPECT_TRUE(near(m[2].curve->end(), Vector3d(-8, 8, 50), 1e-6));
  EXPECT_TRUE(near(m[3].curve->end(), Vector3d(0, 8, 50), 1e-6));
}

}  // namespace
}  // namespace drycut::interp::testing


namespace drycut::interp::testing {
namespace {

TEST(FrameFunctions, BuildTheSameComponentsAsTheInstructions) {
  FrameComponents c;
  // CTRANS(X, 10, Y, 5) : CROT(Z, 90): (10, 0) -> (0, 10) -> (10, 15), as TRANS X10 Y5 / AROT RPL=90.
  ASSERT_EQ(c.assign("CTRANS(X,10,Y,5):CROT(Z,90)", 1.0), "");
  EXPECT_TRUE(near(c.frame().to_outer({10, 0, 0}), Vector3d(10, 15, 0)));
  EXPECT_TRUE(c.set(0, "TR", 20));  // in the components' order: still writable by component
  EXPECT_TRUE(near(c.frame().to_outer({10, 0, 0}), Vector3d(20, 15, 0)));
  // CROT(Z, 90) : CTRANS(X, 10): the shift acts in the rotated system: (5, 0) -> (15, 0) -> (0, 15).
  ASSERT_EQ(c.assign("CROT(Z,90):CTRANS(X,10)", 1.0), "");
  EXPECT_TRUE(near(c.frame().to_outer({5, 0, 0}), Vector3d(0, 15, 0)));
  EXPECT_FALSE(c.set(0, "TR", 1));  // a product the components cannot hold
  // CSCALE(X, 2, Y, 3): (1, 1, 1) -> (2, 3, 1); CMIRROR(Y): (1, 1, 1) -> (1, -1, 1).
  ASSERT_EQ(c.assign("CSCALE(X,2,Y,3)", 1.0), "");
  EXPECT_TRUE(near(c.frame().to_outer({1, 1, 1}), Vector3d(2, 3, 1)));
  ASSERT_EQ(c.assign("CMIRROR(Y)", 1.0), "");
  EXPECT_TRUE(near(c.frame().to_outer({1, 1, 1}), Vector3d(1, -1, 1)));
  // Inch: CTRANS lengths are converted, angles are not.
  ASSERT_EQ(c.assign("CTRANS(X,1):CROT(Z,90)", 25.4), "");
  EXPECT_TRUE(near(c.frame().to_outer({0, 0, 0}), Vector3d(25.4, 0, 0)));
  EXPECT_NE(c.assign("CTRANS(X)", 1.0), "");
  EXPECT_NE(c.assign("CTRANS(5,1)", 1.0), "");
  EXPECT_NE(c.assign("CSCALE(X,0)", 1.0), "");
  EXPECT_NE(c.assign("ROT(Z,30)", 1.0), "");
}

}  // namespace
}  // namespace drycut::interp::testing

namespace drycut::interp::testing {
namespace {

TEST(Frames, RotationInTheG18PlaneKeepsTheCompensationSide) {
  // G18 ROT RPL=90 maps workpiece (x, y, z) to machine (z, y, -x). The side Z10 -> Z20 at X0
  // runs along machine +X from (10, 0, 0) to (20, 0, 0). G41 in G18 (normal +Y): left of +Z is
  // Y x Z = +X in the workpiece, i.e. machine z = -2; seen on the machine: left of +X is Y x X = -Z.
  auto m = tool_centre_path("T1 M6 D1\nG0 X0 Y0 Z0\nG18 ROT RPL=90\nG1 Z10 X0 F100\nG41 Z20\nZ30\nG40 Z40 X10\nM30\n");
  ASSERT_GE(m.size(), 4u);
  EXPECT_TRUE(near(m[3].curve->start(), Vector3d(20, 0, -2), 1e-6));
  EXPECT_TRUE(near(m[3].curve->end(), Vector3d(30, 0, -2), 1e-6));
}

TEST(Frames, ArcInATiltedPlaneFollowsTheFrame) {
  // ROT X90 maps workpiece (x, y, z) to machine (x, -z, y). The G17 circle G2 from (0, 0, 0) to
  // (10, 0, 0) about (5, 0, 0) runs through workpiece (5, 5, 0) -> machine (5, 0, 5).
  auto r = run_program("G0 X0 Y0 Z0\nROT X90\nG0 X0 Y0 Z0\nG2 X10 Y0 I5 F100\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_TRUE(near(m[2].curve->at(m[2].curve->length() / 2).position, Vector3d(5, 0, 5)));
  EXPECT_TRUE(near(m[2].curve->end(), Vector3d(10, 0, 0)));
}

TEST(Frames, FrameWordOfAnAxisBeyondXyzIsWarnedAndTheRestApplies) {
  // TRANS X10 C30: X is shifted by 10 (G54 X10 of the test profile: machine X = 10 + 10 + 5 for
  // the programmed X5); the C component is not modelled and must say so (990002 naming C).
  auto r = run_program("G54 G0 X0 Y0 Z0\nTRANS X10 C30\nG0 X5\nG58 A10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->end_position.x(), 25.0, 1e-9);
  int frame_warnings = 0;
  for (const auto& w : r->diagnostics.items())
    if (w.number == 990002 && w.text.find("frame component of axis") != std::string::npos) ++frame_warnings;
  EXPECT_EQ(frame_warnings, 2);  // C of TRANS, A of G58
}

TEST(Frames, OrientationWordsAreWarnedOnce) {
  // A3/B3/C3 (direction vector), A2 (angle): the block's X/Y/Z still move; the words are named once.
  auto r = run_program("G0 X0 Y0 Z0\nG1 X10 A3=1 B3=0 C3=1 F1000\nG1 X20 A2=5\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->end_position.x(), 20.0, 1e-9);  // G500 at reset: no offset
  int orientation_warnings = 0;
  for (const auto& w : r->diagnostics.items())
    if (w.number == 990002 && w.text.find("tool orientation") != std::string::npos) ++orientation_warnings;
  EXPECT_EQ(orientation_warnings, 1);
}

}  // namespace
}  // namespace drycut::interp::testing
