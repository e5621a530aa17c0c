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

#include "assets/asset.h"
#include "layout/layout.h"
#include "solver/box.h"

namespace villa::solver {

// Angle (degrees, [0, 180]) between two directions.
double AngleDegrees(Point a, Point b);

// The thresholds (issue 27's "done when").
inline constexpr double kSeatToTable = 0.35;      // m
inline constexpr double kSeatFacing = 30.0;       // degrees off the side's inward normal
inline constexpr double kSeatBehind = 0.75;       // m free behind a dining or meeting chair
inline constexpr double kSeatLost = 1.5;          // m: a dining chair this far from every table is lost
inline constexpr double kTvAngle = 25.0;          // degrees
inline constexpr double kScreenFacing = 45.0;     // degrees: the screen turned from the sofa (seen edge-on past it)
inline constexpr double kTvMin = 1.4, kTvMax = 4.0;            // m centre to centre
inline constexpr double kCoffeeMin = 0.25, kCoffeeMax = 0.9;   // m gap
inline constexpr double kDeskSeatGap = 0.5;       // m
inline constexpr double kDeskSeatFacing = 45.0;   // degrees
inline constexpr double kBedsideGap = 0.3;        // m beside the bed
inline constexpr double kBedsideHead = 0.75;      // m from the head's line to its centre
inline constexpr double kPillowHead = 0.3;        // share of the bed's length from the head
inline constexpr double kArmchairFacing = 45.0;   // degrees
inline constexpr double kSideTableGap = 0.3;      // m
inline constexpr double kArmchairReach = 3.0;     // m from the group's focus
inline constexpr double kArmchairNear = 1.5;      // m: without edges, an armchair this near the group is in it
inline constexpr double kRunGap = 0.1;            // m: a cooker or fridge this near a counter is in its run
inline constexpr double kTriangleMin = 4.0, kTriangleMax = 8.0;  // m: the kitchen's work triangle (perimeter)
inline constexpr double kMirrorOffset = 0.2;      // m: a mirror's centre off the basin's axis

// A chair at a table: its centre beyond one side, within that side's length, at most 0.35 m from the table,
// its front within 30 degrees of facing that side. (The 0.75 m behind it needs the room: checked apart.)
std::string TableSeatProblem(const OrientedBox& chair, const OrientedBox& table);
// A desk's chair: in the desk's front half-plane, its centre within the desk's width (+0.1 m), at most 0.5 m
// from it, facing the desk within 45 degrees.
std::string DeskSeatProblem(const OrientedBox& chair, const OrientedBox& desk);
// A nightstand: beside its bed (outside the bed's width, at most 0.3 m off its side), its centre within
// 0.75 m of the head's line (the bed's back).
std::string BedsideProblem(const OrientedBox& nightstand, const OrientedBox& bed);
// A pillow on a bed: its centre in the head 30 % of the bed's length (of its mattress: MattressBox).
std::string PillowProblem(Point pillow, const OrientedBox& bed);
// What a bed's pillows lie on: the bed's box cut to the depth of its asset's highest support surface (an
// imported bed's mattress may start well below its box's head, past a thick headboard); the bed's box when
// `asset` is null or has no surface. `scale`: the bed's scale.
OrientedBox MattressBox(const OrientedBox& bed, const AssetRecord* asset, double scale);
// The sofa faces the TV (or its stand) within 25 degrees, 1.4-4.0 m centre to centre, and the screen faces
// the sofa within 45 degrees (a stand on a side wall ahead shows the sofa its end).
std::string TvProblem(const OrientedBox& sofa, const OrientedBox& tv);
// The coffee table's centre in the sofa's front half-plane, within its width, at a 0.25-0.9 m gap.
std::string CoffeeTableProblem(const OrientedBox& table, const OrientedBox& sofa);
// A side table at an end of the sofa (outside its width, at most 0.3 m from it).
std::string SideTableProblem(const OrientedBox& side_table, const OrientedBox& sofa);
// An armchair faces the group's focus (the coffee table) within 45 degrees, at most 3 m from it.
std::string ArmchairProblem(const OrientedBox& armchair, Point focus);

}  // namespace villa::solver
