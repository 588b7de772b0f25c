// Extra axes: the travel of a programmed value (extra_axes.hpp rules), hand-computed.
#include <gtest/gtest.h>

#include "interp/extra_axes.hpp"

namespace drycut::interp {
namespace {

using parser::ValueMode;

machine::MachineProfile profile_with(bool modulo, bool rotary = true, int mask = 0) {
  machine::MachineProfile p;
  machine::AxisData c;
  c.name = "C";
  c.rotary = rotary;
  c.modulo = modulo;
  c.misc_function_mask = mask;
  c.max_velocity_mm_s = 100;
  c.max_accel_mm_s2 = 100;
  c.max_jerk_mm_s3 = 100;
  p.extra_axes.push_back(c);
  return p;
}

double travel(ExtraAxes& axes, double value, ValueMode mode, bool absolute = true) {
  const auto t = axes.travel_to(0, value, mode, absolute, 25.4);
  EXPECT_EQ(t.alarm, 0) << t.detail;
  axes.move(0, t.travel);
  return t.travel;
}

TEST(ExtraAxes, ModuloWaysFromTheManualsTable) {
  ExtraAxes axes(profile_with(true));
  EXPECT_DOUBLE_EQ(travel(axes, 350, ValueMode::Direct), -10);           // DC: shortest
  EXPECT_DOUBLE_EQ(axes.position(0), 350);
  EXPECT_DOUBLE_EQ(travel(axes, 10, ValueMode::AbsolutePositive), 20);   // ACP: through 360
  EXPECT_DOUBLE_EQ(travel(axes, 0, ValueMode::AbsoluteNegative), -10);   // ACN
  EXPECT_DOUBLE_EQ(travel(axes, 350, ValueMode::Default), 350);          // G90: like a linear axis in 0..360
  EXPECT_DOUBLE_EQ(travel(axes, 10, ValueMode::Absolute), -340);
  EXPECT_DOUBLE_EQ(travel(axes, 400, ValueMode::Default, false), 400);   // G91: more than a turn
  EXPECT_DOUBLE_EQ(axes.position(0), 50);
  EXPECT_DOUBLE_EQ(travel(axes, -90, ValueMode::Absolute), 220);         // -90 is 270 in the range
  EXPECT_DOUBLE_EQ(travel(axes, 90, ValueMode::Direct), 180);            // exactly half a turn: positive
}

TEST(ExtraAxes, Md30455Bit2MakesG90TheShortestWay) {
  ExtraAxes axes(profile_with(true, true, 4));
  travel(axes, 350, ValueMode::Direct);
  EXPECT_DOUBLE_EQ(travel(axes, 10, ValueMode::Default), 20);
}

TEST(ExtraAxes, DirectionModesAreRefusedWhereTheControlRefusesThem) {
  ExtraAxes modulo(profile_with(true));
  EXPECT_EQ(modulo.travel_to(0, 360, ValueMode::Direct, true, 1).alarm, 16830);
  EXPECT_EQ(modulo.travel_to(0, -1, ValueMode::AbsolutePositive, true, 1).alarm, 16830);
  ExtraAxes linear(profile_with(false, false));
  EXPECT_EQ(linear.travel_to(0, 10, ValueMode::Direct, true, 1).alarm, 16800);
  EXPECT_EQ(linear.travel_to(0, 10, ValueMode::AbsolutePositive, true, 1).alarm, 16810);
  EXPECT_EQ(linear.travel_to(0, 10, ValueMode::AbsoluteNegative, true, 1).alarm, 16820);
}

TEST(ExtraAxes, LinearAxisTakesTheGeometryUnitRotaryDoesNot) {
  ExtraAxes linear(profile_with(false, false));
  EXPECT_DOUBLE_EQ(travel(linear, 2, ValueMode::Default), 50.8);  // G70: 2 inch
  ExtraAxes rotary(profile_with(false));
  EXPECT_DOUBLE_EQ(travel(rotary, 2, ValueMode::Default), 2.0);
  EXPECT_DOUBLE_EQ(travel(rotary, 370, ValueMode::Default), 368.0);  // no modulo: beyond a turn
}

TEST(ExtraAxes, FeedGroup) {
  ExtraAxes axes(profile_with(true));
  EXPECT_EQ(axes.geometry_feed_axes(), 7);
  EXPECT_EQ(axes.set_feed_group({"X", "Y", "C"}), "");
  EXPECT_EQ(axes.geometry_feed_axes(), 0b011);  // X and Y: Z follows
  EXPECT_TRUE(axes.in_feed_group(0));
  EXPECT_EQ(axes.set_feed_group({"Z"}), "");
  EXPECT_EQ(axes.geometry_feed_axes(), 0b100);
  EXPECT_FALSE(axes.in_feed_group(0));
  EXPECT_EQ(axes.set_feed_group({"C"}), "");
  EXPECT_EQ(axes.geometry_feed_axes(), 0);
  EXPECT_EQ(axes.set_feed_group({}), "");
  EXPECT_EQ(axes.geometry_feed_axes(), 7);
  EXPECT_FALSE(axes.in_feed_group(0));
  EXPECT_EQ(axes.set_feed_group({"Q1"}), "Q1");
}

}  // namespace
}  // namespace drycut::interp
