#include "solver/group_rules.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "mesh/geometry2d.h"

namespace villa::solver {
namespace {

std::string Fixed(double v, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

// Half the extent of box b along the unit direction k.
double HalfAlong(const PlanBox& b, Point k) { return b.hx * std::abs(geo::Dot(b.U(), k)) + b.hy * std::abs(geo::Dot(b.V(), k)); }

}  // namespace

Point PlanBox::U() const { return {std::cos(yaw), std::sin(yaw)}; }
Point PlanBox::V() const { return {-std::sin(yaw), std::cos(yaw)}; }
Point PlanBox::Front() const { return {std::sin(yaw), -std::cos(yaw)}; }
Point PlanBox::Local(Point p) const {
  const Point d = geo::Sub(p, c);
  return {geo::Dot(d, U()), geo::Dot(d, V())};
}

double PlanGap(const PlanBox& a, const PlanBox& b) {
  double gap = -1e300;
  for (Point k : {a.U(), a.V(), b.U(), b.V()})
    gap = std::max(gap, std::abs(geo::Dot(geo::Sub(b.c, a.c), k)) - HalfAlong(a, k) - HalfAlong(b, k));
  return gap;
}

double AngleDegrees(Point a, Point b) {
  const double la = geo::Len(a), lb = geo::Len(b);
  if (la <= 0.0 || lb <= 0.0) return 180.0;
  return std::acos(std::clamp(geo::Dot(a, b) / (la * lb), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

std::string TableSeatProblem(const PlanBox& chair, const PlanBox& table) {
  const Point l = table.Local(chair.c);
  Point inward;
  if (std::abs(l.x) <= table.hx && std::abs(l.y) > table.hy) inward = l.y > 0 ? geo::Scale(table.V(), -1.0) : table.V();
  else if (std::abs(l.y) <= table.hy && std::abs(l.x) > table.hx) inward = l.x > 0 ? geo::Scale(table.U(), -1.0) : table.U();
  else return "not beside a side of the table (at a corner or beyond its ends)";
  const double gap = PlanGap(chair, table);
  if (gap > kSeatToTable) return Fixed(gap, 2) + " m from the table (<= " + Fixed(kSeatToTable, 2) + ")";
  if (const double a = AngleDegrees(chair.Front(), inward); a > kSeatFacing)
    return "turned " + Fixed(a, 0) + " degrees from the table (<= " + Fixed(kSeatFacing, 0) + ")";
  return "";
}

std::string DeskSeatProblem(const PlanBox& chair, const PlanBox& desk) {
  const Point l = desk.Local(chair.c);
  if (l.y >= -desk.hy || std::abs(l.x) > desk.hx + 0.1) return "not before the desk";
  if (const double gap = PlanGap(chair, desk); gap > kDeskSeatGap)
    return Fixed(gap, 2) + " m from the desk (<= " + Fixed(kDeskSeatGap, 2) + ")";
  if (const double a = AngleDegrees(chair.Front(), desk.V()); a > kDeskSeatFacing)
    return "turned " + Fixed(a, 0) + " degrees from the desk (<= " + Fixed(kDeskSeatFacing, 0) + ")";
  return "";
}

std::string BedsideProblem(const PlanBox& nightstand, const PlanBox& bed) {
  const Point l = bed.Local(nightstand.c);
  if (std::abs(l.x) <= bed.hx) return "at the bed's " + std::string(l.y > 0 ? "head" : "foot") + " end, not beside it";
  if (const double gap = PlanGap(nightstand, bed); gap > kBedsideGap)
    return Fixed(gap, 2) + " m off the bed's side (<= " + Fixed(kBedsideGap, 2) + ")";
  if (const double from_head = bed.hy - l.y; from_head > kBedsideHead)
    return Fixed(from_head, 2) + " m from the head's line (<= " + Fixed(kBedsideHead, 2) + "): not at the head";
  return "";
}

std::string PillowProblem(Point pillow, const PlanBox& bed) {
  const double from_head = bed.hy - bed.Local(pillow).y;
  if (from_head > kPillowHead * 2.0 * bed.hy) return Fixed(from_head, 2) + " m from the head (mid-bed)";
  return "";
}

std::string TvProblem(const PlanBox& sofa, Point tv) {
  const double angle = AngleDegrees(sofa.Front(), geo::Sub(tv, sofa.c));
  if (angle > kTvAngle) return "the sofa is turned " + Fixed(angle, 0) + " degrees from the TV (<= " + Fixed(kTvAngle, 0) + ")";
  const double dist = geo::Dist(tv, sofa.c);
  if (dist < kTvMin || dist > kTvMax)
    return "the TV is " + Fixed(dist, 2) + " m from the sofa (" + Fixed(kTvMin, 1) + "-" + Fixed(kTvMax, 1) + ")";
  return "";
}

std::string CoffeeTableProblem(const PlanBox& table, const PlanBox& sofa) {
  const Point l = sofa.Local(table.c);
  if (l.y > -sofa.hy || std::abs(l.x) > sofa.hx) return "the coffee table is not in front of the sofa";
  const double gap = PlanGap(sofa, table);
  if (gap < kCoffeeMin || gap > kCoffeeMax)
    return "the coffee table is " + Fixed(gap, 2) + " m from the sofa (" + Fixed(kCoffeeMin, 2) + "-" + Fixed(kCoffeeMax, 1) + ")";
  return "";
}

std::string SideTableProblem(const PlanBox& side_table, const PlanBox& sofa) {
  const Point l = sofa.Local(side_table.c);
  if (std::abs(l.x) <= sofa.hx) return "not at an end of the sofa";
  if (const double gap = PlanGap(side_table, sofa); gap > kSideTableGap)
    return Fixed(gap, 2) + " m from the sofa's end (<= " + Fixed(kSideTableGap, 2) + ")";
  return "";
}

std::string ArmchairProblem(const PlanBox& armchair, Point focus) {
  if (const double d = geo::Dist(armchair.c, focus); d > 3.0) return Fixed(d, 2) + " m from the group (<= 3)";
  if (const double a = AngleDegrees(armchair.Front(), geo::Sub(focus, armchair.c)); a > kArmchairFacing)
    return "turned " + Fixed(a, 0) + " degrees from the group (<= " + Fixed(kArmchairFacing, 0) + ")";
  return "";
}

}  // namespace villa::solver
