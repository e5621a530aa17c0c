#pragma once
// The rules a functional group's members keep with their hub (issue 27), as plain plan geometry, in one
// place: the functional checks of a furnished room (solver/functional.h) measure them, and the pose solver
// refuses a move that would carry a member out of them (solver/solve.cpp), so a member carried away from its
// group is never counted as a fix.
//
// Frames: plan metres; a box's yaw turns its +x axis to (cos yaw, sin yaw); its front is -y of its own
// frame, facing (sin yaw, -cos yaw) in the plan (SCENE.md). Each rule returns "" when it holds, else what is
// wrong in words, with the measured value and the bound ("0.42 m from the table (<= 0.35)").
#include <string>

#include "layout/layout.h"

namespace villa::solver {

// A footprint in the plan: centre, yaw (rad), half width (along its +x) and half depth (along its +y).
struct PlanBox {
  Point c;
  double yaw = 0.0;
  double hx = 0.0;
  double hy = 0.0;
  Point U() const;               // +x
  Point V() const;               // +y: its back
  Point Front() const;           // -y
  Point Local(Point p) const;    // p in the box's frame (x along U, y along V)
};

// The gap between two footprints (m, > 0 apart, < 0 overlapping): the widest separation along a face normal.
double PlanGap(const PlanBox& a, const PlanBox& b);
// Angle (degrees, [0, 180]) between two directions.
double AngleDegrees(Point a, Point b);

// The thresholds (issue 27's "done when").
inline constexpr double kSeatToTable = 0.35;      // m
inline constexpr double kSeatFacing = 30.0;       // degrees off the side's inward normal
inline constexpr double kSeatBehind = 0.75;       // m free behind a dining or meeting chair
inline constexpr double kSeatLost = 1.5;          // m: a dining chair this far from every table is lost
inline constexpr double kTvAngle = 25.0;          // degrees
inline constexpr double kTvMin = 1.4, kTvMax = 4.0;            // m centre to centre
inline constexpr double kCoffeeMin = 0.25, kCoffeeMax = 0.9;   // m gap
inline constexpr double kDeskSeatGap = 0.5;       // m
inline constexpr double kDeskSeatFacing = 45.0;   // degrees
inline constexpr double kBedsideGap = 0.3;        // m beside the bed
inline constexpr double kBedsideHead = 0.75;      // m from the head's line to its centre
inline constexpr double kPillowHead = 0.3;        // share of the bed's length from the head
inline constexpr double kArmchairFacing = 45.0;   // degrees
inline constexpr double kSideTableGap = 0.3;      // m

// A chair at a table: its centre beyond one side, within that side's length, at most 0.35 m from the table,
// its front within 30 degrees of facing that side. (The 0.75 m behind it needs the room: checked apart.)
std::string TableSeatProblem(const PlanBox& chair, const PlanBox& table);
// A desk's chair: in the desk's front half-plane, its centre within the desk's width (+0.1 m), at most 0.5 m
// from it, facing the desk within 45 degrees.
std::string DeskSeatProblem(const PlanBox& chair, const PlanBox& desk);
// A nightstand: beside its bed (outside the bed's width, at most 0.3 m off its side), its centre within
// 0.75 m of the head's line (the bed's back).
std::string BedsideProblem(const PlanBox& nightstand, const PlanBox& bed);
// A pillow on a bed: its centre in the head 30 % of the bed's length.
std::string PillowProblem(Point pillow, const PlanBox& bed);
// The sofa faces the TV (or its stand) within 25 degrees, 1.4-4.0 m centre to centre.
std::string TvProblem(const PlanBox& sofa, Point tv);
// The coffee table's centre in the sofa's front half-plane, within its width, at a 0.25-0.9 m gap.
std::string CoffeeTableProblem(const PlanBox& table, const PlanBox& sofa);
// A side table at an end of the sofa (outside its width, at most 0.3 m from it).
std::string SideTableProblem(const PlanBox& side_table, const PlanBox& sofa);
// An armchair faces the group's focus (the coffee table) within 45 degrees, at most 3 m from it.
std::string ArmchairProblem(const PlanBox& armchair, Point focus);

}  // namespace villa::solver
