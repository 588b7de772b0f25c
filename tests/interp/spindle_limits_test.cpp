// G25 S / G26 S spindle speed limits and G4 S<n>= (dwell in revolutions of spindle n). Every
// expected value is worked out in the comment beside it (docs/controller-state.md).
#include <numbers>
#include <string>

#include "interp_test_support.hpp"

namespace drycut::interp::testing {
namespace {

size_t warnings_with(const RunResult& r, int number, const std::string& part) {
  size_t n = 0;
  for (const auto& a : r.diagnostics.items())
    n += a.severity == Severity::Warning && a.number == number && a.text.find(part) != std::string::npos;
  return n;
}

std::vector<double> dwells(const RunResult& r) {
  std::vector<double> out;
  for (const auto& e : r.sink.elements)
    if (e.kind == ElementKind::Dwell) out.push_back(e.dwell_s);
  return out;
}

TEST(SpindleLimits, G26ClampsLaterSpeedsAndG25RaisesThem) {
  // G26 S2000: S3000 runs at 2000 -> G95 F0.1 = 200 mm/min = 10/3 mm/s. G25 S1500: S1000 runs
  // at 1500 -> 150 mm/min = 2.5 mm/s. S1800 lies between: 180 mm/min = 3 mm/s.
  auto r = run_program("G26 S2000\nS3000 M3\nG95 G1 X10 F0.1\nG25 S1500\nS1000\nX20\nS1800\nX30\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_NEAR(m[0].feed_mm_s, 10.0 / 3.0, 1e-12);
  EXPECT_NEAR(m[1].feed_mm_s, 2.5, 1e-12);
  EXPECT_NEAR(m[2].feed_mm_s, 3.0, 1e-12);
  EXPECT_EQ(warnings_with(*r, 990013, "above the G26 limit"), 1u);
  EXPECT_EQ(warnings_with(*r, 990013, "below the G25 limit"), 1u);
}

TEST(SpindleLimits, TheSOfTheLimitBlockIsNoSpeed) {
  // S1200 M3, then G26 S5000: the spindle keeps 1200 -> F0.1 = 120 mm/min = 2 mm/s.
  auto r = run_program("S1200 M3\nG26 S5000\nG95 G1 X10 F0.1\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->sink.motions()[0].feed_mm_s, 2.0, 1e-12);
}

TEST(SpindleLimits, G26LimitsTheConstantCuttingSpeed) {
  // G96 S200 from X10 (diameter 20: 200000/(pi*20) = 3183 rev/min) to X20, limited by G26
  // S2000 up to r_c = 200000/(2pi*2000) = 15.9 mm: ∫ dr/n = (r_c - 10)/2000 + pi(20² - r_c²)/200000
  // min per mm of radius; the block's pieces (each at its feed at F0.1) take that time together,
  // the first at the G26 speed.
  auto r = run_program("G0 X10\nG26 S2000\nS500 M3\nG96 S200\nG1 X20 F0.1\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  const auto m = with_cutting_speed_pieces(r->sink.motions());
  const double r_c = 200000 / (2 * std::numbers::pi * 2000);
  const double per_rev = (r_c - 10) / 2000 + std::numbers::pi * (20.0 * 20 - r_c * r_c) / 200000;
  double seconds = 0;
  for (size_t k = 1; k < m.size(); ++k) {
    seconds += m[k].curve->length() / m[k].feed_mm_s;
    if (!m[k].continues_block) break;
  }
  EXPECT_NEAR(seconds, per_rev / 0.1 * 60, 1e-9);
  EXPECT_NEAR(m[1].feed_mm_s, 0.1 * 2000 / 60, 1e-12);
  EXPECT_EQ(warnings_with(*r, 990013, "G96 spindle speed above the G26 limit"), 1u);
}

TEST(SpindleLimits, WorkingAreaLimitationDoesNotMove) {
  // G25 X.. Z.. / G26 X.. Z..: the working area (not modelled, one warning per word), no motion.
  auto r = run_program("G25 X-100 Z-100\nG26 X100 Z100\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(r->sink.motions().empty());
  EXPECT_EQ(warnings_with(*r, 990002, "working area limitation"), 4u);
}

TEST(DwellRevolutions, G4OfAnotherSpindleUsesItsSpeed) {
  // S2=600 M2=3: G4 S2=30 is 30 revolutions at 600 rev/min = 3 s. The master (S1000 M3) is not
  // the one counted: G4 S30 is 30/1000 min = 1.8 s.
  auto r = run_program("S1000 M3\nS2=600 M2=3\nG4 S2=30\nG4 S30\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  const auto d = dwells(*r);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_NEAR(d[0], 3.0, 1e-12);
  EXPECT_NEAR(d[1], 1.8, 1e-12);
}

TEST(DwellRevolutions, UnknownSpeedOfAnotherSpindleWarns) {
  // No S2= in the program (or spindle 2 stopped by M2=5): drycut cannot time it; 0 s and a warning.
  auto r = run_program("G4 S2=30\nS2=600 M2=5\nG4 S2=10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  const auto d = dwells(*r);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0], 0.0);
  EXPECT_EQ(d[1], 0.0);
  EXPECT_GE(warnings_with(*r, 990002, "speed of spindle 2 is not known"), 1u);
}


TEST(SpindleLimits, G97SelectingFeedPerRevolutionIsWarnedOnlyWhenNotWrittenBeside) {
  // G94 ... G97 S800 M3 makes a later F mm/rev (warning 990019); G95 G97 S800 M3 says so in
  // its own block: no warning. Either way F0.1 at 800 rev/min is 80 mm/min = 4/3 mm/s.
  auto hidden = run_program("G94\nG97 S800 M3\nG1 X10 F0.1\nM30\n");
  auto written = run_program("G94\nG95 G97 S800 M3\nG1 X10 F0.1\nM30\n");
  ASSERT_FALSE(hidden->alarm) << hidden->alarm->format();
  ASSERT_FALSE(written->alarm) << written->alarm->format();
  EXPECT_EQ(warnings_with(*hidden, 990019, "G97 selects feed per revolution"), 1u);
  EXPECT_EQ(warnings_with(*written, 990019, ""), 0u);
  EXPECT_NEAR(hidden->sink.motions()[0].feed_mm_s, 80.0 / 60.0, 1e-12);
  EXPECT_NEAR(written->sink.motions()[0].feed_mm_s, 80.0 / 60.0, 1e-12);
}

TEST(SpindleLimits, G973SelectingFeedPerRevolutionIsWarnedByItsOwnName) {
  // The warning names the code written (until 2026-11-30 G973 was warned as "G97").
  auto r = run_program("G94\nG973 S800 M3\nG1 X10 F0.1\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_EQ(warnings_with(*r, 990019, "G973 selects feed per revolution"), 1u);
}

}  // namespace
}  // namespace drycut::interp::testing
